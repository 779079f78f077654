// DeviceMemory: native values, the bit and word views of 0401/1401, timers and
// counters, long devices, R as a window onto ZR. No profile needed.
#include "devicemodel/device_memory.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <vector>

using namespace slmp::devicemodel;

namespace {

const DeviceSpec& dev(const char* symbol) { return *find_by_symbol(symbol); }

DeviceSizes small_sizes() {
    DeviceSizes s{};
    for (auto& n : s) n = 64;
    s[static_cast<std::size_t>(Area::R)] = 32;
    s[static_cast<std::size_t>(Area::ZR)] = 128;
    s[static_cast<std::size_t>(Area::LZ)] = 2;
    return s;
}

std::vector<std::uint16_t> read(const DeviceMemory& m, const char* symbol, std::uint32_t start, std::size_t n) {
    std::vector<std::uint16_t> out(n);
    m.read_words(dev(symbol), start, out);
    return out;
}

}  // namespace

TEST_CASE("bit devices: bit view and word view agree", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    for (const char* symbol : {"X", "Y", "M", "L", "F", "V", "B", "SB", "S", "SM", "DX", "DY"}) {
        INFO(symbol);
        const auto& spec = dev(symbol);
        SECTION(std::string(symbol) + ": bits -> words") {
            // M16..M47 as in the manual's word-unit example: bit 0 is the lowest device.
            for (std::uint32_t n : {16u, 17u, 19u, 31u, 32u, 47u}) m.set_bit(spec, n, true);
            CHECK(read(m, symbol, 16, 2) == std::vector<std::uint16_t>{0x800B, 0x8001});
            CHECK(read(m, symbol, 17, 1) == std::vector<std::uint16_t>{0xC005});   // starts mid-word: M17..M32
            CHECK(m.value(spec, 19) == 1);
            CHECK(m.value(spec, 18) == 0);
        }
        SECTION(std::string(symbol) + ": words -> bits") {
            std::array<std::uint16_t, 2> in{0x2347, 0xAB96};   // W2 of §6.2
            m.write_words(spec, 0, in);
            const char* expected = "1110001011000100" "0110100111010101";   // device 0 first
            for (std::uint32_t n = 0; n < 32; ++n) {
                INFO("device " << n);
                CHECK(m.bit(spec, n) == (expected[n] == '1'));
            }
            CHECK(read(m, symbol, 0, 2) == std::vector<std::uint16_t>{0x2347, 0xAB96});
            m.set_bit(spec, 0, false);
            CHECK(read(m, symbol, 0, 1) == std::vector<std::uint16_t>{0x2346});
        }
    }
}

TEST_CASE("DX/DY reach the same storage as X/Y", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    m.set_bit(dev("X"), 0x1F, true);
    CHECK(m.bit(dev("DX"), 0x1F));
    m.set_bit(dev("DY"), 3, true);
    CHECK(m.bit(dev("Y"), 3));
    CHECK_FALSE(m.bit(dev("X"), 3));
}

TEST_CASE("word devices hold 16 bits", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    for (const char* symbol : {"D", "W", "SW", "SD", "R", "ZR", "RD", "Z", "TN", "STN", "CN"}) {
        INFO(symbol);
        const auto& spec = dev(symbol);
        std::array<std::uint16_t, 3> in{0x1995, 0x1202, 0x1130};
        m.write_words(spec, 5, in);
        CHECK(read(m, symbol, 5, 3) == std::vector<std::uint16_t>{0x1995, 0x1202, 0x1130});
        CHECK(m.value(spec, 6) == 0x1202);
        m.set_value(spec, 7, 0x12345678);   // only the low word is kept
        CHECK(m.value(spec, 7) == 0x5678);
        CHECK(read(m, symbol, 4, 1) == std::vector<std::uint16_t>{0});
    }
}

TEST_CASE("timers and counters: contact, coil and value are separate", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    for (auto [s, c, n] : {std::array{"TS", "TC", "TN"}, std::array{"STS", "STC", "STN"}, std::array{"CS", "CC", "CN"}}) {
        INFO(s);
        m.set_bit(dev(s), 5, true);
        CHECK(m.bit(dev(s), 5));
        CHECK_FALSE(m.bit(dev(c), 5));
        m.set_bit(dev(c), 6, true);
        CHECK(m.bit(dev(c), 6));
        CHECK_FALSE(m.bit(dev(s), 6));
        m.set_value(dev(n), 5, 4660);
        CHECK(m.value(dev(n), 5) == 4660);
        CHECK(m.bit(dev(s), 5));   // value does not disturb the contact
        CHECK(read(m, s, 0, 1) == std::vector<std::uint16_t>{0x0020});
        CHECK(read(m, c, 0, 1) == std::vector<std::uint16_t>{0x0040});
    }
}

TEST_CASE("long timers: 4 words per device, status word b0 coil b1 contact", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    for (auto [s, c, n] : {std::array{"LTS", "LTC", "LTN"}, std::array{"LSTS", "LSTC", "LSTN"}}) {
        INFO(n);
        m.set_value(dev(n), 0, 0x12345678);
        m.set_bit(dev(c), 0, true);    // coil only
        m.set_value(dev(n), 1, 0x0000FFFF);
        m.set_bit(dev(s), 1, true);    // contact only
        m.set_bit(dev(s), 2, true);
        m.set_bit(dev(c), 2, true);    // both
        CHECK(read(m, n, 0, 12) == std::vector<std::uint16_t>{0x5678, 0x1234, 0x0001, 0,   //
                                                              0xFFFF, 0x0000, 0x0002, 0,   //
                                                              0x0000, 0x0000, 0x0003, 0});
        CHECK(m.value(dev(n), 0) == 0x12345678);

        std::array<std::uint16_t, 4> in{0xBEEF, 0xDEAD, 0x0002, 0x7777};
        m.write_words(dev(n), 3, in);
        CHECK(m.value(dev(n), 3) == 0xDEADBEEF);
        CHECK(m.bit(dev(s), 3));
        CHECK_FALSE(m.bit(dev(c), 3));
        CHECK(read(m, n, 3, 4) == std::vector<std::uint16_t>{0xBEEF, 0xDEAD, 0x0002, 0});   // system word not kept
    }
}

TEST_CASE("LCN and LZ: 2 words per device, 32-bit values", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    for (const char* symbol : {"LCN", "LZ"}) {
        INFO(symbol);
        std::array<std::uint16_t, 4> in{0x0001, 0x8000, 0xFFFF, 0xFFFF};
        m.write_words(dev(symbol), 0, in);
        CHECK(m.value(dev(symbol), 0) == 0x80000001u);
        CHECK(m.value(dev(symbol), 1) == 0xFFFFFFFFu);
        m.set_value(dev(symbol), 0, 0x00020003);
        CHECK(read(m, symbol, 0, 2) == std::vector<std::uint16_t>{0x0003, 0x0002});
    }
    SECTION("LCN's contact and coil live beside its value") {
        m.set_bit(dev("LCS"), 1, true);
        CHECK(m.bit(dev("LCS"), 1));
        CHECK_FALSE(m.bit(dev("LCC"), 1));
        CHECK(read(m, "LCN", 1, 2) == std::vector<std::uint16_t>{0xFFFF, 0xFFFF});
    }
}

TEST_CASE("R is a window onto ZR", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    m.set_value(dev("R"), 5, 0xAAAA);
    CHECK(m.value(dev("ZR"), 5) == 0xAAAA);
    m.set_value(dev("ZR"), 31, 0x5555);
    CHECK(m.value(dev("R"), 31) == 0x5555);
    SECTION("R keeps its own size") {
        CHECK(m.size(Area::R) == 32);
        CHECK(m.size(Area::ZR) == 128);
    }
    SECTION("the slack behind ZR is storage") {
        std::array<std::uint16_t, 2> in{1, 2};
        m.write_words(dev("ZR"), 127, in);   // ZR127 and ZR128 (slack)
        CHECK(read(m, "ZR", 127, 2) == std::vector<std::uint16_t>{1, 2});
    }
}

TEST_CASE("device memory bounds", "[device_memory]") {
    DeviceMemory m(small_sizes(), 16);
    SECTION("contains() counts devices") {
        CHECK(m.contains(Area::D, 0, 64));
        CHECK(m.contains(Area::D, 63, 1));
        CHECK_FALSE(m.contains(Area::D, 63, 2));
        CHECK_FALSE(m.contains(Area::D, 64, 1));
        CHECK(m.contains(Area::D, 64, 0));
        CHECK_FALSE(m.contains(Area::D, 0xFFFFFFFFull, 2));
    }
    SECTION("access past the end is ignored, never a crash") {
        m.set_value(dev("D"), 1000, 7);
        CHECK(m.value(dev("D"), 1000) == 0);
        m.set_bit(dev("M"), 1000, true);
        CHECK_FALSE(m.bit(dev("M"), 1000));
        CHECK(read(m, "D", 62, 4) == std::vector<std::uint16_t>{0, 0, 0, 0});
    }
    SECTION("a new memory is all zero") {
        CHECK(read(m, "D", 0, 64) == std::vector<std::uint16_t>(64, 0));
        CHECK(read(m, "M", 0, 4) == std::vector<std::uint16_t>(4, 0));
    }
}

TEST_CASE("a copy compares equal until a value differs", "[device_memory]") {
    // fuzz_http's snapshot: a copy before a request, == after it.
    DeviceMemory m(small_sizes(), 16);
    const DeviceMemory before = m;
    CHECK(m == before);
    SECTION("any store counts: words, bits, coils, the slack behind ZR") {
        for (const char* symbol : {"D", "M", "TC", "LZ"}) {
            INFO(symbol);
            m.set_value(dev(symbol), 1, 1);
            CHECK_FALSE(m == before);
            m.set_value(dev(symbol), 1, 0);
            CHECK(m == before);
        }
        m.set_value(dev("ZR"), 130, 1);   // slack
        CHECK_FALSE(m == before);
    }
    SECTION("sizes count, the observer does not") {
        auto larger = small_sizes();
        larger[static_cast<std::size_t>(Area::D)] = 65;
        CHECK_FALSE(m == DeviceMemory(larger, 16));
        struct : WriteObserver {
            void written(const DeviceSpec&, std::uint32_t, std::uint32_t) override {}
        } observer;
        m.set_write_observer(&observer);
        CHECK(m == before);
        m.set_write_observer(nullptr);
    }
}
