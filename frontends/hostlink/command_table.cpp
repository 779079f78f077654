#include "frontends/hostlink/command_table.hpp"

#include <array>

#include "devicemodel/hex.hpp"

namespace slmp::hostlink {

namespace {

using C = Compat;

// §5's command list in its order; the compatibility marks the extraction lost
// (N, I) are the spec's inferred ones.
constexpr std::array kCommands{
    CommandRow{"RR", "relay read, channel units", read_words, Area::Cio, C::Omron},
    CommandRow{"RL", "LR read, channel units", read_words, Area::Lr, C::Omron},
    CommandRow{"RH", "HR read, channel units", read_words, Area::Hr, C::Omron},
    CommandRow{"RD", "DM read", read_words, Area::Dm, C::Omron},
    CommandRow{"RV", "VR read", read_words, Area::Vr, C::New},
    CommandRow{"RC", "T/C present value read", read_words, Area::TcPresent, C::Omron},
    CommandRow{"RG", "time-up/count-up relay read", read_flags, Area::TcUp, C::Omron},
    CommandRow{"RJ", "AR read, channel units", read_words, Area::Ar, C::Omron},
    CommandRow{"Rr", "relay read, bit units", read_bits, Area::Cio, C::New},
    CommandRow{"Rh", "HR read, bit units", read_bits, Area::Hr, C::New},
    CommandRow{"Rl", "LR read, bit units", read_bits, Area::Lr, C::New},
    CommandRow{"Rj", "AR read, bit units", read_bits, Area::Ar, C::New},
    CommandRow{"Rc", "T/C set value read", read_words, Area::TcSet, C::New},
    CommandRow{"WR", "relay write, channel units", write_words, Area::Cio, C::Omron, true},
    CommandRow{"WL", "LR write, channel units", write_words, Area::Lr, C::Omron, true},
    CommandRow{"WH", "HR write, channel units", write_words, Area::Hr, C::Omron, true},
    CommandRow{"WD", "DM write", write_words, Area::Dm, C::Omron, true},
    CommandRow{"WV", "VR write", write_words, Area::Vr, C::New, true},
    CommandRow{"WC", "T/C present value write", write_words, Area::TcPresent, C::Omron, true},
    CommandRow{"WG", "time-up/count-up relay write", write_flags, Area::TcUp, C::Omron, true},
    CommandRow{"WJ", "AR write, channel units", write_words, Area::Ar, C::Omron, true},
    CommandRow{"Wr", "relay write, bit units", write_bits, Area::Cio, C::New, true},
    CommandRow{"Wh", "HR write, bit units", write_bits, Area::Hr, C::New, true},
    CommandRow{"Wl", "LR write, bit units", write_bits, Area::Lr, C::New, true},
    CommandRow{"Wj", "AR write, bit units", write_bits, Area::Ar, C::New, true},
    CommandRow{"Wc", "T/C set value write", write_words, Area::TcSet, C::New, true},
    CommandRow{"WP", "intermediate-form object write", write_image, Area::Count, C::Incompatible, true},
    CommandRow{"RP", "intermediate-form object read", read_image, Area::Count, C::Incompatible},
    CommandRow{"WE", "environment data write", write_image, Area::Count, C::Incompatible, true},
    CommandRow{"RE", "environment data read", read_image, Area::Count, C::Incompatible},
    CommandRow{"R#", "set value read 1", refused, Area::Count, C::Refused},
    CommandRow{"R$", "set value read 2", refused, Area::Count, C::Refused},
    CommandRow{"R%", "set value read 3", refused, Area::Count, C::Refused},
    CommandRow{"W#", "set value change 1", refused, Area::Count, C::Refused},
    CommandRow{"W$", "set value change 2", refused, Area::Count, C::Refused},
    CommandRow{"W%", "set value change 3", refused, Area::Count, C::Refused},
    CommandRow{"MS", "operating status read", refused, Area::Count, C::Refused},
    CommandRow{"SC", "operating mode change", refused, Area::Count, C::Refused},
    CommandRow{"MF", "fault information read/clear", refused, Area::Count, C::Refused},
    CommandRow{"KS", "forced set", refused, Area::Count, C::Refused},
    CommandRow{"KR", "forced reset", refused, Area::Count, C::Refused},
    CommandRow{"KF", "multi-point forced set/reset", refused, Area::Count, C::Refused},
    CommandRow{"KC", "cancel all forced set/reset", refused, Area::Count, C::Refused},
    CommandRow{"TS", "test (echo)", test_echo, Area::Count, C::Omron},
    CommandRow{"XZ", "abort (no response)", silent, Area::Count, C::Omron},
    CommandRow{"**", "system initialise (no response)", initialise, Area::Count, C::Omron},
    CommandRow{"R&", "system information read", system_info, Area::Count, C::New},
    CommandRow{"MM", "model code read", model_code, Area::Count, C::Omron},
    CommandRow{"QQ", "composite command (MR register, IR read)", composite, Area::Count, C::Omron},
};

}  // namespace

std::span<const CommandRow> command_table() { return kCommands; }

const CommandRow* find_command(std::string_view code) {
    if (code == "RI") code = "Rl";   // the command list's spelling (§5, §8)
    if (code == "WI") code = "Wl";
    for (const auto& row : kCommands)
        if (row.code == code) return &row;
    return nullptr;
}

std::optional<std::uint32_t> decimal(std::string_view text) {
    if (text.empty()) return std::nullopt;
    std::uint32_t value = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + static_cast<std::uint32_t>(c - '0');
    }
    return value;
}

std::optional<std::uint32_t> hex(std::string_view text) {
    if (text.empty() || text.size() > 8) return std::nullopt;
    return devicemodel::parse_hex(text);
}

}  // namespace slmp::hostlink
