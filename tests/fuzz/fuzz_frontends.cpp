// The two front ends' framers and handlers on arbitrary streams: the host link
// (frontends/hostlink) and the JW-51CM computer link (frontends/jw51cm), fed
// the input as one TCP stream and as one UDP datagram. Whatever the bytes,
// every step consumes something or asks for more (a session never loops),
// never more than it was given, and every answer has its protocol's shape: a
// host-link record of at most 132 bytes (+ STX/ETX) ending in `*` CR, a JW
// answer of the request's header, 45 00, COM, RSLT.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>

#include "config/config.hpp"
#include "frontends/hostlink/host_link.hpp"
#include "frontends/jw51cm/computer_link.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

slmp::devicemodel::Cpu& cpu() {
    static slmp::devicemodel::Cpu instance{slmp::config::load_profile("R08CPU").cpu};
    return instance;
}

void host_link(std::span<const std::uint8_t> data) {
    static slmp::hostlink::HostLink link{cpu(), slmp::hostlink::Options{}};
    slmp::hostlink::LinkState state;
    while (!data.empty()) {
        auto result = link.handle(data, state);
        if (result.kind == slmp::hostlink::Cut::Kind::NeedMore) break;
        FUZZ_CHECK(result.consumed > 0 && result.consumed <= data.size(), "host link consumed %zu of %zu",
                   result.consumed, data.size());
        const auto& r = result.response;
        if (!r.empty()) {
            bool wrapped = r.front() == slmp::hostlink::kStx;
            auto body = wrapped ? r.size() - 2 : r.size();
            FUZZ_CHECK(body <= slmp::hostlink::kMaxRecordBytes + 0, "a %zu-byte host-link answer", body);
            auto end = wrapped ? r.size() - 1 : r.size();
            FUZZ_CHECK(end >= 2 && r[end - 2] == '*' && r[end - 1] == '\r', "a host-link answer not ending in *CR");
        }
        data = data.subspan(result.consumed);
    }
}

// Buffers of every kind, so 28-79 reach their handlers: designated 00 direct and
// 01 indirect, rings 0 (PLC -> host) and 1 (host -> PLC) direct and 2 indirect;
// the input can rewrite every info area and pointer with 34/35 after F9.
slmp::jw51cm::Options with_buffers() {
    slmp::jw51cm::Options options;
    auto set = [&](std::size_t at, std::initializer_list<std::uint8_t> bytes) {
        std::copy(bytes.begin(), bytes.end(), options.parameters.begin() + static_cast<std::ptrdiff_t>(at));
    };
    set(01000, {0x00, 0x0A, 0x00, 0x00, 0x00, 0x01, 0x00, 0x80});
    set(01010, {0x00, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0});
    set(01400, {0x10, 0x08, 0x00, 0x01, 0x0C, 0x00, 0x04, 0x80});
    set(01410, {0x20, 0x08, 0x00, 0x81, 0x10, 0x00, 0x01, 0x80});
    set(01420, {0x30, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0});
    return options;
}

void computer_link(std::span<const std::uint8_t> data) {
    static slmp::jw51cm::ComputerLink link{cpu(), with_buffers()};
    auto datagram = link.handle_datagram(data);
    if (!datagram.response.empty()) FUZZ_CHECK(datagram.response.size() >= 44, "a %zu-byte JW answer", datagram.response.size());
    while (!data.empty()) {
        auto result = link.handle_stream(data);
        if (result.kind == slmp::jw51cm::ComputerLink::Result::Kind::NeedMore) break;
        FUZZ_CHECK(result.consumed > 0 && result.consumed <= data.size(), "JW consumed %zu of %zu", result.consumed,
                   data.size());
        const auto& r = result.response;
        FUZZ_CHECK(r.size() >= 44 && r[40] == 0x45 && r[41] == 0x00 && r[42] == data[42], "a malformed JW answer");
        data = data.subspan(result.consumed);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
    std::span<const std::uint8_t> data(bytes, size);
    host_link(data);
    computer_link(data);
    return 0;
}
