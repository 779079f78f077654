// slmp file ls|get|put|rm against the real simulator: a file put through the
// CLI lands in the --drive folder byte-identical, ls shows it, get brings it
// back, rm deletes it; on a Q CPU the CLI falls back to the 0000 dialect.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
namespace fs = std::filesystem;
using Args = std::vector<std::string>;

namespace {

std::string slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("slmp file put/ls/get/rm against the simulator, iQ-R and Q", "[cli][files]") {
    auto profile = GENERATE(std::string("R08CPU"), std::string("Q06UDVCPU"));
    INFO(profile);
    TempDir data;
    auto folder = data.path() / "plc";
    fs::create_directories(folder);
    std::string content;
    for (int i = 0; i < 5000; ++i) content += static_cast<char>((i * 37 + 11) & 0xFF);
    std::ofstream(data.path() / "recipe.bin", std::ios::binary) << content;
    SimProcess sim(with_args({"--profile", profile, "--drive", "2=" + folder.string()}));
    auto base = target(sim.tcp_port());

    auto put = run_cli(base + Args{"file", "put", (data.path() / "recipe.bin").string(), "2:RECIPE.BIN"});
    INFO(put.err);
    REQUIRE(put.exit_code == 0);
    CHECK(slurp(folder / "RECIPE.BIN") == content);

    auto ls = json_of(run_cli(base + Args{"--json", "file", "ls", "2:"}));
    REQUIRE(ls["entries"].size() == 1);
    CHECK(ls["entries"][0]["name"] == "RECIPE.BIN");
    CHECK(ls["entries"][0]["size"] == 5000);

    auto back = data.path() / "back.bin";
    REQUIRE(run_cli(base + Args{"file", "get", "2:RECIPE.BIN", back.string()}).exit_code == 0);
    CHECK(slurp(back) == content);

    // The name exists: 4028, exit 1.
    CHECK(run_cli(base + Args{"file", "put", back.string(), "2:RECIPE.BIN"}).exit_code == 1);
    REQUIRE(run_cli(base + Args{"file", "rm", "2:RECIPE.BIN"}).exit_code == 0);
    CHECK_FALSE(fs::exists(folder / "RECIPE.BIN"));
    CHECK(run_cli(base + Args{"file", "rm", "2:RECIPE.BIN"}).exit_code == 1);
    CHECK(run_cli(base + Args{"file", "get", "2"}).exit_code == 2);
}
