#include <numeric>

#include "program/source.hpp"

namespace slmp::program {

namespace {
std::string joined(const std::vector<std::string>& problems) {
    if (problems.empty()) return "program does not load";
    return std::accumulate(std::next(problems.begin()), problems.end(), problems.front(),
                           [](std::string all, const std::string& line) { return std::move(all) + "\n" + line; });
}
}  // namespace

LoadError::LoadError(std::vector<std::string> list) : std::runtime_error(joined(list)), problems(std::move(list)) {}

}  // namespace slmp::program
