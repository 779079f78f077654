#include "protocol/differential.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>

#include "devicemodel/hex.hpp"
#include "protocol/client_commands.hpp"
#include "protocol/client_files.hpp"
#include "protocol/client_labels.hpp"

namespace slmp::protocol::differential {

using client::FrameOptions;
using devicemodel::Area;
using devicemodel::DeviceAddress;
using devicemodel::find_by_symbol;
using Bytes = std::vector<std::uint8_t>;

namespace {

DeviceAddress at(std::string_view symbol, std::uint32_t number) { return {find_by_symbol(symbol), number}; }

std::uint16_t sub(DeviceForm form, bool bits, bool extended = false) {
    return static_cast<std::uint16_t>((extended ? 0x80 : 0) + (form == DeviceForm::IQR ? 2 : 0) + (bits ? 1 : 0));
}

// A device code the device table does not know (Q form 0x77, iQ-R form 0x0077):
// the "bad device" of every generated family. Written raw: FieldWriter only
// writes devices it knows.
void unknown_device(FieldWriter& w, Codec codec, DeviceForm form) {
    if (codec == Codec::Binary) {
        if (form == DeviceForm::Q) {
            w.u16(0);
            w.u8(0);
            w.u8(0x77);
        } else {
            w.u32(0);
            w.u16(0x0077);
        }
        return;
    }
    std::string text = form == DeviceForm::Q ? "QQ000000" : "QQQQ0000000000";
    w.raw(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

// A first device of each kind for the list-shaped commands (0403, 0801, 0406).
std::vector<DeviceAddress> words_from(std::string_view symbol, std::uint32_t first, std::uint32_t count) {
    std::vector<DeviceAddress> list;
    for (std::uint32_t i = 0; i < count; ++i) list.push_back(at(symbol, first + i));
    return list;
}

class Generator {
public:
    Generator(const PortProfile& port, const devicemodel::CpuProfile& cpu, FrameOptions frame)
        : port_(port), cpu_(cpu), frame_(frame) {}

    std::vector<Sample> run() {
        add("0101 Read Type Name", 0x0101, 0x0000, {});
        for (auto form : {DeviceForm::Q, DeviceForm::IQR}) {
            batch(form);
            random(form);
            blocks(form);
            monitor(form);
        }
        extended();
        every_row();
        files();
        others();
        remote();
        return std::move(samples_);
    }

private:
    bool form_exists(DeviceForm form, const devicemodel::DeviceSpec& spec) const {
        return form == DeviceForm::IQR || spec.q_code >= 0;
    }
    std::uint32_t size(Area area) const { return cpu_.size(area); }
    std::uint32_t form_limit(const FormLimit& limit, DeviceForm form) const {
        return form == DeviceForm::Q ? limit.q : limit.iqr;
    }
    std::string prefix(std::uint16_t command, std::uint16_t subcommand) const {
        return devicemodel::hex4(command) + "/" + devicemodel::hex4(subcommand) + " ";
    }

    void add(std::string label, std::uint16_t command, std::uint16_t subcommand,
             const std::function<void(FieldWriter&)>& body) {
        samples_.push_back({prefix(command, subcommand) + label, client::build_request(frame_, command, subcommand, body)});
        if (frame_.kind == FrameKind::E4) ++frame_.serial;
    }

    // Word (or bit) reads of `points` at `start`, and the same written back as zeros.
    void read(DeviceForm form, bool bits, const DeviceAddress& start, std::uint32_t points, const std::string& why) {
        add(std::string(start.spec->symbol) + std::to_string(start.number) + " x" + std::to_string(points) + " " + why,
            0x0401, sub(form, bits), [&](FieldWriter& w) {
                w.device(form, start);
                w.u16(static_cast<std::uint16_t>(points));
            });
    }
    void write(DeviceForm form, bool bits, const DeviceAddress& start, std::uint32_t points, const std::string& why) {
        add(std::string(start.spec->symbol) + std::to_string(start.number) + " x" + std::to_string(points) + " " + why,
            0x1401, sub(form, bits), [&](FieldWriter& w) {
                w.device(form, start);
                w.u16(static_cast<std::uint16_t>(points));
                if (bits) {
                    std::vector<std::uint8_t> values(points);
                    for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<std::uint8_t>(i % 3 == 0);
                    w.bits(values);
                } else {
                    std::vector<std::uint16_t> values(points);
                    for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<std::uint16_t>(0x1200 + i);
                    w.words(values);
                }
            });
    }

    void batch(DeviceForm form) {
        const auto& bit_limit = frame_.codec == Codec::Binary ? port_.batch_bits_binary : port_.batch_bits_ascii;
        read(form, false, at("D", 0), port_.batch_words.max, "(word limit)");
        read(form, false, at("D", 0), port_.batch_words.max + 1, "(word limit +1)");
        read(form, false, at("D", 0), 0, "(no points)");
        read(form, true, at("M", 0), bit_limit.max, "(bit limit)");
        read(form, true, at("M", 0), bit_limit.max + 1, "(bit limit +1)");
        read(form, true, at("D", 0), 1, "(bit units of a word device)");
        write(form, false, at("D", 100), 3, "(write)");
        read(form, false, at("D", 100), 3, "(read back)");
        write(form, true, at("M", 100), 5, "(write bits)");
        read(form, true, at("M", 100), 5, "(read back bits)");
        write(form, false, at("D", 0), port_.batch_words.max + 1, "(word write limit +1)");
        write(form, true, at("M", 0), bit_limit.max + 1, "(bit write limit +1)");
        write(form, false, at("S", 0), 1, "(S: read-only over Ethernet?)");
        add("unknown device code", 0x0401, sub(form, false), [&](FieldWriter& w) {
            unknown_device(w, frame_.codec, form);
            w.u16(1);
        });
        // The edges of every area: the last point, the first past it, a span over the end.
        for (const auto& spec : devicemodel::all_devices()) {
            if (spec.extension_only || !form_exists(form, spec)) continue;
            if (spec.symbol == "DX" || spec.symbol == "DY") continue;
            const auto n = size(spec.area);
            const bool bits = spec.unit == devicemodel::Unit::Bit;
            const bool volatile_area = spec.area == Area::SM || spec.area == Area::SD;
            if (n == 0) {
                read(form, bits, {&spec, 0}, 1, "(area absent)");
                continue;
            }
            if (!volatile_area) {
                read(form, bits, {&spec, n - 1}, 1, "(last point)");
                read(form, bits, {&spec, n - 1}, 2, "(span past the end)");
            }
            read(form, bits, {&spec, n}, 1, "(first point past the end)");
        }
        for (const auto& reg : cpu_.size_registers)
            read(form, false, at("SD", reg.sd), reg.bits / 16, "(size register of " +
                                                                     std::string(devicemodel::area_name(reg.area)) + ")");
    }

    void random(DeviceForm form) {
        for (auto n : {form_limit(port_.random_read_points, form), form_limit(port_.random_read_points, form) + 1}) {
            if (n == 0 || n > 255) continue;
            auto words = words_from("D", 0, n);
            add("read random " + std::to_string(n) + " words", 0x0403, sub(form, false), [&](FieldWriter& w) {
                w.u8(static_cast<std::uint8_t>(n));
                w.u8(0);
                for (const auto& d : words) w.device(form, d);
            });
        }
        auto words = words_from("D", 100, 2);
        auto dwords = words_from("D", 200, 1);
        samples_.push_back({prefix(0x0403, sub(form, false)) + "read random D100 D101 + dword D200",
                            client::read_random(frame_, words, dwords, form)});
        if (frame_.kind == FrameKind::E4) ++frame_.serial;
        // 1402 words weigh 12 each (double words 14): the limit in words ±1.
        auto weight = form_limit(port_.random_write_weight, form);
        for (auto n : {weight / 12, weight / 12 + 1}) {
            if (n == 0 || n > 255) continue;
            add("write random " + std::to_string(n) + " words", 0x1402, sub(form, false), [&](FieldWriter& w) {
                w.u8(static_cast<std::uint8_t>(n));
                w.u8(0);
                for (std::uint32_t i = 0; i < n; ++i) {
                    w.device(form, at("D", 300 + i));
                    w.u16(static_cast<std::uint16_t>(i));
                }
            });
        }
        auto bits = form_limit(port_.random_write_bits, form);
        for (auto n : {bits, bits + 1}) {
            if (n == 0 || n > 255) continue;
            add("write random " + std::to_string(n) + " bits", 0x1402, sub(form, true), [&](FieldWriter& w) {
                w.u8(static_cast<std::uint8_t>(n));
                for (std::uint32_t i = 0; i < n; ++i) {
                    w.device(form, at("M", 300 + i));
                    if (form == DeviceForm::Q) w.u8(i % 2);
                    else w.u16(static_cast<std::uint16_t>(i % 2));
                }
            });
        }
    }

    void block(DeviceForm form, bool write_, std::uint32_t word_blocks, std::uint32_t bit_blocks, std::uint16_t points,
               const std::string& why) {
        add(std::string(write_ ? "write" : "read") + " block " + std::to_string(word_blocks) + "+" +
                std::to_string(bit_blocks) + " blocks x" + std::to_string(points) + " " + why,
            write_ ? 0x1406 : 0x0406, sub(form, false), [&](FieldWriter& w) {
                w.u8(static_cast<std::uint8_t>(word_blocks));
                w.u8(static_cast<std::uint8_t>(bit_blocks));
                for (std::uint32_t i = 0; i < word_blocks + bit_blocks; ++i) {
                    bool bit = i >= word_blocks;
                    w.device(form, bit ? at("M", 16 * i) : at("D", 10 * i));
                    w.u16(points);
                    if (write_) w.words(std::vector<std::uint16_t>(points, static_cast<std::uint16_t>(0x0F0F)));
                }
            });
    }

    void blocks(DeviceForm form) {
        auto count = form_limit(port_.block_count, form);
        if (count > 0 && count < 255) {
            block(form, false, count, 0, 1, "(block limit)");
            block(form, false, count + 1, 0, 1, "(block limit +1)");
        }
        auto points = port_.block_points.max;
        block(form, false, 1, 0, static_cast<std::uint16_t>(points), "(point limit)");
        block(form, false, 1, 0, static_cast<std::uint16_t>(points + 1), "(point limit +1)");
        block(form, false, 2, 1, 4, "(words and bits)");
        block(form, true, 1, 1, 2, "(mixed words and bits)");
        block(form, true, 2, 0, 3, "(words)");
        block(form, false, 0, 0, 1, "(no blocks)");
    }

    void monitor(DeviceForm form) {
        auto limit = form_limit(port_.monitor_points, form);
        for (auto n : {limit, limit + 1, std::uint32_t{3}}) {
            if (n == 0 || n > 255) continue;
            auto words = words_from("D", 0, n);
            add("entry monitor " + std::to_string(n) + " words", 0x0801, sub(form, false), [&](FieldWriter& w) {
                w.u8(static_cast<std::uint8_t>(n));
                w.u8(0);
                for (const auto& d : words) w.device(form, d);
            });
        }
        add("execute monitor", 0x0802, 0x0000, {});
    }

    // 008x: the extended device form, plain and through the CPU buffer (U3E0\G).
    void extended() {
        for (auto form : {DeviceForm::Q, DeviceForm::IQR}) {
            add("D100 x3 (extended, plain)", 0x0401, sub(form, false, true), [&](FieldWriter& w) {
                w.extended_device(form, at("D", 100));
                w.u16(3);
            });
            DeviceExtension buffer;
            buffer.kind = DeviceExtension::Kind::CpuBuffer;
            buffer.target = 0x03E0;
            add("U3E0\\G0 x4 (CPU buffer memory)", 0x0401, sub(form, false, true), [&](FieldWriter& w) {
                w.extended_device(form, at("G", 0), buffer);
                w.u16(4);
            });
            auto half = form_limit(port_.random_read_points, form) / 2;   // each point counts twice
            for (auto n : {half, half + 1}) {
                if (n == 0 || n > 255) continue;
                add("read random " + std::to_string(n) + " words (extended: points count twice)", 0x0403,
                    sub(form, false, true), [&](FieldWriter& w) {
                        w.u8(static_cast<std::uint8_t>(n));
                        w.u8(0);
                        for (std::uint32_t i = 0; i < n; ++i) w.extended_device(form, at("D", i));
                    });
            }
        }
    }

    // Every row of the command table in its smallest form (sample_request), so
    // that a subcommand no other part names is still compared.
    void every_row() {
        for (const auto& row : all_commands()) {
            auto bytes = sample_request(row, frame_, at("D", 500), at("M", 500));
            if (!bytes) continue;
            built(row.command, row.subcommand, std::string(row.name) + ", smallest request", std::move(*bytes));
        }
        add("extend unit write 2 bytes to module 03E0", 0x1601, 0x0000, [](FieldWriter& w) {
            w.u32(0);
            w.u16(2);
            w.u16(0x03E0);
            w.u8(0x12);
            w.u8(0x34);
        });
        std::vector<client::LabelWrite> labels{{"NoSuchLabel", {devicemodel::BasicType::Word, {1}}}};
        built(0x141B, 0, "label write random of an undeclared label", client::label_write_random(frame_, labels));
        std::vector<client::ArrayWrite> arrays{{"NoSuchArray[0]", devicemodel::BasicType::Word, {{1}}}};
        built(0x141A, 0, "array label write of an undeclared label", client::array_label_write(frame_, arrays));
        add("lock with a 1-character password", 0x1631, 0x0000, [](FieldWriter& w) {
            w.u16(1);
            w.raw(std::vector<std::uint8_t>{'x'});
        });
    }

    // The file commands that change something, each in the Q/L (0000) and iQ-R
    // (0040) form: a file made and deleted, and the others on a file that does
    // not exist or a pointer never opened.
    void files() {
        for (bool iqr : {false, true}) {
            const std::uint16_t s = iqr ? 0x40 : 0;
            client::FileTarget made{iqr, 4, "DIFF.TMP", ""}, missing{iqr, 4, "NOFILE.CSV", ""};
            built(0x1820, s, "new file", client::file_new(frame_, made, 64));
            built(0x1824, s, "copy a file that does not exist", client::file_copy(frame_, made, missing));
            built(0x1825, s, "state of a file that does not exist", client::file_state(frame_, missing, 0x0001));
            built(0x1826, s, "date of a file that does not exist", client::file_date(frame_, missing, 0x5821, 0x0000));
            built(0x1822, s, "delete the new file", client::file_delete(frame_, made));
        }
        // 0004, the L CPUs' 32-character-password form (a QnU refuses it).
        client::FileTarget l_form{false, 4, "NOFILE.CSV", "", true};
        built(0x1822, 4, "delete a file that does not exist", client::file_delete(frame_, l_form));
        built(0x1824, 4, "copy a file that does not exist", client::file_copy(frame_, l_form, l_form));
        built(0x1825, 4, "state of a file that does not exist", client::file_state(frame_, l_form, 0x0001));
        built(0x1828, 0, "read through a pointer never opened", client::file_read(frame_, 7, 0, 4));
        std::vector<std::uint8_t> data{1, 2};
        built(0x1829, 0, "write through a pointer never opened", client::file_write(frame_, 7, 0, data));
        built(0x182A, 0, "close a pointer never opened", client::file_close(frame_, 7, 0));
    }

    void others() {
        for (auto bytes : {std::uint32_t{1}, port_.loopback_max_bytes, port_.loopback_max_bytes + 1}) {
            add("loopback " + std::to_string(bytes) + " bytes", 0x0619, 0x0000, [&](FieldWriter& w) {
                w.u16(static_cast<std::uint16_t>(bytes));
                w.raw(std::vector<std::uint8_t>(bytes, '5'));
            });
        }
        add("loopback 0 bytes", 0x0619, 0x0000, [](FieldWriter& w) { w.u16(0); });
        add("memory read 4 words at 0", 0x0613, 0x0000, [](FieldWriter& w) {
            w.u32(0);
            w.u16(4);
        });
        add("memory write 2 words at 0x10", 0x1613, 0x0000, [](FieldWriter& w) {
            w.u32(0x10);
            w.u16(2);
            w.u16(0x1234);
            w.u16(0x5678);
        });
        add("extend unit read 8 bytes of module 03E0", 0x0601, 0x0000, [](FieldWriter& w) {
            w.u32(0);
            w.u16(8);
            w.u16(0x03E0);
        });
        std::vector<std::string> names{"NoSuchLabel"};
        built(0x041C, 0, "label read random of an undeclared label", client::label_read_random(frame_, names));
        std::vector<client::ArrayRead> arrays{{"NoSuchArray[0]", false, 2}};
        built(0x041A, 0, "array label read of an undeclared label", client::array_label_read(frame_, arrays));
        for (bool iqr : {false, true}) {
            for (std::uint16_t drive = 0; drive <= 4; ++drive) {
                samples_.push_back({prefix(0x1810, iqr ? 0x40 : 0) + "list drive " + std::to_string(drive),
                                    client::file_list(frame_, iqr, drive, 1, 4)});
                if (frame_.kind == FrameKind::E4) ++frame_.serial;
            }
            client::FileTarget missing{iqr, 4, "NOFILE.CSV", ""};
            samples_.push_back({prefix(0x1827, iqr ? 0x40 : 0) + "open a file that does not exist",
                                client::file_open(frame_, missing, false)});
            if (frame_.kind == FrameKind::E4) ++frame_.serial;
        }
        add("unlock with a 1-character password", 0x1630, 0x0000, [](FieldWriter& w) {
            w.u16(1);
            w.raw(std::vector<std::uint8_t>{'x'});
        });
        add("clear error", 0x1617, 0x0000, {});
        add("unknown command", 0x1234, 0x0000, {});
        add("unknown subcommand", 0x0401, 0x0009, [](FieldWriter& w) { w.u16(0); });
        add("word read with a field missing", 0x0401, 0x0000, [](FieldWriter& w) { w.u16(0); });
    }

    void built(std::uint16_t command, std::uint16_t subcommand, std::string label, Bytes bytes) {
        samples_.push_back({prefix(command, subcommand) + std::move(label), std::move(bytes)});
        if (frame_.kind == FrameKind::E4) ++frame_.serial;
    }

    void remote() {
        built(0x1002, 0, "remote STOP", client::remote_stop(frame_));
        built(0x1005, 0, "remote latch clear", client::remote_latch_clear(frame_));
        write(DeviceForm::Q, false, at("D", 100), 2, "(write in STOP)");
        built(0x1003, 0, "remote PAUSE", client::remote_pause(frame_, client::RemoteMode::Normal));
        built(0x1001, 0, "remote RUN", client::remote_run(frame_, client::RemoteMode::Force, client::ClearMode::None));
    }

    const PortProfile& port_;
    const devicemodel::CpuProfile& cpu_;
    FrameOptions frame_;
    std::vector<Sample> samples_;
};

}  // namespace

std::vector<Sample> generate(const PortProfile& port, const devicemodel::CpuProfile& cpu, const FrameOptions& frame) {
    return Generator(port, cpu, frame).run();
}

std::optional<Bytes> sample_request(const CommandSpec& row, const FrameOptions& frame, const DeviceAddress& scratch,
                                    const DeviceAddress& scratch_bits) {
    const auto form = row.form;
    const bool extended = row.subcommand & 0x80;
    const bool bits = row.access == Access::Bits;
    auto device = [&](FieldWriter& w, const DeviceAddress& d) {
        if (extended) w.extended_device(form, d);
        else w.device(form, d);
    };
    auto build = [&](const std::function<void(FieldWriter&)>& body) {
        return client::build_request(frame, row.command, row.subcommand, body);
    };
    switch (row.command) {
        case 0x0101: return build({});
        case 0x0401: return build([&](FieldWriter& w) { device(w, bits ? at("M", 0) : at("D", 0)), w.u16(1); });
        case 0x0403:
            return build([&](FieldWriter& w) {
                w.u8(1);
                w.u8(0);
                device(w, at("D", 0));
            });
        case 0x0406:
            return build([&](FieldWriter& w) {
                w.u8(1);
                w.u8(0);
                device(w, at("D", 0));
                w.u16(1);
            });
        case 0x041A: {
            std::vector<client::ArrayRead> arrays{{"ProbeNoSuchLabel[0]", false, 2}};
            return client::array_label_read(frame, arrays);
        }
        case 0x041C: {
            std::vector<std::string> names{"ProbeNoSuchLabel"};
            return client::label_read_random(frame, names);
        }
        case 0x0601:
            return build([](FieldWriter& w) {
                w.u32(0);
                w.u16(2);
                w.u16(0x03E0);
            });
        case 0x0613:
            return build([](FieldWriter& w) {
                w.u32(0);
                w.u16(1);
            });
        case 0x0619:
            return build([](FieldWriter& w) {
                w.u16(1);
                w.raw(std::vector<std::uint8_t>{'5'});
            });
        case 0x0801:
            return build([&](FieldWriter& w) {
                w.u8(1);
                w.u8(0);
                device(w, at("D", 0));
            });
        case 0x0802: return build({});
        case 0x1401:
            return build([&](FieldWriter& w) {
                device(w, bits ? scratch_bits : scratch);
                w.u16(1);
                if (bits) w.bits(std::vector<std::uint8_t>{0});
                else w.u16(0);
            });
        case 0x1402:
            return build([&](FieldWriter& w) {
                w.u8(1);
                if (!bits) w.u8(0);
                device(w, bits ? scratch_bits : scratch);
                if (!bits) w.u16(0);
                else if (form == DeviceForm::Q) w.u8(0);
                else w.u16(0);
            });
        case 0x1406:
            return build([&](FieldWriter& w) {
                w.u8(1);
                w.u8(0);
                device(w, scratch);
                w.u16(1);
                w.u16(0);
            });
        case 0x1810: return client::file_list(frame, row.subcommand == 0x40, 4, 1, 1);
        case 0x1811:
        case 0x1827: {
            client::FileTarget missing{row.subcommand == 0x40, 4, "PROBE.NOF", "", row.subcommand == 0x0004};
            return row.command == 0x1811 ? client::file_search(frame, missing) : client::file_open(frame, missing, false);
        }
        // The node commands (JA §3.12-3.14) in forms that change nothing: IP
        // Address Set names MAC 00:00:00:00:00:00 (no device's), Parameter
        // Set/End/Cancel come without a Start (CF31). Parameter Set Start is
        // left out: it would lock the node against every other request for 10 s.
        case 0x0E30:
            return build([](FieldWriter& w) {
                w.octets(std::vector<std::uint8_t>(6));
                w.u8(4);
                w.octets(std::vector<std::uint8_t>(4));
            });
        case 0x0E31:
            return build([](FieldWriter& w) {
                w.octets(std::vector<std::uint8_t>(6));   // client MAC, IP
                w.u8(4);
                w.octets(std::vector<std::uint8_t>(4));
                w.octets(std::vector<std::uint8_t>(6));   // server MAC
                w.u8(4);
                for (int i = 0; i < 3; ++i) w.octets(std::vector<std::uint8_t>(4));   // IP, mask, gateway
                w.u8(0);                                                              // no host name
                w.u8(4);
                w.octets(std::vector<std::uint8_t>(4));   // partner IP, port, protocol
                w.u16(0);
                w.u8(0);
            });
        case 0x0E32:
            return build([](FieldWriter& w) {
                w.u16(0x0001);
                w.u16(0x0000);
            });
        case 0x0E33:
            return build([](FieldWriter& w) {
                w.u16(1);
                w.u16(0x0001);
            });
        case 0x0E34:
            return build([](FieldWriter& w) {
                w.u16(1);
                w.u16(0x0001);
                w.u16(2);
                w.u16(0);
            });
        case 0x0E45: return build([](FieldWriter& w) { w.u16(0x0001); });
        case 0x0E36:
        case 0x0E3A:
        case 0x0E44:
        case 0x0E53: return build({});
        default: return std::nullopt;   // remote operations, passwords, file changes, labels written, 0E35
    }
}

std::string describe(const Observed& observed) {
    switch (observed.kind) {
        case Observed::Kind::Silence: return "no answer";
        case Observed::Kind::Close: return "connection closed";
        case Observed::Kind::Answer: break;
    }
    return "end code " + devicemodel::hex4(observed.end_code) + ", " + std::to_string(observed.bytes.size()) + " bytes";
}

std::string_view kind_name(DifferenceKind kind) {
    switch (kind) {
        case DifferenceKind::Same: return "same";
        case DifferenceKind::Close: return "close";
        case DifferenceKind::Silence: return "silence";
        case DifferenceKind::EndCode: return "end_code";
        case DifferenceKind::Bytes: return "bytes";
        case DifferenceKind::Time: return "time";
    }
    return "same";
}

std::string_view kind_name(Observed::Kind kind) {
    switch (kind) {
        case Observed::Kind::Answer: return "answer";
        case Observed::Kind::Silence: return "silence";
        case Observed::Kind::Close: return "close";
    }
    return "answer";
}

bool times_far_apart(std::chrono::microseconds a, std::chrono::microseconds b, std::chrono::microseconds slack) {
    const auto shorter = std::min(a, b), longer = std::max(a, b);
    return longer > 2 * shorter + slack;
}

namespace {

std::string milliseconds(std::chrono::microseconds time) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f ms", static_cast<double>(time.count()) / 1000.0);
    return text;
}

}  // namespace

Difference classify(const Observed& a, const Observed& b, std::optional<std::chrono::microseconds> slack) {
    using Kind = Observed::Kind;
    Difference d;
    if (a.kind != b.kind) {
        d.kind = a.kind == Kind::Close || b.kind == Kind::Close ? DifferenceKind::Close : DifferenceKind::Silence;
        d.text = describe(a) + " vs " + describe(b);
        return d;
    }
    if (a.kind != Kind::Answer) return d;
    if (a.bytes != b.bytes) {
        auto mismatch = std::mismatch(a.bytes.begin(), a.bytes.end(), b.bytes.begin(), b.bytes.end());
        d.first_byte = static_cast<std::size_t>(mismatch.first - a.bytes.begin());
        if (a.end_code != b.end_code) {
            d.kind = DifferenceKind::EndCode;
            d.text = describe(a) + " vs " + describe(b);
        } else {
            d.kind = DifferenceKind::Bytes;
            d.text = "same end code " + devicemodel::hex4(a.end_code) + ", bytes differ from offset " +
                     std::to_string(*d.first_byte) + " (" + std::to_string(a.bytes.size()) + " vs " +
                     std::to_string(b.bytes.size()) + " bytes): " + devicemodel::bytes_to_hex(a.bytes) + " vs " +
                     devicemodel::bytes_to_hex(b.bytes);
        }
        return d;
    }
    if (slack && a.time && b.time && times_far_apart(*a.time, *b.time, *slack)) {
        d.kind = DifferenceKind::Time;
        d.text = "the same answer, in " + milliseconds(*a.time) + " vs " + milliseconds(*b.time) +
                 " (far apart: more than twice the shorter plus " + milliseconds(*slack) + ")";
    }
    return d;
}

std::optional<std::string> difference(const Observed& a, const Observed& b) {
    auto d = classify(a, b);
    if (d.same()) return std::nullopt;
    return d.text;
}

}  // namespace slmp::protocol::differential
