// A generated part of a committed file (docs/compatibility.md's matrix, the
// Wireshark dissector's tables) kept true by a test: the text between `begin`
// and `end` must equal what the code produces now. With SLMP_UPDATE_DOCS set
// the test rewrites that part instead of failing, after a deliberate change.
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/files.hpp"

namespace slmp::test {

inline void check_generated_section(const std::filesystem::path& file, const std::string& begin_marker,
                                    const std::string& end_marker, const std::string& generated) {
    auto text = read_text(file);
    auto begin = text.find(begin_marker);
    auto end = text.find(end_marker);
    REQUIRE(begin != std::string::npos);
    REQUIRE(end != std::string::npos);
    const auto committed = text.substr(begin + begin_marker.size(), end - begin - begin_marker.size());
    if (committed != generated && std::getenv("SLMP_UPDATE_DOCS")) {
        std::ofstream(file, std::ios::binary) << text.substr(0, begin + begin_marker.size()) << generated
                                              << text.substr(end);
        WARN("rewrote " << file.string());
        return;
    }
    INFO(file.string() << " is stale; rerun with SLMP_UPDATE_DOCS=1 after checking the new text:\n" << generated);
    CHECK(committed == generated);
}

}  // namespace slmp::test
