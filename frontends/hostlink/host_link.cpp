#include "frontends/hostlink/host_link.hpp"

#include <cctype>

#include "devicemodel/hex.hpp"
#include "frontends/hostlink/command_table.hpp"

namespace slmp::hostlink {

namespace {

bool same_hex(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

constexpr std::size_t kFraming = 9;   // `@`, station (2), command (2), FCS (2), `*`, CR

}  // namespace

HostLink::HostLink(devicemodel::Cpu& cpu, Options options)
    : cpu_(cpu), options_(std::move(options)), environment_(options_.environment_bytes, 0),
      object_(options_.object_bytes, 0) {}

HostLink::Result HostLink::handle(std::span<const std::uint8_t> stream, LinkState& link, const frontends::Gate& gate) {
    auto cut = cut_record(stream);
    Result result{cut.kind, cut.consumed, {}, {}, {}};
    if (cut.kind != Cut::Kind::Record) return result;
    result.response = answer(cut.record, link, &result, gate);
    if (cut.wrapped && !result.response.empty()) result.response = kStx + result.response + kEtx;
    return result;
}

std::string HostLink::answer(std::string_view record, LinkState& link, Result* result, const frontends::Gate& gate) {
    // Without `*` CR or room for station, command and FCS there is no record to answer (§8: discard).
    if (record.size() < kFraming || record[record.size() - 2] != '*') return {};
    if (record.substr(1, 2) != "00") return {};   // another station: silence, as an OMRON PLC
    auto code = record.substr(3, 2);
    if (result) result->command = std::string(code);
    auto answered = [&](std::string_view response_code) {
        if (result) result->code = std::string(response_code);
    };
    auto body = record.substr(0, record.size() - 4);
    // QQ answers under its subcommand too: "QQMR" + code, "QQIR" + code + data (§6.9, §6.10).
    auto answered_as = code == "QQ" && body.size() >= 7 ? body.substr(3, 4) : code;
    auto with_code = [&](std::string_view response_code, std::string_view data = {}) {
        answered(response_code);
        std::string reply = "@00";
        reply += answered_as;
        reply += response_code;
        reply += data;
        return close_record(reply);
    };
    // A record over 132 bytes is not split by Ladder Motion (§3.3): 01 (inferred).
    if (record.size() > kMaxRecordBytes) return with_code("01");
    if (!same_hex(record.substr(record.size() - 4, 2), fcs(body))) return with_code(options_.fcs_error_code);
    const auto* row = find_command(code);
    if (!row) {
        answered("IC");
        return close_record("@00IC");   // §6.13: no response code, no data
    }
    if (gate) {   // a scenario fault: answer a chosen code, or nothing, and execute nothing
        auto intercept = gate(code);
        if (intercept.kind == frontends::Intercept::Kind::Silent) return {};
        if (intercept.kind == frontends::Intercept::Kind::Answer) {
            return with_code(devicemodel::hex2(intercept.code));
        }
    }
    Context context{*this, link, AreaAccess(cpu_.memory(), options_.map), code, body.substr(5)};
    auto reply = row->handler(*row, context);
    switch (reply.kind) {
        case Answer::Kind::Silent: return {};
        case Answer::Kind::Echo: answered("00"); return close_record(body);
        case Answer::Kind::Unknown: answered("IC"); return close_record("@00IC");
        case Answer::Kind::Normal: break;
    }
    return with_code(reply.code, reply.code == "00" ? std::string_view(reply.data) : std::string_view());
}

}  // namespace slmp::hostlink
