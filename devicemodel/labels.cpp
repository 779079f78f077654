#include "devicemodel/labels.hpp"
#include "devicemodel/device_parts.hpp"
#include "devicemodel/hex.hpp"

#include <algorithm>
#include <cctype>

namespace slmp::devicemodel {
namespace {

// The label area: 4 Mi words at most (chosen; an R120CPU has about 1.2 M words of label area).
constexpr std::uint64_t kMaxLabelAreaWords = 4u << 20;

bool is_bit(const LabelType& t) { return t.kind == LabelType::Kind::Basic && t.basic == BasicType::Bit; }

Area timer_area(TimerKind kind) {
    switch (kind) {
        case TimerKind::Timer: return Area::T;
        case TimerKind::RetentiveTimer: return Area::ST;
        case TimerKind::Counter: return Area::C;
        case TimerKind::LongTimer: return Area::LT;
        case TimerKind::LongRetentiveTimer: return Area::LST;
        case TimerKind::LongCounter: return Area::LC;
    }
    return Area::T;
}

// R is a window onto ZR: assignments to both must not overlap.
Area storage_of(Area a) { return a == Area::R ? Area::ZR : a; }

std::uint16_t store_word(const DeviceMemory& m, const DeviceSpec* spec, std::uint64_t word) {
    if (!spec) return m.label_word(static_cast<std::uint32_t>(word));
    return static_cast<std::uint16_t>(m.value(*spec, static_cast<std::uint32_t>(word)));
}
void set_store_word(DeviceMemory& m, const DeviceSpec* spec, std::uint64_t word, std::uint16_t value) {
    if (!spec) return m.set_label_word(static_cast<std::uint32_t>(word), value);
    if (store_word(m, spec, word) != value) m.set_value(*spec, static_cast<std::uint32_t>(word), value);
}

// ---- names as clients send them -------------------------------------------

struct Segment {
    std::string_view name;
    std::vector<std::uint32_t> index;
    bool indexed = false;
};

bool ident_char(char c) {
    auto u = static_cast<unsigned char>(c);
    return std::isalnum(u) || c == '_' || u >= 0x80;
}

// One element number: "20", "k20"/"K20" (decimal) or "h14"/"H14" (hex).
std::optional<std::uint32_t> index_number(std::string_view s) {
    unsigned base = 10;
    if (!s.empty() && (s[0] == 'k' || s[0] == 'K')) s.remove_prefix(1);
    else if (!s.empty() && (s[0] == 'h' || s[0] == 'H')) base = 16, s.remove_prefix(1);
    if (s.empty() || s.size() > 8) return std::nullopt;
    std::uint32_t v = 0;
    for (char c : s) {
        int d = hex_digit(static_cast<unsigned char>(c));
        if (d < 0 || unsigned(d) >= base) return std::nullopt;   // BBB[XXX]: a variable is not an element number
        v = v * base + d;
    }
    return v;
}

std::optional<std::vector<Segment>> segments(std::string_view text) {
    std::vector<Segment> out;
    std::size_t i = 0;
    while (true) {
        Segment seg;
        auto start = i;
        while (i < text.size() && ident_char(text[i])) ++i;
        seg.name = text.substr(start, i - start);
        // AAA.3 (a bit of a label) and an empty unit are not names.
        if (seg.name.empty() || std::isdigit(static_cast<unsigned char>(seg.name[0]))) return std::nullopt;
        if (i < text.size() && text[i] == '[') {
            seg.indexed = true;
            ++i;
            while (true) {
                auto from = i;
                while (i < text.size() && text[i] != ',' && text[i] != ']') ++i;
                if (i == text.size()) return std::nullopt;
                auto n = index_number(text.substr(from, i - from));
                if (!n) return std::nullopt;
                seg.index.push_back(*n);
                if (text[i++] == ']') break;
            }
            if (seg.index.size() > 3) return std::nullopt;
        }
        out.push_back(std::move(seg));
        if (i == text.size()) return out;
        if (text[i] != '.' || i + 1 == text.size()) return std::nullopt;
        ++i;
    }
}

// "%1.%2.memberB1" with {"LabelA", "memberA3"} -> "LabelA.memberA3.memberB1".
// An abbreviation is a whole "."-separated unit; "%1[2]" (an abbreviated
// array) is refused (§2.3).
std::optional<std::string> expand(std::string_view name, std::span<const std::string> abbreviations) {
    if (name.find('%') == std::string_view::npos) return std::string(name);
    std::string out;
    std::size_t i = 0;
    while (i <= name.size()) {
        auto dot = name.find('.', i);
        // A '.' inside brackets does not end a unit, but brackets hold only numbers.
        auto unit = name.substr(i, dot == std::string_view::npos ? std::string_view::npos : dot - i);
        if (!unit.empty() && unit[0] == '%') {
            auto digits = unit.substr(1);
            if (digits.empty() || digits.size() > 4 ||
                !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
                return std::nullopt;
            std::size_t n = 0;
            for (char c : digits) n = n * 10 + static_cast<std::size_t>(c - '0');
            if (n == 0 || n > abbreviations.size()) return std::nullopt;
            const auto& text = abbreviations[n - 1];
            if (text.empty() || text.find('%') != std::string::npos) return std::nullopt;
            out += text;
        } else {
            if (unit.find('%') != std::string_view::npos) return std::nullopt;
            out += unit;
        }
        if (dot == std::string_view::npos) break;
        out += '.';
        i = dot + 1;
    }
    return out;
}

// Where the walk stands while resolving a name.
struct Node {
    enum class Space : std::uint8_t { Store, BitDevice, TimerDevice } space = Space::Store;
    const DeviceSpec* spec = nullptr;   // Store: the word device (null: label area); BitDevice: it; TimerDevice: its value part
    std::uint64_t at = 0;               // Store: word offset (bit number when `bit`); devices: device number
    bool bit = false;
    LabelType type;
    std::vector<std::uint32_t> dims;
    unsigned array_dims = 0;
    std::uint32_t elements = 1;
};

LabelFault apply_index(Node& n, const Segment& seg) {
    if (n.dims.empty()) return seg.indexed ? LabelFault::BadName : LabelFault::None;
    if (!seg.indexed || seg.index.size() != n.dims.size()) return LabelFault::BadName;
    std::uint64_t flat = 0;
    for (std::size_t d = 0; d < n.dims.size(); ++d) {
        if (seg.index[d] >= n.dims[d]) return LabelFault::IndexOutOfRange;
        flat = flat * n.dims[d] + seg.index[d];
    }
    n.array_dims = static_cast<unsigned>(n.dims.size());
    n.elements = static_cast<std::uint32_t>(element_count(n.dims) - flat);
    if (n.space == Node::Space::Store && is_bit(n.type)) {
        n.at = n.at * 16 + flat;   // bit arrays pack 16 elements a word
        n.bit = true;
    } else if (n.space == Node::Space::Store) {
        n.at += flat * element_words(n.type);
    } else {
        n.at += flat;
    }
    n.dims.clear();
    return LabelFault::None;
}

}  // namespace

std::string_view describe(LabelFault fault) {
    switch (fault) {
        case LabelFault::None: return "";
        case LabelFault::NotFound: return "no global label or member of that name";
        case LabelFault::NotExternal: return "the label's \"Access from External Device\" is off";
        case LabelFault::BadName: return "the name is not a label name the CPU accepts (§2.3)";
        case LabelFault::IndexOutOfRange: return "an element index is past the end of the array";
        case LabelFault::NotALeaf: return "the name ends at a structure or timer, not at a member of basic type";
    }
    return "";
}

std::optional<std::string> check_label_name(std::string_view name) {
    if (name.empty()) return "the name is empty";
    if (name.size() > 255) return "the name is longer than 255 bytes";
    if (std::isdigit(static_cast<unsigned char>(name[0]))) return "a name cannot start with a digit";
    if (!std::all_of(name.begin(), name.end(), ident_char))
        return "a name may hold only letters, digits and '_' (no '.', '[', ',', '%' or spaces)";
    // GX Works3 refuses names that read as a device or a digit specification
    // ("D100", "X1F"); letters only ("BBB", as in the manual's examples) pass.
    if (std::any_of(name.begin(), name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }) &&
        parse_address(name)) return "'" + std::string(name) + "' is a device name";
    if ((name[0] == 'K' || name[0] == 'k') && name.size() > 1 && std::isdigit(static_cast<unsigned char>(name[1])))
        return "'" + std::string(name) + "' reads as a digit specification (K4M0)";
    return std::nullopt;
}

std::optional<LabelProblem> LabelTable::add_structure(StructType type) {
    if (auto why = check_label_name(type.name)) return LabelProblem{"bad structure name: " + *why, "rename it"};
    if (structure(type.name)) return LabelProblem{"structure '" + type.name + "' is declared twice", "remove one"};
    if (type.members.empty()) return LabelProblem{"structure '" + type.name + "' has no members", "add members"};
    std::uint64_t offset = 0;
    for (std::size_t i = 0; i < type.members.size(); ++i) {
        auto& m = type.members[i];
        if (auto why = check_label_name(m.name)) return LabelProblem{"bad member name: " + *why, "rename it"};
        for (std::size_t j = 0; j < i; ++j)
            if (type.members[j].name == m.name)
                return LabelProblem{"member '" + m.name + "' is declared twice", "rename one"};
        m.offset = static_cast<std::uint32_t>(offset);
        offset += storage_words(m.type, m.dims);
    }
    if (offset > kMaxLabelAreaWords)
        return LabelProblem{"structure '" + type.name + "' is too large", "use smaller arrays"};
    type.words = static_cast<std::uint32_t>(offset);
    structures_.push_back(std::move(type));
    return std::nullopt;
}

const StructType* LabelTable::structure(std::string_view name) const {
    for (const auto& s : structures_)
        if (s.name == name) return &s;
    return nullptr;
}

const Label* LabelTable::find(std::string_view name) const {
    auto it = by_name_.find(name);
    return it == by_name_.end() ? nullptr : &labels_[it->second];
}

std::optional<LabelProblem> LabelTable::add_label(LabelDecl decl, const DeviceMemory& memory) {
    if (auto why = check_label_name(decl.name)) return LabelProblem{"bad label name: " + *why, "rename the label"};
    if (find(decl.name)) return LabelProblem{"label '" + decl.name + "' is declared twice", "rename or remove one"};
    if (decl.dims.size() > 3) return LabelProblem{"an array has 1 to 3 dimensions", "use at most 3 dims"};
    for (auto d : decl.dims)
        if (d == 0 || d > 65536) return LabelProblem{"an array dimension must have 1 to 65536 elements", "fix dims"};
    Label label;
    static_cast<LabelDecl&>(label) = std::move(decl);
    label.words = storage_words(label.type, label.dims);
    if (std::uint64_t{element_count(label.dims)} * std::max<std::uint32_t>(element_words(label.type), 1) >
        kMaxLabelAreaWords)
        return LabelProblem{"label '" + label.name + "' is too large for the label area (4194304 words)",
                            "use a smaller array"};
    if (label.device) {
        const auto& spec = *label.device->spec;
        const auto n = label.device->number;
        const auto points = std::uint64_t{element_count(label.dims)};
        std::uint64_t count = 0;
        if (label.type.kind == LabelType::Kind::Timer) {
            auto area = timer_area(label.type.timer);
            if (spec.area != area)
                return LabelProblem{"a " + std::string(timer_kind_name(label.type.timer)) + " label needs a " +
                                        std::string(area_name(area)) + " device, not " + format_address(*label.device),
                                    "assign it to e.g. " + std::string(find_by_part(area, Part::Value)->symbol) + "0"};
            count = points;
        } else if (is_bit(label.type)) {
            if (spec.unit != Unit::Bit || spec.part != Part::Plain)
                return LabelProblem{"a Bit label needs a bit device, not " + format_address(*label.device),
                                    "assign it to a bit device such as M, X, Y, L or B"};
            count = points;
        } else {
            if (spec.unit != Unit::Word || spec.part != Part::Plain || spec.extension_only)
                return LabelProblem{"a " + format_label_type(label.type) + " label needs a word device, not " +
                                        format_address(*label.device),
                                    "assign it to a word device such as D, W, R or ZR"};
            if (label.type.kind == LabelType::Kind::Struct)
                for (const auto& m : label.type.structure->members)
                    if (m.type.kind != LabelType::Kind::Basic)
                        return LabelProblem{"structure '" + label.type.structure->name + "' has member '" + m.name +
                                                "' of a structure or timer type, and such a label cannot be "
                                                "assigned to a device (docs/labels.md, \"Assigned to a device\")",
                                            "remove \"device\" to place the label in the label area"};
            count = label.words;
        }
        if (!memory.contains(spec.area, n, count))
            return LabelProblem{"label '" + label.name + "' needs " + std::to_string(count) + " device(s) from " +
                                    format_address(*label.device) + ", past the " + std::string(area_name(spec.area)) +
                                    " size of " + std::to_string(memory.size(spec.area)),
                                "assign a lower device number or raise device_sizes"};
        for (const auto& other : labels_) {
            if (!other.device || storage_of(other.device->spec->area) != storage_of(spec.area)) continue;
            auto other_count = other.type.kind == LabelType::Kind::Timer || is_bit(other.type)
                                   ? std::uint64_t{element_count(other.dims)}
                                   : std::uint64_t{other.words};
            auto a0 = std::uint64_t{n}, a1 = a0 + count, b0 = std::uint64_t{other.device->number},
                 b1 = b0 + other_count;
            if (a0 < b1 && b0 < a1)
                return LabelProblem{"label '" + label.name + "' on " + format_address(*label.device) +
                                        " overlaps label '" + other.name + "' on " + format_address(*other.device),
                                    "assign devices that do not overlap"};
        }
    }
    by_name_.emplace(label.name, labels_.size());
    labels_.push_back(std::move(label));
    return std::nullopt;
}

std::optional<LabelProblem> LabelTable::allocate(DeviceMemory& memory) {
    std::uint64_t offset = 0;
    for (auto& label : labels_) {
        if (label.device) continue;
        label.area_offset = static_cast<std::uint32_t>(offset);
        offset += label.words;
        if (offset > kMaxLabelAreaWords)
            return LabelProblem{"the labels without a device need more than 4194304 words of label area",
                                "assign large labels to devices (e.g. ZR) or make them smaller"};
    }
    memory.resize_label_area(static_cast<std::uint32_t>(offset));
    return std::nullopt;
}

std::optional<LabelRef> LabelTable::resolve(std::string_view name, std::span<const std::string> abbreviations,
                                            LabelFault& fault, bool external_only) const {
    auto fail = [&](LabelFault f) -> std::optional<LabelRef> {
        fault = f;
        return std::nullopt;
    };
    auto text = expand(name, abbreviations);
    if (!text) return fail(LabelFault::BadName);
    auto segs = segments(*text);
    if (!segs) return fail(LabelFault::BadName);
    const auto* label = find((*segs)[0].name);
    if (!label) return fail(LabelFault::NotFound);
    if (external_only && !label->external) return fail(LabelFault::NotExternal);

    Node node;
    node.type = label->type;
    node.dims = label->dims;
    if (!label->device) {
        node.at = label->area_offset;
    } else if (label->type.kind == LabelType::Kind::Timer) {
        node.space = Node::Space::TimerDevice;
        node.spec = find_by_part(label->device->spec->area, Part::Value);
        node.at = label->device->number;
    } else if (is_bit(label->type)) {
        node.space = Node::Space::BitDevice;
        node.spec = label->device->spec;
        node.at = label->device->number;
    } else {
        node.spec = label->device->spec;
        node.at = label->device->number;
    }
    if (auto f = apply_index(node, (*segs)[0]); f != LabelFault::None) return fail(f);

    LabelRef ref;
    ref.label = label;
    for (std::size_t s = 1; s < segs->size(); ++s) {
        const auto& seg = (*segs)[s];
        if (node.type.kind == LabelType::Kind::Struct) {
            const Member* member = nullptr;
            for (const auto& m : node.type.structure->members)
                if (m.name == seg.name) member = &m;
            if (!member) return fail(LabelFault::NotFound);
            node.at += member->offset;
            node.type = member->type;
            node.dims = member->dims;
            node.array_dims = 0;
            node.elements = 1;
            if (auto f = apply_index(node, seg); f != LabelFault::None) return fail(f);
        } else if (node.type.kind == LabelType::Kind::Timer) {
            // T1.S / T1.C / T1.N end the name (§2.3).
            if (seg.indexed || s + 1 != segs->size()) return fail(LabelFault::BadName);
            const bool wide = is_long(node.type.timer);
            const auto area = node.space == Node::Space::TimerDevice ? node.spec->area : Area::Count;
            LabelCell cell;
            if (seg.name == "S" || seg.name == "C") {
                const bool coil = seg.name == "C";
                ref.basic = BasicType::Bit;
                if (node.space == Node::Space::TimerDevice)
                    cell = {LabelCell::Kind::Bit, find_by_part(area, coil ? Part::Coil : Part::Contact), node.at};
                else
                    cell = {LabelCell::Kind::BitInWord, node.spec, (node.at + (wide ? 2 : 1)) * 16 + (coil ? 1 : 0)};
            } else if (seg.name == "N") {
                ref.basic = wide ? BasicType::UDWord : BasicType::UWord;
                cell = node.space == Node::Space::TimerDevice ? LabelCell{LabelCell::Kind::Value, node.spec, node.at}
                                                              : LabelCell{LabelCell::Kind::Words, node.spec, node.at};
            } else {
                return fail(LabelFault::NotFound);
            }
            ref.timer_member = true;
            ref.first = cell;
            ref.array_dims = node.array_dims;
            ref.elements = node.elements;
            ref.stride = element_words(node.type);
            return ref;
        } else {
            return fail(LabelFault::BadName);   // AAA.x: a basic type has no members
        }
    }
    if (node.type.kind != LabelType::Kind::Basic) return fail(LabelFault::NotALeaf);
    if (!node.dims.empty()) return fail(LabelFault::BadName);   // an array needs its element numbers
    ref.basic = node.type.basic;
    ref.chars = node.type.chars;
    ref.array_dims = node.array_dims;
    ref.elements = node.elements;
    ref.stride = element_words(node.type);
    if (node.space == Node::Space::BitDevice) ref.first = {LabelCell::Kind::Bit, node.spec, node.at};
    else if (ref.basic == BasicType::Bit)
        ref.first = {LabelCell::Kind::BitInWord, node.spec, node.bit ? node.at : node.at * 16};
    else ref.first = {LabelCell::Kind::Words, node.spec, node.at};
    return ref;
}

LabelCell element_cell(const LabelRef& ref, std::uint32_t index) {
    auto cell = ref.first;
    // A timer array's elements are whole timers apart in the label area.
    cell.at += cell.kind == LabelCell::Kind::Words || (ref.timer_member && cell.kind == LabelCell::Kind::BitInWord)
                   ? std::uint64_t{index} * ref.stride * (cell.kind == LabelCell::Kind::BitInWord ? 16 : 1)
                   : index;
    return cell;
}

std::vector<std::uint16_t> read_element(const DeviceMemory& memory, const LabelRef& ref, std::uint32_t index) {
    auto cell = element_cell(ref, index);
    switch (cell.kind) {
        case LabelCell::Kind::Words: {
            std::vector<std::uint16_t> out(basic_words(ref.basic, ref.chars));
            for (std::size_t i = 0; i < out.size(); ++i) out[i] = store_word(memory, cell.spec, cell.at + i);
            return out;
        }
        case LabelCell::Kind::BitInWord:
            return {static_cast<std::uint16_t>((store_word(memory, cell.spec, cell.at / 16) >> (cell.at % 16)) & 1)};
        case LabelCell::Kind::Bit:
            return {static_cast<std::uint16_t>(memory.bit(*cell.spec, static_cast<std::uint32_t>(cell.at)) ? 1 : 0)};
        case LabelCell::Kind::Value: {
            auto v = memory.value(*cell.spec, static_cast<std::uint32_t>(cell.at));
            if (cell.spec->unit == Unit::DoubleWord) return {static_cast<std::uint16_t>(v), static_cast<std::uint16_t>(v >> 16)};
            return {static_cast<std::uint16_t>(v)};
        }
    }
    return {};
}

void write_element(DeviceMemory& memory, const LabelRef& ref, std::uint32_t index, std::span<const std::uint16_t> data) {
    auto cell = element_cell(ref, index);
    auto at = [&](std::size_t i) -> std::uint16_t { return i < data.size() ? data[i] : 0; };
    switch (cell.kind) {
        case LabelCell::Kind::Words:
            for (std::uint32_t i = 0; i < basic_words(ref.basic, ref.chars); ++i)
                set_store_word(memory, cell.spec, cell.at + i, at(i));
            return;
        case LabelCell::Kind::BitInWord: {
            auto word = store_word(memory, cell.spec, cell.at / 16);
            auto mask = static_cast<std::uint16_t>(1u << (cell.at % 16));
            set_store_word(memory, cell.spec, cell.at / 16,
                           static_cast<std::uint16_t>(at(0) & 1 ? word | mask : word & ~mask));
            return;
        }
        case LabelCell::Kind::Bit:
            memory.set_bit(*cell.spec, static_cast<std::uint32_t>(cell.at), at(0) & 1);
            return;
        case LabelCell::Kind::Value: {
            std::uint32_t v = at(0);
            if (cell.spec->unit == Unit::DoubleWord) v |= std::uint32_t{at(1)} << 16;
            memory.set_value(*cell.spec, static_cast<std::uint32_t>(cell.at), v);
            return;
        }
    }
}

}  // namespace slmp::devicemodel
