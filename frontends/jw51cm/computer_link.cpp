#include "frontends/jw51cm/computer_link.hpp"

#include <algorithm>

#include "devicemodel/hex.hpp"
#include "frontends/jw51cm/command_table.hpp"

namespace slmp::jw51cm {

namespace {

constexpr std::size_t kCom = kHeaderBytes + 2;   // offset of COM
constexpr std::size_t kMinRequest = kHeaderBytes + 3;

bool zero_header(std::span<const std::uint8_t> request) {
    return std::all_of(request.begin(), request.begin() + kHeaderBytes, [](std::uint8_t b) { return b == 0; });
}

}  // namespace

std::vector<std::uint8_t> response_frame(std::span<const std::uint8_t> request, Rslt rslt,
                                         std::span<const std::uint8_t> text) {
    // The header is echoed (inferred: "presumably an echo of the command header").
    std::vector<std::uint8_t> frame(request.begin(), request.begin() + kHeaderBytes);
    frame.push_back(kResponseId);
    frame.push_back(0x00);
    frame.push_back(request[kCom]);
    frame.push_back(static_cast<std::uint8_t>(rslt));
    if (rslt == Rslt::Ok) frame.insert(frame.end(), text.begin(), text.end());
    return frame;
}

ComputerLink::ComputerLink(devicemodel::Cpu& cpu, Options options, Clock clock)
    : system_memory(options.system_bytes, 0),
      program(2 * 2 * static_cast<std::size_t>(options.program_steps), 0),
      cpu_(cpu),
      options_(std::move(options)),
      map_(options_.file_bytes, options_.timers),
      clock_(clock ? std::move(clock) : Clock([] { return std::chrono::system_clock::now(); })) {}

ComputerLink::Result ComputerLink::handle_stream(std::span<const std::uint8_t> stream, const frontends::Gate& gate,
                                                 const Caller& caller) {
    auto result = cut_stream(stream, gate);
    record_completion(stream, result, caller);
    return result;
}

ComputerLink::Result ComputerLink::cut_stream(std::span<const std::uint8_t> stream, const frontends::Gate& gate) {
    Result result;
    if (stream.size() < kMinRequest) return result;
    result.command = stream[kCom];
    const auto* row = find_command(stream[kCom]);
    // A wrong ID or ATTR or an unknown COM leaves no way to find the request's end:
    // answer 01 and drop what is buffered (inferred; §4.1 leaves it undocumented).
    auto refuse_all = [&] {
        result.kind = Result::Kind::Respond;
        result.consumed = stream.size();
        result.response = response_frame(stream, Rslt::Format);
        return result;
    };
    if (stream[kHeaderBytes] != kCommandId || stream[kHeaderBytes + 1] != 0x00 || !row) return refuse_all();
    auto length = request_length(*row, stream);
    if (!length) return result;
    if (*length > kMinRequest + 5 + 2 * kMaxData) return refuse_all();   // an L no real request carries
    // E8: the format table shows a MODE byte, the example sends none: one more byte
    // is taken only when it arrived with the command (§7.2, inferred).
    if (row->com == 0xE8 && stream.size() == *length + 1) ++*length;
    if (stream.size() < *length) return result;
    return answer(stream, *length, gate);
}

ComputerLink::Result ComputerLink::handle_datagram(std::span<const std::uint8_t> datagram, const frontends::Gate& gate,
                                                   const Caller& caller) {
    auto result = cut_datagram(datagram, gate);
    record_completion(datagram, result, caller);
    return result;
}

ComputerLink::Result ComputerLink::cut_datagram(std::span<const std::uint8_t> datagram, const frontends::Gate& gate) {
    Result result;
    result.kind = Result::Kind::Drop;
    result.consumed = datagram.size();
    if (datagram.size() < kMinRequest) return result;   // not even a header and COM: nothing to answer
    result.command = datagram[kCom];
    const auto* row = find_command(datagram[kCom]);
    auto refuse = [&] {
        result.kind = Result::Kind::Respond;
        result.response = response_frame(datagram, Rslt::Format);
        return result;
    };
    if (datagram[kHeaderBytes] != kCommandId || datagram[kHeaderBytes + 1] != 0x00 || !row) return refuse();
    auto length = request_length(*row, datagram);
    bool e8_with_mode = row->com == 0xE8 && datagram.size() == kMinRequest + 1;
    // §4.1: a UDP command is at most 1024 bytes, and one datagram holds one command.
    if (!length || datagram.size() > kMaxData || (datagram.size() != *length && !e8_with_mode)) return refuse();
    return answer(datagram, datagram.size(), gate);
}

ComputerLink::Result ComputerLink::answer(std::span<const std::uint8_t> request, std::size_t length,
                                          const frontends::Gate& gate) {
    Result result;
    result.kind = Result::Kind::Respond;
    result.consumed = length;
    result.command = request[kCom];
    const auto& row = *find_command(request[kCom]);
    auto frame = request.first(length);
    // A non-zero header is 2-tier relaying to Satellite Net, not simulated: 01 (inferred, §4.3).
    if (!zero_header(frame)) {
        result.response = response_frame(frame, Rslt::Format);
        return result;
    }
    if (gate) {   // a scenario fault: answer a chosen RSLT, or nothing, and execute nothing
        auto intercept = gate(devicemodel::hex2(row.com));
        if (intercept.kind == frontends::Intercept::Kind::Silent) {
            result.kind = Result::Kind::Drop;
            return result;
        }
        if (intercept.kind == frontends::Intercept::Kind::Answer) {
            result.response = response_frame(frame, static_cast<Rslt>(intercept.code));
            return result;
        }
    }
    Rslt rslt = Rslt::Ok;
    std::vector<std::uint8_t> text;
    if (row.min_mode > write_mode_) rslt = Rslt::WriteMode;
    else if (row.needs == Needs::Stopped && cpu_.runtime().state() == devicemodel::RunState::Run) rslt = Rslt::NotStopped;
    else {
        Context context{*this, frame.subspan(kMinRequest), text};
        rslt = row.handler(context);
    }
    result.response = response_frame(frame, rslt, text);
    return result;
}

void ComputerLink::record_completion(std::span<const std::uint8_t> request, const Result& result, const Caller& caller) {
    if (result.kind != Result::Kind::Respond || result.response.size() <= kCom + 1) return;
    auto area = completion_area(options_.parameters);
    if (!area.on) return;   // checked at start: inside its file, 16-64 bytes
    auto command = request.first(result.consumed).subspan(kHeaderBytes);
    write_area(area.place, completion_record(caller, result.response[kCom + 1], command, area.bytes));
}

void ComputerLink::assign_connections(bool udp_port, std::uint8_t udp, std::uint8_t reserved) {
    udp_port_ = udp_port;
    connections_.assign(static_cast<std::uint8_t>(udp | (udp_port ? 1u << kUdpConnection : 0u)), reserved);
}

std::uint8_t ComputerLink::udp_connection() const { return udp_port_ ? kUdpConnection : kNoConnection; }

void ComputerLink::set_connection(std::uint8_t number, bool established) {
    connections_.set(number, established);
    write_flags();
}

std::uint8_t ComputerLink::open_connection() {
    auto number = connections_.open();
    write_flags();
    return number;
}

void ComputerLink::close_connection(std::uint8_t number) {
    connections_.close(number);
    write_flags();
}

void ComputerLink::power_on() { write_flags(); }

void ComputerLink::write_flags() {
    auto area = status_flag_area(options_.parameters);
    if (!area.on) return;
    const std::uint8_t flags = connections_.flags();
    write_area(area.place, std::span<const std::uint8_t>(&flags, 1));
}

void ComputerLink::write_area(Place place, std::span<const std::uint8_t> bytes) {
    ByteAccess memory(cpu_.memory(), map_);
    for (std::size_t i = 0; i < bytes.size(); ++i) memory.set_byte(place.file, place.address + static_cast<std::uint32_t>(i), bytes[i]);
}

}  // namespace slmp::jw51cm
