// Consistency property test (issue 3): for every device kind of an R08CPU —
// plain devices, the CPU buffer memory U3E0\G / U3E0\HG, a module's U3\G and a
// network's J1\X/Y/B/SB/W/SW — random values are written through one command
// and read back through every other, in both codes and every device form
// (Q/iQ-R, plain/extended):
//   writers: device memory itself, 1401 (words; bits), 1402 (words+dwords; bits),
//            1406, 1613 and 1601 where they reach;
//   readers: 0401 (words; bits), 0403, 0801+0802, 0406, 0613 and 0601 where they reach.
// A bit device's bit view (0401 bit units, 1402 bits) and word view (16 devices
// a word, the lowest in bit 0) must agree. A command that may not name a device
// must answer 4030 — and only for the devices the spec lists (§6.1–§6.8,
// corrected by real-CPU measurements: LZ is read and written by 0401/1401;
// S is read-only). The random generator is seeded: every run is the same run.
#include <algorithm>
#include <random>

#include "support/device_commands.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::Cpu;
using devicemodel::DeviceSpec;
using devicemodel::Unit;

namespace {

bool listed(const DeviceSpec& spec, std::initializer_list<std::string_view> symbols) {
    return std::find(symbols.begin(), symbols.end(), spec.symbol) != symbols.end();
}

// The devices each command may not name, written down from the spec.
enum class Op { Read, Write, RandomRead, RandomWrite, Monitor, BlockRead, BlockWrite };
bool forbidden(Op op, const DeviceSpec& spec, bool plain) {
    const bool read_only = plain && spec.symbol == "S";
    switch (op) {
        case Op::Read:
            return listed(spec, {"LTS", "LTC", "LSTS", "LSTC"});
        case Op::Write:
            return read_only || listed(spec, {"LTS", "LTC", "LTN", "LSTS", "LSTC", "LSTN"});
        case Op::RandomRead:
            return listed(spec, {"LTS", "LTC", "LSTS", "LSTC", "LCS", "LCC"});
        case Op::RandomWrite:
            return read_only;
        case Op::Monitor:
            return listed(spec, {"TS", "TC", "LTS", "LTC", "LTN", "STS", "STC", "LSTS", "LSTC", "LSTN", "CS", "CC",
                                 "LCS", "LCC", "LCN"});
        case Op::BlockRead:
        case Op::BlockWrite:
            return (op == Op::BlockWrite && read_only) ||
                   listed(spec, {"LTS", "LTC", "LTN", "LSTS", "LSTC", "LSTN", "LCS", "LCC", "LCN", "LZ"});
    }
    return false;
}

// One device kind: a symbol, and the memory it lives in.
struct Kind {
    const DeviceSpec* spec;
    Extension ext;                      // None: the CPU's own device
    devicemodel::DeviceMemory* memory;  // where the values live
    std::uint32_t size;                 // devices there
    std::uint32_t head = 0;             // 0601/1601 head address (module U3 only)
    int extend_unit_module = 0;         // 0601/1601 module number, 0 = not reachable that way
    bool station_buffer = false;        // 0613/1613 reach it

    bool plain() const { return ext.kind == Extension::None; }
    bool bits() const { return spec->unit == Unit::Bit; }
    bool longs() const { return spec->unit == Unit::DoubleWord; }
    std::uint32_t count() const { return bits() ? 32 : longs() ? 2 : 6; }
    std::string name() const {
        std::string prefix = ext.kind == Extension::J     ? "J1\\"
                             : ext.kind == Extension::U   ? "U3\\"
                             : ext.kind == Extension::U3E ? "U3E0\\"
                                                          : "";
        return prefix + std::string(spec->symbol);
    }
};

// The request forms that can name a kind: {form, extended}.
std::vector<std::pair<Form, bool>> forms_of(const Kind& k) {
    std::vector<std::pair<Form, bool>> forms;
    const bool q = k.spec->q_code >= 0;
    if (k.plain()) {
        if (q) forms.push_back({Form::Q, false});
        forms.push_back({Form::IQR, false});
    }
    if (q) forms.push_back({Form::Q, true});
    forms.push_back({Form::IQR, true});
    return forms;
}

class Check {
public:
    Check(Cpu& cpu, const Kind& kind, std::uint32_t seed)
        : engine_(cpu, port_of(cpu)), conn_{engine_}, kind_(kind), rng_(seed) {}

    // One round: new place and values, written by `writer` (or straight into
    // memory), then read back by every reader in every form and both codes.
    void round(const std::string& writer) {
        start_ = static_cast<std::uint32_t>(rng_() % (kind_.size - kind_.count() + 1));
        values_.assign(kind_.count(), 0);
        for (auto& v : values_)
            v = kind_.bits() ? rng_() & 1 : kind_.longs() ? static_cast<std::uint32_t>(rng_()) : rng_() & 0xFFFF;
        auto forms = forms_of(kind_);
        auto [form, ext] = forms[rng_() % forms.size()];
        const Wire& wire = rng_() & 1 ? kAscii3E : kBinary3E;
        INFO(kind_.name() << " at " << at(0) << " written by " << writer << " (" << wire.name() << ", "
                          << (form == Form::Q ? "Q" : "iQ-R") << (ext ? " extended" : "") << ")");
        if (!write(writer, wire, form, ext)) return;
        for (auto [rf, rext] : forms)
            for (const Wire* rw : {&kBinary3E, &kAscii3E}) read_all(*rw, rf, rext);
        read_by_address();
    }

private:
    std::string at(std::uint32_t offset) const { return devicemodel::format_address({kind_.spec, start_ + offset}); }
    Payload dev(Form f, bool ext, std::uint32_t offset) const { return field(f, ext, at(offset), kind_.ext); }

    // The word view: 16 devices a word for bit devices, the device for word
    // devices, words_per_device words (value low, high, 0, 0) for long ones.
    std::vector<std::uint16_t> word_view() const {
        std::vector<std::uint16_t> out;
        if (kind_.bits()) {
            for (std::size_t i = 0; i < values_.size(); i += 16) {
                std::uint16_t w = 0;
                for (unsigned b = 0; b < 16; ++b) w |= static_cast<std::uint16_t>(values_[i + b] << b);
                out.push_back(w);
            }
        } else if (kind_.longs()) {
            for (auto v : values_) {
                out.push_back(static_cast<std::uint16_t>(v));
                out.push_back(static_cast<std::uint16_t>(v >> 16));
                for (unsigned extra = 2; extra < devicemodel::words_per_device(*kind_.spec); ++extra) out.push_back(0);
            }
        } else {
            for (auto v : values_) out.push_back(static_cast<std::uint16_t>(v));
        }
        return out;
    }
    std::vector<int> bit_view() const { return std::vector<int>(values_.begin(), values_.end()); }
    std::uint32_t step() const { return kind_.bits() ? 16 : 1; }  // devices per random-access word point

    // 0403/0801 lists: word points on every word of the view, then dword points.
    std::pair<std::vector<Payload>, std::vector<Payload>> random_list(Form f, bool ext, Payload& answer) const {
        std::vector<Payload> words_list, dwords_list;
        auto view = word_view();
        if (kind_.longs()) {
            for (std::uint32_t i = 0; i < values_.size(); ++i) {
                words_list.push_back(dev(f, ext, i));
                answer = answer + word(static_cast<std::uint16_t>(values_[i]));
            }
            for (std::uint32_t i = 0; i < values_.size(); ++i) {
                dwords_list.push_back(dev(f, ext, i));
                answer = answer + dword(values_[i]);
            }
            return {words_list, dwords_list};
        }
        for (std::uint32_t j = 0; j < view.size(); ++j) {
            words_list.push_back(dev(f, ext, j * step()));
            answer = answer + word(view[j]);
        }
        dwords_list.push_back(dev(f, ext, 0));
        answer = answer + dword(view[0] | std::uint32_t{view[1]} << 16);
        return {words_list, dwords_list};
    }

    // Sends a request; true when served with `expected`. A refusal is only
    // acceptable as the spec's 4030 for a device the command may not name.
    bool served(const Wire& wire, Op op, std::uint16_t command, std::uint16_t sub, const Payload& request,
                const Payload& expected) {
        auto answer = conn_.exchange(wire, request);
        if (forbidden(op, *kind_.spec, kind_.plain())) {
            CHECK(answer == wire.expect(error(0x4030, command, sub)));
            return false;
        }
        CHECK(answer == wire.expect(ok(expected)));
        return answer == wire.expect(ok(expected));
    }

    bool write(const std::string& writer, const Wire& wire, Form f, bool ext) {
        const auto sub = device_sub(f, ext);
        const auto view = word_view();
        if (writer == "memory") {
            for (std::uint32_t i = 0; i < values_.size(); ++i) {
                if (kind_.bits())
                    kind_.memory->set_bit(*kind_.spec, start_ + i, values_[i] != 0);
                else
                    kind_.memory->set_value(*kind_.spec, start_ + i, values_[i]);
            }
            return true;
        }
        if (writer == "1401 words")
            return served(
                wire, Op::Write, 0x1401, sub,
                word(0x1401) + word(sub) + dev(f, ext, 0) + word(static_cast<std::uint16_t>(view.size())) + words(view),
                {});
        if (writer == "1401 bits") {
            if (!kind_.bits()) return false;
            const auto bsub = device_sub(f, ext, true);
            return served(wire, Op::Write, 0x1401, bsub,
                          word(0x1401) + word(bsub) + dev(f, ext, 0) +
                              word(static_cast<std::uint16_t>(values_.size())) + bits(bit_view()),
                          {});
        }
        if (writer == "1402 words") {
            std::vector<std::pair<Payload, std::uint16_t>> w;
            std::vector<std::pair<Payload, std::uint32_t>> dw;
            if (kind_.longs()) {
                for (std::uint32_t i = 0; i < values_.size(); ++i) dw.push_back({dev(f, ext, i), values_[i]});
            } else {
                // The first two words as one double word, the rest as words.
                dw.push_back({dev(f, ext, 0), view[0] | std::uint32_t{view[1]} << 16});
                for (std::uint32_t j = 2; j < view.size(); ++j) w.push_back({dev(f, ext, j * step()), view[j]});
            }
            return served(wire, Op::RandomWrite, 0x1402, sub, random_write_words_req(sub, w, dw), {});
        }
        if (writer == "1402 bits") {
            if (!kind_.bits()) return false;
            const auto bsub = device_sub(f, ext, true);
            std::vector<std::pair<Payload, bool>> points;
            for (std::uint32_t i = 0; i < values_.size(); ++i) points.push_back({dev(f, ext, i), values_[i] != 0});
            return served(wire, Op::RandomWrite, 0x1402, bsub, random_write_bits_req(bsub, points), {});
        }
        if (writer == "1406") {
            std::vector<Block> blocks = {{dev(f, ext, 0), view}};
            return served(wire, Op::BlockWrite, 0x1406, sub,
                          kind_.bits() ? block_write_req(sub, {}, blocks) : block_write_req(sub, blocks, {}), {});
        }
        if (writer == "1613") {
            if (!kind_.station_buffer) return false;
            return served(wire, Op::Write, 0x1613, 0, memory_write_req(start_, view), {});
        }
        if (writer == "1601") {
            if (!kind_.extend_unit_module) return false;
            std::vector<std::uint8_t> bytes;
            for (auto w : view)
                bytes.insert(bytes.end(), {static_cast<std::uint8_t>(w), static_cast<std::uint8_t>(w >> 8)});
            return served(wire, Op::Write, 0x1601, 0,
                          extend_unit_write_req(kind_.head + 2 * start_,
                                                static_cast<std::uint16_t>(kind_.extend_unit_module), bytes),
                          {});
        }
        FAIL("unknown writer " << writer);
        return false;
    }

    void read_all(const Wire& wire, Form f, bool ext) {
        INFO("read in " << wire.name() << ", " << (f == Form::Q ? "Q" : "iQ-R") << (ext ? " extended" : ""));
        const auto sub = device_sub(f, ext);
        const auto view = word_view();
        served(wire, Op::Read, 0x0401, sub,
               word(0x0401) + word(sub) + dev(f, ext, 0) + word(static_cast<std::uint16_t>(view.size())), words(view));
        if (kind_.bits()) {
            const auto bsub = device_sub(f, ext, true);
            served(wire, Op::Read, 0x0401, bsub,
                   word(0x0401) + word(bsub) + dev(f, ext, 0) + word(static_cast<std::uint16_t>(values_.size())),
                   bits(bit_view()));
        }
        Payload answer;
        auto [w, dw] = random_list(f, ext, answer);
        served(wire, Op::RandomRead, 0x0403, sub, random_read_req(sub, w, dw), answer);
        // 0801 answers no data; its 0802 answers as 0403 did.
        Connection monitor{engine_};
        auto entry = monitor.exchange(wire, monitor_entry_req(sub, w, dw));
        if (forbidden(Op::Monitor, *kind_.spec, kind_.plain())) {
            CHECK(entry == wire.expect(error(0x4030, 0x0801, sub)));
        } else {
            CHECK(entry == wire.expect(ok()));
            CHECK(monitor.exchange(wire, monitor_execute_req()) == wire.expect(ok(answer)));
        }
        auto block =
            std::vector<std::pair<Payload, std::uint16_t>>{{dev(f, ext, 0), static_cast<std::uint16_t>(view.size())}};
        served(wire, Op::BlockRead, 0x0406, sub,
               kind_.bits() ? block_read_req(sub, {}, block) : block_read_req(sub, block, {}), words(view));
    }

    // 0613 and 0601, which name no device.
    void read_by_address() {
        const auto view = word_view();
        for (const Wire* wire : {&kBinary3E, &kAscii3E}) {
            if (kind_.station_buffer)
                served(*wire, Op::Read, 0x0613, 0, memory_read_req(start_, static_cast<std::uint16_t>(view.size())),
                       words(view));
            if (kind_.extend_unit_module) {
                std::vector<std::uint8_t> bytes;
                for (auto w : view)
                    bytes.insert(bytes.end(), {static_cast<std::uint8_t>(w), static_cast<std::uint8_t>(w >> 8)});
                served(*wire, Op::Read, 0x0601, 0,
                       extend_unit_read_req(kind_.head + 2 * start_, static_cast<std::uint16_t>(2 * view.size()),
                                            static_cast<std::uint16_t>(kind_.extend_unit_module)),
                       memory_bytes(bytes));
            }
        }
    }

    protocol::Engine engine_;
    Connection conn_;
    Kind kind_;
    std::mt19937 rng_;
    std::uint32_t start_ = 0;
    std::vector<std::uint32_t> values_;
};

// Every kind on a fresh R08CPU with network 1 and a module at U3.
std::vector<Kind> kinds_of(Cpu& cpu) {
    std::vector<Kind> kinds;
    for (const auto& spec : devicemodel::all_devices()) {
        if (spec.extension_only || cpu.profile().size(spec.area) == 0) continue;
        kinds.push_back({&spec, {}, &cpu.memory(), cpu.profile().size(spec.area)});
    }
    kinds.push_back(
        {&spec_of("G"), cpu_buffer(), &cpu.memory(), cpu.profile().size(devicemodel::Area::G), 0, 0x03E0, true});
    kinds.push_back({&spec_of("HG"), cpu_buffer(), &cpu.memory(), cpu.profile().size(devicemodel::Area::HG)});
    auto* module = cpu.module(3);
    kinds.push_back({&spec_of("G"), module_access(3), &module->memory, 4096, 0x1008, 3});
    for (const char* symbol : {"X", "Y", "B", "SB", "W", "SW"})
        kinds.push_back({&spec_of(symbol), link_direct(1), cpu.network(1), cpu.network(1)->size(spec_of(symbol).area)});
    return kinds;
}

}  // namespace

TEST_CASE("Values written by any command read back identically through every other", "[consistency]") {
    auto probe = make_station(2048);
    const auto count = kinds_of(probe).size();
    for (std::size_t i = 0; i < count; ++i) {
        auto cpu = make_station(2048);
        auto kind = kinds_of(cpu)[i];
        Check check(cpu, kind, static_cast<std::uint32_t>(20240603 + i));
        for (const char* writer :
             {"memory", "1401 words", "1401 bits", "1402 words", "1402 bits", "1406", "1613", "1601"})
            check.round(writer);
    }
}

TEST_CASE("A long timer's 4-word view carries the coil (b0) and contact (b1) written by 1402", "[consistency]") {
    // LTS/LTC/LSTS/LSTC cannot be read directly (4030, real-CPU measurements): LTN's
    // status word is the only way to see them.
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kAscii3E);
    cpu.memory().set_value(spec_of("LTN"), 5, 0x00012345);
    CHECK(wire.exchange(cpu, random_write_bits_req(0x0003, {{device(Form::IQR, "LTC5"), true},
                                                            {device(Form::IQR, "LSTS2"), true}})) == wire.expect(ok()));
    CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LTN5", 4)) ==
          wire.expect(ok(words({0x2345, 0x0001, 0x0001, 0x0000}))));
    CHECK(wire.exchange(cpu, read_words_req(Form::IQR, "LSTN2", 4)) == wire.expect(ok(words({0, 0, 0x0002, 0}))));
    CHECK(wire.exchange(cpu, read_bits_req(Form::IQR, "LTC5", 1)) == wire.expect(error(0x4030, 0x0401, 0x0003)));
}
