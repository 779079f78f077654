// Test-only helpers for the engine suite: a Source from text lines (until the
// loader's read_source lands: "MNEMONIC op op" split on blanks, "P10" alone a
// pointer), the three reference profiles by hand, and a rig that scans like
// the runtime does (SM400 ON, SM402 ON in scan 1 only, end_of_scan(10 ms)).
#pragma once

#include <cctype>
#include <chrono>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_memory.hpp"
#include "devicemodel/device_table.hpp"
#include "program/program.hpp"

namespace engine_test {

using namespace slmp;
using devicemodel::Area;

inline program::Source text_source(const std::vector<std::string>& lines, std::string file = "test.il") {
    program::Source source;
    source.file = std::move(file);
    source.format = program::Format::Text;
    std::size_t row = 0;
    for (const auto& text : lines) {
        ++row;
        std::istringstream in(text);
        std::vector<std::string> words;
        for (std::string word; in >> word;) words.push_back(word);
        if (words.empty()) continue;
        program::SourceLine line;
        line.row = row;
        if (words.size() == 1 && words[0].size() > 1 && (words[0][0] == 'P' || words[0][0] == 'p') &&
            std::isdigit(static_cast<unsigned char>(words[0][1]))) {
            line.kind = program::SourceLine::Kind::Pointer;
            line.mnemonic = words[0];
        } else {
            line.mnemonic = words[0];
            line.operands.assign(words.begin() + 1, words.end());
        }
        source.lines.push_back(std::move(line));
    }
    return source;
}

// "LD X0 · OUT Y0 · END" as in the spec's text form.
inline program::Source dotted(const std::string& text) {
    std::vector<std::string> lines;
    std::string current;
    for (std::size_t i = 0; i < text.size();) {
        if (text.compare(i, 2, "\xC2\xB7") == 0) {   // '·' in UTF-8
            lines.push_back(current);
            current.clear();
            i += 2;
        } else {
            current += text[i++];
        }
    }
    lines.push_back(current);
    return text_source(lines);
}

inline void size(devicemodel::CpuProfile& p, Area area, std::uint32_t points) { p.sizes[static_cast<std::size_t>(area)] = points; }

inline devicemodel::CpuProfile r08() {
    devicemodel::CpuProfile p;
    p.name = "R08CPU";
    p.family = devicemodel::Family::IQR;
    for (auto [a, n] : std::initializer_list<std::pair<Area, std::uint32_t>>{
             {Area::X, 12288}, {Area::Y, 12288}, {Area::M, 12288}, {Area::L, 8192}, {Area::B, 8192}, {Area::SB, 2048},
             {Area::SW, 2048}, {Area::F, 2048}, {Area::V, 2048}, {Area::S, 1024}, {Area::T, 1024}, {Area::ST, 1024},
             {Area::LT, 1024}, {Area::LST, 1024}, {Area::C, 512}, {Area::LC, 512}, {Area::D, 10240}, {Area::W, 8192},
             {Area::Z, 20}, {Area::LZ, 2}, {Area::R, 32768}, {Area::ZR, 163840}, {Area::RD, 524288}, {Area::SM, 4096},
             {Area::SD, 4096}})
        size(p, a, n);
    return p;
}

inline devicemodel::CpuProfile q26() {
    devicemodel::CpuProfile p;
    p.name = "Q26UDEHCPU";
    p.family = devicemodel::Family::QnU;
    for (auto [a, n] : std::initializer_list<std::pair<Area, std::uint32_t>>{
             {Area::X, 8192}, {Area::Y, 8192}, {Area::M, 8192}, {Area::L, 8192}, {Area::B, 8192}, {Area::SB, 2048},
             {Area::SW, 2048}, {Area::F, 2048}, {Area::V, 2048}, {Area::S, 8192}, {Area::T, 2048}, {Area::ST, 0},
             {Area::C, 1024}, {Area::D, 12288}, {Area::W, 8192}, {Area::Z, 20}, {Area::R, 32768}, {Area::ZR, 65536},
             {Area::SM, 2048}, {Area::SD, 2048}})
        size(p, a, n);
    return p;
}

inline devicemodel::CpuProfile fx5u() {
    devicemodel::CpuProfile p;
    p.name = "FX5U-32MR";
    p.family = devicemodel::Family::IQF;
    p.numbering.xy = devicemodel::Radix::Oct;
    for (auto [a, n] : std::initializer_list<std::pair<Area, std::uint32_t>>{
             {Area::X, 1024}, {Area::Y, 1024}, {Area::M, 7680}, {Area::L, 7680}, {Area::B, 256}, {Area::SB, 512},
             {Area::SW, 512}, {Area::F, 128}, {Area::S, 4096}, {Area::T, 512}, {Area::ST, 16}, {Area::C, 256},
             {Area::LC, 64}, {Area::D, 8000}, {Area::W, 512}, {Area::Z, 20}, {Area::LZ, 2}, {Area::R, 32768},
             {Area::SM, 10000}, {Area::SD, 12000}})
        size(p, a, n);
    return p;
}

// A CPU in RUN with one program: scan() as the runtime would call it.
struct Rig {
    devicemodel::CpuProfile profile;
    devicemodel::DeviceMemory memory;
    program::Execution execution;
    int scans = 0;

    Rig(const program::Source& source, devicemodel::CpuProfile p = r08(), program::ProgramOptions options = {})
        : profile(std::move(p)), memory(profile.sizes), execution(program::compile(source, profile, options)) {
        set("SM400", 1);
    }

    static const devicemodel::DeviceSpec& spec(const std::string& symbol) { return *devicemodel::find_by_symbol(symbol); }
    devicemodel::DeviceAddress address(const std::string& text) const {
        std::string error;
        auto a = devicemodel::parse_address(text, profile.numbering, &error);
        if (!a) throw std::runtime_error(error);
        return *a;
    }
    void set(const std::string& device, std::uint32_t value) {
        auto a = address(device);
        memory.set_value(*a.spec, a.number, value);
    }
    std::uint32_t get(const std::string& device) const {
        auto a = address(device);
        return memory.value(*a.spec, a.number);
    }
    // One scan: SM402 ON in scan 1 only, then END processing with 10 ms.
    program::ScanOutcome scan() {
        ++scans;
        set("SM402", scans == 1 ? 1 : 0);
        auto outcome = execution.scan(memory);
        execution.end_of_scan(std::chrono::milliseconds(10));
        return outcome;
    }
    void scan(int n) {
        for (int i = 0; i < n; ++i) scan();
    }
};

// The problems compile() reports, or none.
inline std::vector<std::string> load_problems(const program::Source& source, const devicemodel::CpuProfile& profile,
                                              program::ProgramOptions options = {},
                                              std::vector<std::string>* warnings = nullptr) {
    try {
        program::compile(source, profile, options, warnings);
    } catch (const program::LoadError& e) {
        return e.problems;
    }
    return {};
}

}  // namespace engine_test
