#include "tools/slmp/probe.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <thread>
#include <ostream>

#include "config/config.hpp"
#include "devicemodel/hex.hpp"
#include "protocol/client_commands.hpp"
#include "protocol/client_files.hpp"
#include "protocol/command_table.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

using devicemodel::Area;
using devicemodel::DeviceAddress;
using devicemodel::DeviceSpec;
using devicemodel::Family;
using devicemodel::hex4;
using protocol::Codec;
using protocol::DeviceForm;
using protocol::FieldWriter;
using protocol::FrameKind;
using Kind = Observed::Kind;
using Bytes = std::vector<std::uint8_t>;

namespace {

DeviceAddress at(std::string_view symbol, std::uint32_t number) { return {devicemodel::find_by_symbol(symbol), number}; }

bool served(const Observed& o) { return o.kind == Kind::Answer && o.end_code == 0; }

// How a port reacts, as a profile writes it: "answer", "silence", "close" or the end code.
std::string reaction(const Observed& o) {
    switch (o.kind) {
        case Kind::Silence: return "silence";
        case Kind::Close: return "close";
        case Kind::Answer: break;
    }
    return o.end_code == 0 ? "answer" : hex4(o.end_code);
}

std::uint16_t sub(DeviceForm form, bool bits, bool extended = false) {
    return static_cast<std::uint16_t>((extended ? 0x80 : 0) + (form == DeviceForm::IQR ? 2 : 0) + (bits ? 1 : 0));
}

// The built-in profile that is the root of each family: what a probed profile
// extends for the facts the probe cannot find (docs/twin.md).
std::string family_base(Family family) {
    switch (family) {
        case Family::IQR: return "R08CPU";
        case Family::QnU: return "Q26UDEHCPU";
        case Family::L: return "L26CPU-BT";
        case Family::QJ71E71: return "Q06UDVCPU-QJ71E71";
        case Family::IQF: return "FX5U-32MR";
    }
    return "R08CPU";
}

// The spec a size is probed with: the area's plain device, or a timer's or
// counter's current value (a word, or a double word for the long ones).
const DeviceSpec* sizing_spec(Area area) {
    const DeviceSpec* found = nullptr;
    for (const auto& spec : devicemodel::all_devices()) {
        if (spec.area != area || spec.symbol == "DX" || spec.symbol == "DY") continue;
        if (spec.part == devicemodel::Part::Plain || spec.part == devicemodel::Part::Value) return &spec;
        if (!found) found = &spec;
    }
    return found;
}

}  // namespace

ScratchRanges parse_scratch_ranges(const std::string& text, devicemodel::Numbering numbering) {
    devicemodel::NumberingScope scope(numbering);
    ScratchRanges ranges;
    std::size_t start = 0;
    while (start <= text.size()) {
        auto comma = text.find(',', start);
        auto part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        start = comma == std::string::npos ? text.size() + 1 : comma + 1;
        auto dash = part.find('-');
        if (dash == std::string::npos)
            throw UsageError("--allow-writes '" + part + "' is not a range; write FIRST-LAST, e.g. D9000-D9999");
        std::string error;
        auto first = devicemodel::parse_address(part.substr(0, dash), &error);
        auto last = devicemodel::parse_address(part.substr(dash + 1), &error);
        if (!first || !last) throw UsageError("--allow-writes '" + part + "': " + error);
        if (first->spec != last->spec || last->number < first->number)
            throw UsageError("--allow-writes '" + part + "': one device, the first before the last (D9000-D9999)");
        auto count = last->number - first->number + 1;
        if (first->spec->part != devicemodel::Part::Plain)
            throw UsageError("--allow-writes '" + part + "': use a plain word or bit device (D, W, R, ZR, M, B ...)");
        if (first->spec->unit == devicemodel::Unit::Bit) {
            ranges.bits = first;
            ranges.bit_count = count;
        } else {
            ranges.words = first;
            ranges.word_count = count;
        }
    }
    return ranges;
}

Prober::Prober(const ProbeSettings& settings, WireRecorder* recorder, std::ostream& progress)
    : settings_(settings), recorder_(recorder), progress_(progress), wire_(settings.target, settings.silence, recorder) {}

void Prober::progress(const std::string& line) { progress_ << "probe: " << line << '\n' << std::flush; }

void Prober::fact(std::string name, std::string value, std::string how, bool found) {
    facts_.push_back({std::move(name), std::move(value), std::move(how), found});
}

protocol::client::FrameOptions Prober::frame(Codec codec, FrameKind kind) const {
    auto options = settings_.frame;
    options.codec = codec;
    options.kind = kind;
    options.serial = serial_;
    return options;
}

Observed Prober::ask(const Bytes& request) {
    ++serial_;
    return wire_.exchange(request);
}

Observed Prober::ask_in(Codec codec, FrameKind kind, std::uint16_t command, std::uint16_t subcommand,
                        const std::function<void(FieldWriter&)>& body) {
    return ask(protocol::client::build_request(frame(codec, kind), command, subcommand, body));
}

std::optional<Prober::Limit> Prober::bisect(std::uint32_t cap, const std::function<Bytes(std::uint32_t)>& request) {
    Limit limit;
    auto ok = [&](std::uint32_t n) {
        ++limit.requests;
        return served(ask(request(n)));
    };
    if (!ok(1)) return std::nullopt;
    std::uint32_t good = 1, bad = 0;
    for (std::uint32_t n = 16; !bad; n = std::min<std::uint64_t>(std::uint64_t{n} * 2, cap)) {
        if (ok(n)) good = n;
        else bad = n;
        if (n == cap) break;
    }
    if (!bad) {
        limit.max = good;
        return limit;
    }
    while (bad - good > 1) {
        auto mid = good + (bad - good) / 2;
        (ok(mid) ? good : bad) = mid;
    }
    limit.max = good;
    ++limit.requests;
    limit.over = ask(request(good + 1));
    return limit;
}

nlohmann::ordered_json Prober::run() {
    identity();
    frames();
    subcommand_forms();
    family();
    end_codes();
    sizes();
    limits();
    commands();
    writes();
    if (!settings_.target.udp) {
        pipeline();
        connections();
    }
    timing();
    wire_.close("probe done");
    return profile_;
}

// 0101: the model name and code, or how the port refuses it.
void Prober::identity() {
    progress("0101 Read Type Name");
    for (auto codec : {Codec::Binary, Codec::Ascii}) {
        auto o = ask(protocol::client::read_type_name(frame(codec, FrameKind::E3)));
        if (o.kind != Kind::Answer) continue;
        (codec == Codec::Binary ? binary_ : ascii_) = true;
        if (o.end_code != 0) {
            fact("type_name", "refused: " + reaction(o), "0101 answered an end code; the base's name is kept (never sent)");
            not_supported_ = o.end_code;
            codec_ = codec;
            return;
        }
        auto response = protocol::client::parse_response(o.bytes);
        auto name = response ? protocol::client::decode_type_name(*response) : std::nullopt;
        if (!name) continue;
        type_answered_ = true;
        codec_ = codec;
        profile_["type_name"] = name->model;
        profile_["model_code"] = hex4(name->model_code);
        fact("type_name", name->model + " " + hex4(name->model_code), "0101 Read Type Name");
        return;
    }
    // 0101 got silence or a close in both codes: does the port answer 3E at all?
    for (auto codec : {Codec::Binary, Codec::Ascii}) {
        auto o = ask(protocol::client::read_words(frame(codec, FrameKind::E3), at("D", 0), 1));
        if (o.kind == Kind::Answer) {
            codec_ = codec;
            (codec == Codec::Binary ? binary_ : ascii_) = true;
            fact("type_name", "no answer to 0101", "0101 got silence or a close; 0401 is answered");
            return;
        }
    }
    throw ConnectionError("the port answers no 3E request (0101, 0401) in binary or ASCII: check --host/--port, --udp, "
                          "and that the port is an SLMP (MC protocol) port");
}

// The frames and data codes the port answers, and what it does with the others.
void Prober::frames() {
    progress("frames: 3E/4E, binary/ASCII, 1E");
    auto read_d0 = [&](Codec codec, FrameKind kind) {
        return ask(protocol::client::read_words(frame(codec, kind), at("D", 0), 1));
    };
    for (auto codec : {Codec::Binary, Codec::Ascii}) {
        auto o = read_d0(codec, FrameKind::E3);
        bool answered = o.kind == Kind::Answer;
        (codec == Codec::Binary ? binary_ : ascii_) = answered;
        fact(codec == Codec::Binary ? "3E binary" : "3E ASCII", reaction(o),
             "0401 D0 x1 (a port setting, not a profile key: slmp-sim's --data-code)");
    }
    if (!binary_) codec_ = Codec::Ascii;
    auto e4 = read_d0(codec_, FrameKind::E4);
    e4_ = served(e4);
    profile_["frame_4e"] = e4_ ? "answer" : reaction(e4);
    fact("frame_4e", profile_["frame_4e"], "0401 D0 x1 in a 4E frame");
    // 1E PC type read (subheader 15, PC No. FF, monitoring timer 000A): answered 95 00 <type> where 1E is served.
    Bytes pc_type{0x15, 0xFF, 0x0A, 0x00};
    auto e1 = ask(pc_type);
    if (e1.kind == Kind::Answer && e1.bytes.size() >= 3 && e1.bytes[0] == 0x95 && e1.bytes[1] == 0x00) {
        profile_["frame_1e"] = {{"pc_type", devicemodel::hex_text(e1.bytes[2], 4)}};
        fact("frame_1e", "served, PC type " + devicemodel::hex_text(e1.bytes[2], 2), "1E PC type read (15 FF 0A 00)");
    } else {
        profile_["frame_1e"] = nullptr;   // removes the base's
        fact("frame_1e", "not served (" + reaction(e1) + ")", "1E PC type read (15 FF 0A 00)");
    }
}

// Which subcommand families the device commands take: Q form, iQ-R form, 008x.
void Prober::subcommand_forms() {
    progress("subcommand forms: Q, iQ-R, 008x");
    auto iqr = ask(protocol::client::read_words(frame(codec_, FrameKind::E3), at("D", 0), 1, DeviceForm::IQR));
    iqr_ = served(iqr);
    profile_["iqr_subcommands"] = iqr_ ? "answer" : reaction(iqr);
    fact("iqr_subcommands", profile_["iqr_subcommands"], "0401/0002 D0 x1");
    auto extended = ask_in(codec_, FrameKind::E3, 0x0401, 0x0080, [](FieldWriter& w) {
        w.extended_device(DeviceForm::Q, at("D", 0));
        w.u16(1);
    });
    extended_ = served(extended);
    fact("008x subcommands", reaction(extended), "0401/0080 D0 x1 (the command table's rows; not a profile key)");
    auto monitor = ask_in(codec_, FrameKind::E3, 0x0801, 0x0000, [](FieldWriter& w) {
        w.u8(1);
        w.u8(0);
        w.device(DeviceForm::Q, at("D", 0));
    });
    monitor_served_ = served(monitor);
    // 0004 is the L CPUs' 32-character-password form of the file commands (a
    // QnU refuses it): an open of a file that does not exist tells them apart.
    protocol::client::FileTarget missing{false, 4, "PROBE.NOF", "", true};
    auto l_form = ask(protocol::client::file_open(frame(codec_, FrameKind::E3), missing, false));
    l_only_subcommand_ = l_form.kind == Kind::Answer && l_form.end_code != not_supported_;
}

// The family decides which commands the command table serves, and which built-in
// profile the probed one extends (docs/twin.md "How the family is told").
void Prober::family() {
    if (iqr_) family_ = Family::IQR;
    else if (type_answered_ && !monitor_served_) family_ = Family::IQF;
    else if (!type_answered_) family_ = l_only_subcommand_ ? Family::L : Family::QnU;
    else family_ = Family::QJ71E71;
    base_ = family_base(family_);
    base_cpu_ = config::load_profile(base_).cpu;
    profile_["family"] = std::string(config::family_name(family_));
    fact("family", profile_["family"].get<std::string>() + " (extends " + base_ + ")",
         "iQ-R form served: iQ-R; 0101 answered but 0801 refused: iQ-F; 0101 refused: QnU, or L when file "
         "subcommand 0004 is known; else QJ71E71");
    // iQ-F numbers X/Y in octal: in ASCII, X"000008" is no octal number.
    if (ascii_) {
        auto o = ask_in(Codec::Ascii, FrameKind::E3, 0x0401, 0x0001, [](FieldWriter& w) {
            w.raw(Bytes{'X', '*', '0', '0', '0', '0', '0', '8'});
            w.u16(1);
        });
        profile_["xy_radix"] = served(o) ? 16 : 8;
        fact("xy_radix", std::to_string(profile_["xy_radix"].get<int>()), "ASCII 0401 X000008 x1: " + reaction(o));
        auto zr = ask_in(Codec::Ascii, FrameKind::E3, 0x0401, 0x0000, [](FieldWriter& w) {
            w.raw(Bytes{'Z', 'R', '0', '0', '0', '0', '0', 'A'});
            w.u16(1);
        });
        profile_["zr_ascii_hex"] = served(zr);
        fact("zr_ascii_hex", served(zr) ? "true" : "false", "ASCII 0401 ZR00000A x1 (hex digits): " + reaction(zr));
    } else {
        fact("xy_radix", "base's", "needs ASCII frames, which the port does not answer", false);
        fact("zr_ascii_hex", "base's", "needs ASCII frames, which the port does not answer", false);
    }
}

void Prober::end_codes() {
    progress("end codes");
    auto& codes = profile_["end_codes"];
    auto unknown = ask_in(codec_, FrameKind::E3, 0x1234, 0x0000, {});
    if (unknown.kind == Kind::Answer && unknown.end_code) {
        not_supported_ = unknown.end_code;
        codes["not_supported"] = hex4(unknown.end_code);
    }
    fact("end_codes.not_supported", reaction(unknown), "command 1234 (no such command)", unknown.end_code != 0);
    auto bad_device = ask_in(codec_, FrameKind::E3, 0x0401, 0x0000, [&](FieldWriter& w) {
        if (codec_ == Codec::Binary) {
            w.u16(0);
            w.u8(0);
            w.u8(0x77);
        } else {
            w.raw(Bytes{'Q', 'Q', '0', '0', '0', '0', '0', '0'});
        }
        w.u16(1);
    });
    if (bad_device.kind == Kind::Answer && bad_device.end_code) codes["unknown_device"] = hex4(bad_device.end_code);
    fact("end_codes.unknown_device", reaction(bad_device), "0401 of device code 77 (none)", bad_device.end_code != 0);
    auto bad_unit = ask(protocol::client::read_bits(frame(codec_, FrameKind::E3), at("D", 0), 1));
    if (bad_unit.kind == Kind::Answer && bad_unit.end_code) codes["bad_unit"] = hex4(bad_unit.end_code);
    fact("end_codes.bad_unit", reaction(bad_unit), "0401/0001 (bit units) of D0", bad_unit.end_code != 0);
}

std::optional<std::uint32_t> Prober::area_size(const DeviceSpec& spec, DeviceForm form, unsigned& asked) {
    const bool bits = spec.unit == devicemodel::Unit::Bit;
    const auto points = bits ? 1u : devicemodel::words_per_device(spec);
    auto read = [&](std::uint32_t number) {
        ++asked;
        return served(ask_in(codec_, FrameKind::E3, 0x0401, sub(form, bits), [&](FieldWriter& w) {
            w.device(form, {&spec, number});
            w.u16(static_cast<std::uint16_t>(points));
        }));
    };
    if (!read(0)) return 0;
    const std::uint32_t cap = form == DeviceForm::Q ? 0xFFFFFF : 0x7FFFFFFF;
    std::uint32_t good = 0, bad = 0;
    for (std::uint64_t n = 1024; !bad; n *= 2) {
        auto probe = static_cast<std::uint32_t>(std::min<std::uint64_t>(n, cap));
        if (read(probe)) good = probe;
        else bad = probe;
        if (probe == cap && !bad) return std::nullopt;   // larger than the address field reaches
    }
    while (bad - good > 1) {
        auto mid = good + (bad - good) / 2;
        (read(mid) ? good : bad) = mid;
    }
    return good + 1;
}

// Device sizes: range probing (a read of one point at N, doubling then
// bisecting) where the port reaches the area, checked against the size
// registers (SD260… iQ-R/iQ-F, SD286… Q/L) the family publishes them in.
void Prober::sizes() {
    progress("device sizes (size registers, range probing)");
    std::array<std::optional<std::uint32_t>, static_cast<std::size_t>(Area::Count)> published{};
    for (const auto& reg : base_cpu_.size_registers) {
        auto o = ask(protocol::client::read_words(frame(codec_, FrameKind::E3), at("SD", reg.sd), reg.bits / 16));
        auto response = served(o) ? protocol::client::parse_response(o.bytes) : std::nullopt;
        if (!response) continue;
        auto r = response->reader();
        std::uint32_t value = r.u16("low");
        if (reg.bits == 32) value |= std::uint32_t{r.u16("high")} << 16;
        published[static_cast<std::size_t>(reg.area)] = value;
    }
    auto& sizes = profile_["device_sizes"];
    for (std::size_t i = 0; i < static_cast<std::size_t>(Area::Count); ++i) {
        auto area = static_cast<Area>(i);
        const auto name = std::string(devicemodel::area_name(area));
        const auto* spec = sizing_spec(area);
        if (!spec || spec->extension_only) {
            fact("device_sizes." + name, "base's", "buffer memory needs the 008x extension; not probed", false);
            continue;
        }
        std::optional<std::uint32_t> size;
        unsigned asked = 0;
        std::string how;
        if (spec->q_code >= 0) size = area_size(*spec, DeviceForm::Q, asked), how = "range probing, Q form";
        else if (iqr_) size = area_size(*spec, DeviceForm::IQR, asked), how = "range probing, iQ-R form";
        how += " (" + std::to_string(asked) + " requests)";
        const auto& sd = published[i];
        if (!size && sd) size = sd, how = "its size register";
        else if (size && sd)
            how += *sd == *size ? "; the size register agrees" : "; the size register says " + std::to_string(*sd);
        if (!size) {
            fact("device_sizes." + name, "base's",
                 "no Q-form device code, the iQ-R form is refused and no size register", false);
            continue;
        }
        sizes[name] = *size;
        if (area == Area::D) d_size_ = *size;
        fact("device_sizes." + name, std::to_string(*size), how);
    }
    // Out of range, and the areas whose span the port does not check (only the start).
    if (d_size_) {
        auto o = ask(protocol::client::read_words(frame(codec_, FrameKind::E3), at("D", d_size_), 1));
        if (o.kind == Kind::Answer && o.end_code) profile_["end_codes"]["out_of_range"] = hex4(o.end_code);
        fact("end_codes.out_of_range", reaction(o), "0401 D" + std::to_string(d_size_) + " x1 (one past the end)");
    }
    auto start_only = nlohmann::ordered_json::array();
    for (const auto& [name, size] : sizes.items()) {
        auto area = devicemodel::area_by_name(name);
        const auto* spec = area ? sizing_spec(*area) : nullptr;
        if (!spec || size.get<std::uint32_t>() == 0) continue;
        const bool bits = spec->unit == devicemodel::Unit::Bit;
        const auto form = spec->q_code >= 0 ? DeviceForm::Q : DeviceForm::IQR;
        const auto last = size.get<std::uint32_t>() - 1;
        auto o = ask_in(codec_, FrameKind::E3, 0x0401, sub(form, bits), [&](FieldWriter& w) {
            w.device(form, {spec, last});
            w.u16(static_cast<std::uint16_t>(2 * (bits ? 1 : devicemodel::words_per_device(*spec))));
        });
        if (served(o)) start_only.push_back(name);
    }
    profile_["start_only_range_check"] = start_only;
    fact("start_only_range_check", start_only.dump(), "0401 of the last point x2 in each area: served = only the start is checked");
}

void Prober::limits() {
    progress("point limits (bisection)");
    auto& limits = profile_["limits"];
    auto point_limit = [&](const std::string& key, std::uint32_t cap, const std::function<Bytes(std::uint32_t)>& request,
                           const std::string& how) {
        auto found = bisect(cap, request);
        if (!found || !found->over) {
            fact("limits." + key, "base's", how + (found ? ": no limit below " + std::to_string(cap) : ": one point is refused"), false);
            return;
        }
        const auto& over = *found->over;
        if (over.kind != Kind::Answer) {   // a profile limit answers an end code; silence or a close has no key
            fact("limits." + key, "base's", how + ": over " + std::to_string(found->max) + " the port answers " + reaction(over), false);
            return;
        }
        limits[key] = {{"max", found->max}, {"end_code", hex4(over.end_code)}};
        fact("limits." + key, std::to_string(found->max) + ", over it " + reaction(over),
             how + " (" + std::to_string(found->requests) + " requests)");
    };
    auto words = [&](Codec codec) {
        return [this, codec](std::uint32_t n) {
            return protocol::client::read_words(frame(codec, FrameKind::E3), at("D", 0), static_cast<std::uint16_t>(n));
        };
    };
    auto bits = [&](Codec codec) {
        return [this, codec](std::uint32_t n) {
            return protocol::client::read_bits(frame(codec, FrameKind::E3), at("M", 0), static_cast<std::uint16_t>(n));
        };
    };
    point_limit("batch_words", 0xFFFF, words(codec_), "0401 D0 xN");
    if (binary_) point_limit("batch_bits_binary", 0xFFFF, bits(Codec::Binary), "0401/0001 M0 xN, binary");
    else fact("limits.batch_bits_binary", "base's", "the port answers no binary frame", false);
    if (ascii_) point_limit("batch_bits_ascii", 0xFFFF, bits(Codec::Ascii), "0401/0001 M0 xN, ASCII");
    else fact("limits.batch_bits_ascii", "base's", "the port answers no ASCII frame", false);
    point_limit("block_points", 0xFFFF, [this](std::uint32_t n) {
        return protocol::client::build_request(frame(codec_, FrameKind::E3), 0x0406, 0x0000, [&](FieldWriter& w) {
            w.u8(1);
            w.u8(0);
            w.device(DeviceForm::Q, at("D", 0));
            w.u16(static_cast<std::uint16_t>(n));
        });
    }, "0406 one block D0 xN");
    {
        auto found = bisect(0xFFFF, [this](std::uint32_t n) {
            return protocol::client::self_test(frame(codec_, FrameKind::E3), std::string(n, '5'));
        });
        if (found) {
            limits["loopback_bytes"] = found->max;
            fact("limits.loopback_bytes", std::to_string(found->max), "0619 of N bytes (" + std::to_string(found->requests) + " requests)");
        } else {
            fact("limits.loopback_bytes", "base's", "0619 is refused", false);
        }
    }
    // The per-form limits: Q form and iQ-R form, counted in a one-byte field.
    auto form_limit = [&](const std::string& key, std::uint16_t command, bool applies, const std::string& how) {
        if (!applies) {
            fact("limits." + key, "base's", how + " is refused by this port", false);
            return;
        }
        nlohmann::ordered_json value = nlohmann::ordered_json::object();
        std::string shown;
        for (auto form : {DeviceForm::Q, DeviceForm::IQR}) {
            const char* form_key = form == DeviceForm::Q ? "q" : "iqr";
            if (form == DeviceForm::IQR && !iqr_) {
                value[form_key] = 0;
                continue;
            }
            auto found = bisect(255, [&, form](std::uint32_t n) {
                return protocol::client::build_request(frame(codec_, FrameKind::E3), command, sub(form, false), [&](FieldWriter& w) {
                    w.u8(static_cast<std::uint8_t>(n));
                    w.u8(0);
                    for (std::uint32_t i = 0; i < n; ++i) {
                        w.device(form, at("D", i));
                        if (command == 0x0406) w.u16(1);
                    }
                });
            });
            // A limit the one-byte count cannot pass, or one refused without an end code, is not found.
            if (!found || !found->over || found->over->kind != Kind::Answer) {
                fact("limits." + key, "base's", how + ", " + form_key + " form: " +
                     (found ? "no end code up to " + std::to_string(found->max) : "one point is refused"), false);
                return;
            }
            value[form_key] = found->max;
            value["end_code"] = hex4(found->over->end_code);
            shown += std::string(shown.empty() ? "" : ", ") + form_key + " " + std::to_string(found->max) +
                     " (over: " + reaction(*found->over) + ")";
        }
        limits[key] = value;
        fact("limits." + key, shown, how + ", bisection of N in each form");
    };
    form_limit("random_read_points", 0x0403, true, "0403 of N words");
    form_limit("monitor_points", 0x0801, monitor_served_, "0801 of N words");
    form_limit("block_count", 0x0406, true, "0406 of N one-point blocks");
    // 008x: each point counts twice; a port may answer another code over it.
    if (extended_) {
        auto q = limits["random_read_points"].value("q", 0u);
        auto over = ask_in(codec_, FrameKind::E3, 0x0403, 0x0080, [&](FieldWriter& w) {
            auto n = q / 2 + 1;
            w.u8(static_cast<std::uint8_t>(n));
            w.u8(0);
            for (std::uint32_t i = 0; i < n; ++i) w.extended_device(DeviceForm::Q, at("D", i));
        });
        auto normal = limits["random_read_points"].value("end_code", std::string("C054"));
        if (over.kind == Kind::Answer && over.end_code && hex4(over.end_code) != normal)
            limits["extended_over_limit_code"] = hex4(over.end_code);
        fact("limits.extended_over_limit_code", reaction(over), "0403/0080 of q/2 + 1 points (each counts twice)");
    }
}

// The commands the port refuses: every read-only row of the command table,
// sent in its smallest harmless form; refused = the not-supported end code
// (or silence/close). Rows its family serves but it refuses become
// unsupported_commands.
void Prober::commands() {
    progress("commands served and refused");
    std::vector<std::string> listed, unexpected;
    auto scratch = settings_.scratch.words.value_or(at("D", 0));
    auto scratch_bits = settings_.scratch.bits.value_or(at("M", 0));
    // A command is unsupported when every row of it that was asked is refused
    // (a family may serve one subcommand form of a command and not another).
    std::map<std::uint16_t, bool> any_served;   // rows the family serves
    std::map<std::uint16_t, bool> served_any;   // all rows asked
    bool node_served = false;                   // any of 0E30-0E53 answered
    for (const auto& row : protocol::all_commands()) {
        if (row.writes()) continue;
        if (!iqr_ && row.form == DeviceForm::IQR && row.device_command()) continue;   // iqr_subcommands says
        if (!extended_ && (row.subcommand & 0x80)) continue;
        auto request = protocol::differential::sample_request(row, frame(codec_, FrameKind::E3), scratch, scratch_bits);
        if (!request) continue;
        auto o = ask(*request);
        bool refused_here = o.kind != Kind::Answer || o.end_code == not_supported_;
        // The node commands (docs/nodes.md) are a profile key of their own, not
        // a family's: one served (any answer but not-supported, silence
        // included for IP Address Set to no one's MAC) makes "node_commands".
        if (row.node_command()) {
            const bool answered = o.kind == Kind::Answer && o.end_code != not_supported_;
            node_served |= answered;
            continue;
        }
        if (refused_here) listed.push_back(hex4(row.command) + "/" + hex4(row.subcommand) + " " + reaction(o));
        if (row.served_by(family_)) any_served[row.command] |= !refused_here;
        served_any[row.command] |= !refused_here;
        if (!refused_here && !row.served_by(family_))
            unexpected.push_back(hex4(row.command) + "/" + hex4(row.subcommand));
    }
    // Label, file and buffer-memory support, as the rows above found it.
    auto support = [&](const std::string& what, std::initializer_list<std::uint16_t> commands, const std::string& how) {
        std::string seen;
        for (auto c : commands) {
            auto it = served_any.find(c);
            seen += (seen.empty() ? "" : ", ") + hex4(c) + (it != served_any.end() && it->second ? " served" : " refused");
        }
        fact(what, seen, how);
    };
    support("labels", {0x041C, 0x041A}, "041C/041A of a label that does not exist: any answer but not-supported");
    support("files", {0x1810, 0x1811, 0x1827}, "1810/1811/1827 on drive 4, a file that does not exist");
    support("buffer memory", {0x0613, 0x0601}, "0613 of word 0, 0601 of module 03E0");
    if (node_served) profile_["node_commands"] = true;
    fact("node commands", node_served ? "served" : "refused",
         "0E30 node search, 0E32/0E33/0E44/0E45/0E53 reads, 0E34/0E36/0E3A without a start (CF31 on a node)");
    auto refused = nlohmann::ordered_json::array();
    for (const auto& [command, served_once] : any_served)
        if (!served_once) refused.push_back(hex4(command));
    profile_["unsupported_commands"] = refused;
    std::string text;
    for (const auto& l : listed) text += (text.empty() ? "" : ", ") + l;
    fact("refused commands", text.empty() ? "none" : text, "each read-only command-table row, its smallest harmless request");
    fact("unsupported_commands", refused.dump(), "refused rows the family serves");
    if (!unexpected.empty()) {
        std::string u;
        for (const auto& l : unexpected) u += (u.empty() ? "" : ", ") + l;
        fact("served beyond the family", u, "a family that serves these has no profile key; the twin refuses them", false);
    }
}

// Commands per connection: a burst of requests in one send; the port serves
// 1 + buffer ÷ connections of them (this is the only connection). Three
// bursts, the best one counted: a connection closed just before the first may
// still be counted by the port when a burst arrives (slmp-sim frees it on the
// station's turn, which can come after a whole burst); the later bursts go on
// the same connection when the one before was all answered.
void Prober::pipeline() {
    progress("commands per connection (a burst of 200)");
    std::vector<Bytes> burst;
    for (int i = 0; i < 200; ++i) {
        burst.push_back(protocol::client::read_words(frame(codec_, FrameKind::E3), at("D", 0), 1));
        ++serial_;
    }
    auto served_in = [](const std::vector<Observed>& outcomes) {
        std::size_t n = 0;
        while (n < outcomes.size() && served(outcomes[n])) ++n;
        return n;
    };
    wire_.close("before the bursts");
    auto outcomes = wire_.burst(burst);
    for (int more = 0; more < 2; ++more)
        if (auto again = wire_.burst(burst); served_in(again) > served_in(outcomes)) outcomes = std::move(again);
    const auto served_count = served_in(outcomes);
    if (served_count == outcomes.size()) {
        profile_["pipeline"] = nullptr;
        fact("pipeline", "no limit up to 200", "a burst of 200 × 0401 in one send, all answered");
        return;
    }
    profile_["pipeline"] = {{"buffer", served_count - 1}, {"over_limit", reaction(outcomes[served_count])}};
    fact("pipeline", "buffer " + std::to_string(served_count - 1) + ", over it " + reaction(outcomes[served_count]),
         "a burst of 200 × 0401 in one send: " + std::to_string(served_count) + " answered");
}

// How many TCP connections the port serves at once: opened one by one (each
// asked 0401) until one is refused or closed, then all closed at once.
void Prober::connections() {
    progress("connections (up to " + std::to_string(settings_.max_connections) + ")");
    std::vector<std::unique_ptr<Wire>> open;
    // The probe's own connection counts when the bursts left it open (it is
    // not closed just now, so the port cannot still be freeing it).
    unsigned count = wire_.is_open() ? 1 : 0;
    std::string stop = "none refused";
    for (unsigned i = count; i < settings_.max_connections; ++i) {
        auto wire = std::make_unique<Wire>(settings_.target, settings_.silence, recorder_);
        auto o = wire->exchange(protocol::client::read_words(frame(codec_, FrameKind::E3), at("D", 0), 1));
        other_wires_sent_ += wire->sent();
        if (!served(o)) {
            stop = "connection " + std::to_string(i + 1) + ": " + reaction(o);
            break;
        }
        ++count;
        open.push_back(std::move(wire));
    }
    for (auto& w : open) w->close("counted");
    // The port frees the connections when it has seen them closed: wait (at
    // most the timeout) until it serves this one again, so the steps after
    // this one are not refused for a connection it still counts.
    auto deadline = Clock::now() + settings_.target.timeout;
    while (!served(ask(protocol::client::read_words(frame(codec_, FrameKind::E3), at("D", 0), 1))) &&
           Clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    profile_["max_connections"] = count;
    fact("max_connections", std::to_string(count) + (stop == "none refused" ? " (the most tried)" : ""),
         "TCP connections opened one by one, each asked 0401 (" + stop + ")",
         stop != "none refused" || count == settings_.max_connections);
}

// The response-time model: timed reads of 1 … 960 words (the fastest of five
// each), a straight line through them: Ke (ms) + Kdt (ms a word) × words.
void Prober::timing() {
    progress("response times (reads of 1..960 words)");
    auto& timing = profile_["timing"];
    for (auto codec : {Codec::Binary, Codec::Ascii}) {
        if ((codec == Codec::Binary && !binary_) || (codec == Codec::Ascii && !ascii_)) continue;
        std::vector<std::pair<double, double>> points;   // words, ms
        double spread = 0;
        auto max_words = std::min<std::uint32_t>(960, profile_["limits"]["batch_words"].value("max", 960u));
        max_words = std::min(max_words, std::max<std::uint32_t>(d_size_, 1));
        for (std::uint32_t words : {1u, max_words / 4, max_words / 2, 3 * max_words / 4, max_words}) {
            if (words == 0) continue;
            double fastest = 1e9, slowest = 0;
            for (int i = 0; i < 5; ++i) {
                auto o = ask(protocol::client::read_words(frame(codec, FrameKind::E3), at("D", 0), static_cast<std::uint16_t>(words)));
                if (!served(o)) break;
                double ms = static_cast<double>(wire_.last_elapsed().count()) / 1000.0;
                fastest = std::min(fastest, ms);
                slowest = std::max(slowest, ms);
            }
            if (fastest < 1e9) points.emplace_back(words, fastest);
            spread = std::max(spread, slowest - fastest);
        }
        if (points.size() < 2) {
            fact(codec == Codec::Binary ? "timing (binary)" : "timing (ASCII)", "base's", "the timed reads were not served", false);
            continue;
        }
        double n = static_cast<double>(points.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (auto [x, y] : points) sx += x, sy += y, sxx += x * x, sxy += x * y;
        double kdt = std::max(0.0, (n * sxy - sx * sy) / (n * sxx - sx * sx));
        double ke = std::max(0.0, (sy - kdt * sx) / n);
        auto round3 = [](double v) { return std::round(v * 10000.0) / 10000.0; };
        auto text = [](double v) {
            std::ostringstream out;
            out << v;
            return out.str();
        };
        const bool binary = codec == Codec::Binary;
        timing[binary ? "ke_ms" : "ke_ascii_ms"] = round3(ke);
        timing[binary ? "kdt_ms" : "kdt_ascii_ms"] = std::min(100.0, round3(kdt));
        fact(binary ? "timing (binary)" : "timing (ASCII)",
             "Ke " + text(round3(ke)) + " ms + Kdt " + text(round3(kdt)) + " ms/word; spread " + text(round3(spread)) + " ms",
             "the fastest of 5 reads of 1, 1/4, 1/2, 3/4 and all of " + std::to_string(max_words) +
                 " words, a least-squares line; the spread (slowest − fastest) bounds the scan time a port "
                 "that answers at END adds");
    }
    fact("timing.scan_wait", "base's", "whether answers wait for END is not told apart from network jitter", false);
}

// With --allow-writes only: the write commands' limits, the mixed word+bit
// 1406, and read-only areas — in the scratch ranges, restored at the end.
void Prober::writes() {
    const auto& scratch = settings_.scratch;
    if (!scratch.words) {
        for (const char* key : {"limits.random_write_weight", "limits.random_write_bits", "mixed_block_write",
                                "read_only_devices", "end_codes.not_accessible"})
            fact(key, "base's", "needs --allow-writes (a scratch range the probe may write)", false);
        return;
    }
    progress("write commands in the scratch ranges (restored afterwards)");
    // Keep what the scratch words hold, to write it back.
    std::vector<std::uint16_t> saved;
    auto word_limit = profile_["limits"]["batch_words"].value("max", 960u);
    for (std::uint32_t done = 0; done < scratch.word_count;) {
        auto n = std::min(scratch.word_count - done, word_limit);
        DeviceAddress from{scratch.words->spec, scratch.words->number + done};
        auto o = ask(protocol::client::read_words(frame(codec_, FrameKind::E3), from, static_cast<std::uint16_t>(n)));
        auto response = served(o) ? protocol::client::parse_response(o.bytes) : std::nullopt;
        if (!response) throw ConnectionError("--allow-writes: the scratch range cannot be read (" + reaction(o) + "); check it exists");
        auto r = response->reader();
        auto values = r.words(n, "scratch");
        saved.insert(saved.end(), values.begin(), values.end());
        done += n;
    }
    std::vector<std::uint8_t> saved_bits;
    if (scratch.bits) {
        auto o = ask(protocol::client::read_bits(frame(codec_, FrameKind::E3), *scratch.bits,
                                                 static_cast<std::uint16_t>(std::min<std::uint32_t>(scratch.bit_count, 255))));
        auto response = served(o) ? protocol::client::parse_response(o.bytes) : std::nullopt;
        if (!response) throw ConnectionError("--allow-writes: the scratch bits cannot be read (" + reaction(o) + ")");
        auto r = response->reader();
        saved_bits = r.bits(std::min<std::uint32_t>(scratch.bit_count, 255), "scratch bits");
    }
    auto& limits = profile_["limits"];
    for (auto form : {DeviceForm::Q, DeviceForm::IQR}) {
        if (form == DeviceForm::IQR && !iqr_) continue;
        // 1402 words weigh 12 each: N words up to the scratch range.
        auto weight = bisect(std::min<std::uint32_t>(255, scratch.word_count), [&, form](std::uint32_t n) {
            return protocol::client::build_request(frame(codec_, FrameKind::E3), 0x1402, sub(form, false), [&](FieldWriter& w) {
                w.u8(static_cast<std::uint8_t>(n));
                w.u8(0);
                for (std::uint32_t i = 0; i < n; ++i) {
                    w.device(form, {scratch.words->spec, scratch.words->number + i});
                    w.u16(saved[i]);
                }
            });
        });
        const char* key = form == DeviceForm::Q ? "q" : "iqr";
        auto bounded = [&](const std::optional<Limit>& found, const std::string& name) {
            if (found && !found->over)
                fact(name, "base's", "every count the scratch range holds (" + std::to_string(found->max) +
                                         ") is served: give a larger range", false);
            return found && found->over;
        };
        if (bounded(weight, std::string("limits.random_write_weight.") + key)) {
            limits["random_write_weight"][key] = weight->max * 12;
            if (weight->over && weight->over->end_code) limits["random_write_weight"]["end_code"] = hex4(weight->over->end_code);
            fact(std::string("limits.random_write_weight.") + key, std::to_string(weight->max) + " words = weight " +
                 std::to_string(weight->max * 12), "1402 of N scratch words (" + std::to_string(weight->requests) + " requests)");
        }
        if (!iqr_) limits["random_write_weight"]["iqr"] = 0;
        if (scratch.bits) {
            auto bit_limit = bisect(static_cast<std::uint32_t>(saved_bits.size()), [&, form](std::uint32_t n) {
                return protocol::client::build_request(frame(codec_, FrameKind::E3), 0x1402, sub(form, true), [&](FieldWriter& w) {
                    w.u8(static_cast<std::uint8_t>(n));
                    for (std::uint32_t i = 0; i < n; ++i) {
                        w.device(form, {scratch.bits->spec, scratch.bits->number + i});
                        if (form == DeviceForm::Q) w.u8(saved_bits[i]);
                        else w.u16(saved_bits[i]);
                    }
                });
            });
            if (bounded(bit_limit, std::string("limits.random_write_bits.") + key)) {
                limits["random_write_bits"][key] = bit_limit->max;
                if (bit_limit->over && bit_limit->over->end_code)
                    limits["random_write_bits"]["end_code"] = hex4(bit_limit->over->end_code);
                fact(std::string("limits.random_write_bits.") + key, std::to_string(bit_limit->max),
                     "1402/0001 of N scratch bits (" + std::to_string(bit_limit->requests) + " requests)");
            }
            if (!iqr_) limits["random_write_bits"]["iqr"] = 0;
        }
    }
    if (!scratch.bits) fact("limits.random_write_bits", "base's", "needs a bit range in --allow-writes", false);
    // 1406 with a word block and a bit block, both in the scratch ranges.
    if (scratch.bits && scratch.bit_count >= 16) {
        auto o = ask_in(codec_, FrameKind::E3, 0x1406, 0x0000, [&](FieldWriter& w) {
            w.u8(1);
            w.u8(1);
            w.device(DeviceForm::Q, *scratch.words);
            w.u16(1);
            w.u16(saved[0]);
            w.device(DeviceForm::Q, *scratch.bits);
            w.u16(1);
            std::uint16_t packed = 0;
            for (std::size_t i = 0; i < 16 && i < saved_bits.size(); ++i) packed |= static_cast<std::uint16_t>(saved_bits[i] << i);
            w.u16(packed);
        });
        profile_["mixed_block_write"] = served(o) ? "answer" : reaction(o);
        fact("mixed_block_write", profile_["mixed_block_write"], "1406 of one scratch word block and one scratch bit block");
    } else {
        fact("mixed_block_write", "base's", "needs a bit range of 16 or more in --allow-writes", false);
    }
    fact("read_only_devices", "base's", "a write outside the scratch ranges is never sent (S is the usual one)", false);
    fact("end_codes.not_accessible", "base's", "found only by writing a read-only area, which the probe never does", false);
    // Restore the scratch words and bits.
    for (std::uint32_t done = 0; done < saved.size();) {
        auto n = std::min<std::uint32_t>(static_cast<std::uint32_t>(saved.size()) - done, word_limit);
        std::span<const std::uint16_t> values(saved.data() + done, n);
        ask(protocol::client::write_words(frame(codec_, FrameKind::E3), {scratch.words->spec, scratch.words->number + done}, values));
        done += n;
    }
    if (scratch.bits)
        ask(protocol::client::write_bits(frame(codec_, FrameKind::E3), *scratch.bits, saved_bits));
}

}  // namespace slmp::cli
