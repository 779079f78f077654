#include "protocol/client_commands.hpp"

namespace slmp::protocol::client {
namespace {

std::uint16_t form_subcommand(DeviceForm form, bool bits) {
    return static_cast<std::uint16_t>((form == DeviceForm::IQR ? 2 : 0) + (bits ? 1 : 0));
}

std::span<const std::uint8_t> chars(std::string_view text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

// The remote commands other than RUN and PAUSE carry only the fixed word 0001
// (the iQ-R MC manual's "fixed value"; the SLMP manuals leave it unnamed).
std::vector<std::uint8_t> fixed_0001(const FrameOptions& options, std::uint16_t command) {
    return build_request(options, command, 0x0000, [](FieldWriter& w) { w.u16(0x0001); });
}

std::vector<std::uint8_t> password_request(const FrameOptions& options, std::uint16_t command,
                                           std::string_view password) {
    return build_request(options, command, 0x0000, [&](FieldWriter& w) {
        w.u16(static_cast<std::uint16_t>(password.size()));
        w.raw(chars(password));
    });
}

}  // namespace

std::vector<std::uint8_t> read_random(const FrameOptions& options, std::span<const devicemodel::DeviceAddress> words,
                                      std::span<const devicemodel::DeviceAddress> dwords, DeviceForm form) {
    return build_request(options, 0x0403, form_subcommand(form, false), [&](FieldWriter& w) {
        w.u8(static_cast<std::uint8_t>(words.size()));
        w.u8(static_cast<std::uint8_t>(dwords.size()));
        for (const auto& d : words) w.device(form, d);
        for (const auto& d : dwords) w.device(form, d);
    });
}

std::vector<std::uint8_t> write_random_words(const FrameOptions& options, std::span<const WordWrite> words,
                                             std::span<const DwordWrite> dwords, DeviceForm form) {
    return build_request(options, 0x1402, form_subcommand(form, false), [&](FieldWriter& w) {
        w.u8(static_cast<std::uint8_t>(words.size()));
        w.u8(static_cast<std::uint8_t>(dwords.size()));
        for (const auto& item : words) {
            w.device(form, item.device);
            w.u16(item.value);
        }
        for (const auto& item : dwords) {
            w.device(form, item.device);
            w.u32(item.value);
        }
    });
}

std::vector<std::uint8_t> write_random_bits(const FrameOptions& options, std::span<const BitWrite> bits,
                                            DeviceForm form) {
    return build_request(options, 0x1402, form_subcommand(form, true), [&](FieldWriter& w) {
        w.u8(static_cast<std::uint8_t>(bits.size()));
        for (const auto& item : bits) {
            w.device(form, item.device);
            if (form == DeviceForm::IQR) w.u16(item.on ? 1 : 0);
            else w.u8(item.on ? 1 : 0);
        }
    });
}

std::vector<std::uint8_t> remote_run(const FrameOptions& options, RemoteMode mode, ClearMode clear) {
    return build_request(options, 0x1001, 0x0000, [&](FieldWriter& w) {
        w.u16(static_cast<std::uint16_t>(mode));
        w.u8(static_cast<std::uint8_t>(clear));
        w.u8(0x00);   // fixed
    });
}

std::vector<std::uint8_t> remote_stop(const FrameOptions& options) { return fixed_0001(options, 0x1002); }

std::vector<std::uint8_t> remote_pause(const FrameOptions& options, RemoteMode mode) {
    return build_request(options, 0x1003, 0x0000, [&](FieldWriter& w) { w.u16(static_cast<std::uint16_t>(mode)); });
}

std::vector<std::uint8_t> remote_latch_clear(const FrameOptions& options) { return fixed_0001(options, 0x1005); }
std::vector<std::uint8_t> remote_reset(const FrameOptions& options) { return fixed_0001(options, 0x1006); }

std::vector<std::uint8_t> unlock(const FrameOptions& options, std::string_view password) {
    return password_request(options, 0x1630, password);
}

std::vector<std::uint8_t> lock(const FrameOptions& options, std::string_view password) {
    return password_request(options, 0x1631, password);
}

std::vector<std::uint8_t> read_type_name(const FrameOptions& options) { return build_request(options, 0x0101, 0x0000); }

std::vector<std::uint8_t> self_test(const FrameOptions& options, std::string_view data) {
    return build_request(options, 0x0619, 0x0000, [&](FieldWriter& w) {
        w.u16(static_cast<std::uint16_t>(data.size()));
        w.raw(chars(data));
    });
}

std::optional<TypeName> decode_type_name(const Response& response) {
    auto r = response.reader();
    auto name = r.raw(16, "model name");
    auto code = r.u16("model code");
    if (!r.finish()) return std::nullopt;
    TypeName result{std::string(name.begin(), name.end()), code};
    while (!result.model.empty() && (result.model.back() == ' ' || result.model.back() == '\0')) result.model.pop_back();
    return result;
}

std::optional<std::string> decode_self_test(const Response& response) {
    auto r = response.reader();
    auto count = r.u16("loopback data count");
    auto data = r.raw(count, "loopback data");
    if (!r.finish()) return std::nullopt;
    return std::string(data.begin(), data.end());
}

std::optional<ErrorInfo> decode_error_info(const Response& response) {
    auto r = response.reader();
    ErrorInfo info;
    info.route.network = r.u8("network");
    info.route.station = r.u8("station");
    info.route.module_io = r.u16("module I/O");
    info.route.multidrop = r.u8("multidrop");
    info.command = r.u16("command");
    info.subcommand = r.u16("subcommand");
    if (!r.finish()) return std::nullopt;
    return info;
}

}  // namespace slmp::protocol::client
