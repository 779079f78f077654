#include "control/endpoints/device_view.hpp"

#include "control/http/reply.hpp"

namespace slmp::control {

using devicemodel::DeviceAddress;
using devicemodel::DeviceSpec;
using devicemodel::Unit;
using nlohmann::json;

namespace {

std::string symbol(const DeviceSpec& spec) { return std::string(spec.symbol); }

void check_view(const DeviceSpec& spec, View view) {
    switch (view) {
        case View::Bits:
            if (spec.unit != Unit::Bit)
                bad(symbol(spec) + " is a " + (spec.unit == Unit::Word ? "word" : "32-bit") +
                    " device; use as=words, as=dwords" + (spec.unit == Unit::Word ? " or as=string" : ""));
            return;
        case View::Words:
            if (spec.unit == Unit::DoubleWord) bad(symbol(spec) + " holds 32-bit values; use as=dwords");
            return;
        case View::Dwords: return;
        case View::String:
            if (spec.unit != Unit::Word) bad("as=string needs a word device such as D, W or R; " + symbol(spec) + " is not one");
            return;
    }
}

std::uint64_t devices_spanned(const DeviceSpec& spec, View view, std::uint64_t count) {
    switch (view) {
        case View::Bits: return count;
        case View::Words: return spec.unit == Unit::Bit ? count * 16 : count;
        case View::Dwords:
            return spec.unit == Unit::Bit ? count * 32 : spec.unit == Unit::Word ? count * 2 : count;
        case View::String: return count;
    }
    return count;
}

// A number from JSON as the raw bits a device stores: negative values in two's complement.
std::uint32_t checked_value(const json& item, std::size_t index, View view) {
    auto where = "values[" + std::to_string(index) + "]: ";
    if (item.is_boolean()) {
        if (view != View::Bits) bad(where + "true/false is for bit devices; give a number");
        return item.get<bool>() ? 1 : 0;
    }
    if (!item.is_number_integer()) bad(where + item.dump() + " is not an integer; give whole numbers");
    auto wide = item.is_number_unsigned() ? static_cast<std::int64_t>(std::min<std::uint64_t>(item.get<std::uint64_t>(), 1ULL << 40))
                                          : item.get<std::int64_t>();
    switch (view) {
        case View::Bits:
            if (wide != 0 && wide != 1) bad(where + item.dump() + " is not a bit value; use 0, 1, true or false");
            break;
        case View::Words:
            if (wide < -32768 || wide > 65535) bad(where + item.dump() + " does not fit a 16-bit word; use -32768..65535");
            break;
        case View::Dwords:
            if (wide < -2147483648LL || wide > 4294967295LL)
                bad(where + item.dump() + " does not fit a 32-bit double word; use -2147483648..4294967295");
            break;
        case View::String: break;
    }
    return static_cast<std::uint32_t>(wide);
}

void append_utf8(std::string& out, unsigned code_point) {
    if (code_point < 0x80) {
        out += static_cast<char>(code_point);
    } else {
        out += static_cast<char>(0xC0 | (code_point >> 6));
        out += static_cast<char>(0x80 | (code_point & 0x3F));
    }
}

}  // namespace

std::optional<View> parse_view(std::string_view text) {
    if (text == "bits") return View::Bits;
    if (text == "words") return View::Words;
    if (text == "dwords") return View::Dwords;
    if (text == "string") return View::String;
    return std::nullopt;
}

std::string_view to_string(View view) {
    switch (view) {
        case View::Bits: return "bits";
        case View::Words: return "words";
        case View::Dwords: return "dwords";
        case View::String: return "string";
    }
    return "words";
}

View default_view(const DeviceSpec& spec) {
    if (spec.unit == Unit::Bit) return View::Bits;
    return spec.unit == Unit::Word ? View::Words : View::Dwords;
}

DeviceAddress parse_device(const std::string& text, devicemodel::Numbering numbering) {
    std::string error;
    auto address = devicemodel::parse_address(text, numbering, &error);
    if (!address) bad(error);
    if (address->spec->extension_only)
        bad(symbol(*address->spec) + " (" + std::string(address->spec->name) +
            ") is reached through a module, not as a plain device; read a CPU device such as D100 instead");
    return *address;
}

DeviceRun make_run(const devicemodel::Cpu& cpu, DeviceAddress start, View view, std::uint64_t count) {
    auto area = std::string(devicemodel::area_name(start.spec->area));
    return make_run(cpu.memory(), RunPlace{cpu.profile().name, "raise device_sizes." + area + " in the configuration", cpu.profile().numbering},
                    start, view, count);
}

DeviceRun make_run(const devicemodel::DeviceMemory& memory, const RunPlace& place, DeviceAddress start, View view,
                   std::uint64_t count) {
    const auto& spec = *start.spec;
    check_view(spec, view);
    if (count == 0 || count > kMaxValues)
        bad("count " + std::to_string(count) + " is out of range; use 1 to " + std::to_string(kMaxValues) +
            " (read larger spans in parts)");
    DeviceRun run{start, view, static_cast<std::uint32_t>(count), devices_spanned(spec, view, count), place.numbering};

    auto size = memory.size(spec.area);
    if (!memory.contains(spec.area, start.number, run.devices)) {
        if (size == 0) bad(symbol(spec) + " has no devices in " + place.name + " (size 0); " + place.enlarge);
        bad(devicemodel::format_address(start, place.numbering) + " with " + std::to_string(count) + " " +
            std::string(to_string(view)) + " runs past " +
            devicemodel::format_address(DeviceAddress{&spec, size - 1}, place.numbering) + ", the last " + symbol(spec) +
            " device of " + place.name + " (" + std::to_string(size) + " devices); lower the start or count, or " +
            place.enlarge);
    }
    return run;
}

json read_run(const devicemodel::DeviceMemory& memory, const DeviceRun& run) {
    const auto& spec = *run.start.spec;
    json out{{"device", devicemodel::format_address(run.start, run.numbering)}, {"as", to_string(run.view)}, {"count", run.count}};
    auto values = json::array();
    switch (run.view) {
        case View::Bits:
            for (std::uint32_t i = 0; i < run.count; ++i) values.push_back(memory.bit(spec, run.start.number + i) ? 1 : 0);
            break;
        case View::Words: {
            std::vector<std::uint16_t> words(run.count);
            memory.read_words(spec, run.start.number, words);
            for (auto w : words) values.push_back(w);
            break;
        }
        case View::Dwords:
            if (spec.unit == Unit::DoubleWord) {
                for (std::uint32_t i = 0; i < run.count; ++i) values.push_back(memory.value(spec, run.start.number + i));
            } else {
                std::vector<std::uint16_t> words(std::size_t{run.count} * 2);
                memory.read_words(spec, run.start.number, words);
                for (std::size_t i = 0; i < words.size(); i += 2) values.push_back(words[i] | std::uint32_t{words[i + 1]} << 16);
            }
            break;
        case View::String: {
            std::vector<std::uint16_t> words(run.count);
            memory.read_words(spec, run.start.number, words);
            out["string"] = unpack_string(words);
            return out;
        }
    }
    out["values"] = std::move(values);
    return out;
}

std::vector<std::uint32_t> parse_values(const json& values, View view) {
    if (view == View::String) bad("as=string takes {\"string\": \"...\"}, not \"values\"");
    if (!values.is_array()) bad("\"values\" must be a list of numbers, e.g. {\"values\": [1, 2, 3]}");
    if (values.empty()) bad("\"values\" is empty; give at least one value");
    if (values.size() > kMaxValues)
        bad(std::to_string(values.size()) + " values is over the limit of " + std::to_string(kMaxValues) + "; write in parts");
    std::vector<std::uint32_t> out;
    out.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out.push_back(checked_value(values[i], i, view));
    return out;
}

void write_run(devicemodel::DeviceMemory& memory, const DeviceRun& run, const std::vector<std::uint32_t>& values) {
    const auto& spec = *run.start.spec;
    switch (run.view) {
        case View::Bits:
            for (std::uint32_t i = 0; i < run.count; ++i) memory.set_bit(spec, run.start.number + i, values[i] != 0);
            return;
        case View::Words:
        case View::String: {
            std::vector<std::uint16_t> words(values.begin(), values.end());
            memory.write_words(spec, run.start.number, words);
            return;
        }
        case View::Dwords:
            if (spec.unit == Unit::DoubleWord) {
                for (std::uint32_t i = 0; i < run.count; ++i) memory.set_value(spec, run.start.number + i, values[i]);
                return;
            }
            std::vector<std::uint16_t> words;
            for (auto v : values) {
                words.push_back(static_cast<std::uint16_t>(v));
                words.push_back(static_cast<std::uint16_t>(v >> 16));
            }
            memory.write_words(spec, run.start.number, words);
            return;
    }
}

std::vector<std::uint16_t> pack_string(const std::string& utf8) {
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = 0; i < utf8.size();) {
        auto c = static_cast<unsigned char>(utf8[i]);
        unsigned code_point = c;
        std::size_t length = 1;
        if (c >= 0x80) {
            // nlohmann::json has already checked the UTF-8; only its length matters here.
            length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
            code_point = length == 2 && i + 1 < utf8.size() ? ((c & 0x1Fu) << 6) | (static_cast<unsigned char>(utf8[i + 1]) & 0x3Fu)
                                                             : 0x100;
        }
        if (code_point > 0xFF)
            bad("\"string\": character " + utf8.substr(i, length) + " at byte " + std::to_string(i) +
                " is not a single byte; strings are stored one byte a character (U+0000-U+00FF)");
        bytes.push_back(static_cast<std::uint8_t>(code_point));
        i += length;
    }
    bytes.push_back(0);   // the terminator
    std::vector<std::uint16_t> words;
    for (std::size_t i = 0; i < bytes.size(); i += 2)
        words.push_back(static_cast<std::uint16_t>(bytes[i] | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0)));
    return words;
}

std::string unpack_string(const std::vector<std::uint16_t>& words) {
    std::string out;
    for (auto w : words) {
        for (unsigned byte : {w & 0xFFu, unsigned{w} >> 8}) {
            if (byte == 0) return out;
            append_utf8(out, byte);
        }
    }
    return out;
}

}  // namespace slmp::control
