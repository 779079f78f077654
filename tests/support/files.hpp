// Reading a whole file in tests (recordings, documents, scenario files).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace slmp::test {

inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

}  // namespace slmp::test
