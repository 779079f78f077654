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

TEST_CASE("slmp file --file-password reaches a file with a password, iQ-R and Q", "[cli][files]") {
    struct Case {
        std::string profile, password, wrong;
    };
    auto c = GENERATE(Case{"R08CPU", "abcdef12", "abcdef13"}, Case{"Q06UDVCPU", "AB12", "AB13"});
    INFO(c.profile);
    TempDir data;
    auto folder = data.path() / "plc";
    fs::create_directories(folder);
    const std::string content = "recipe 42\n";
    std::ofstream(folder / "SECRET.BIN", std::ios::binary) << content;
    SimOptions options;
    options.args = {"--profile", c.profile};
    options.config_json = R"({"drives": {"2": {"dir": ")" + folder.string() + R"(", "passwords": {"SECRET.BIN": ")" +
                          c.password + R"("}}}})";
    SimProcess sim(options);
    auto base = target(sim.tcp_port());
    auto back = (data.path() / "back.bin").string();

    // Without the password, or with a wrong one: 4026, exit 1, nothing read.
    auto refused = run_cli(base + Args{"file", "get", "2:SECRET.BIN", back});
    CHECK(refused.exit_code == 1);
    CHECK(refused.err.find("4026") != std::string::npos);
    CHECK(run_cli(base + Args{"file", "get", "2:SECRET.BIN", back, "--file-password", c.wrong}).exit_code == 1);
    CHECK_FALSE(fs::exists(back));

    auto got = run_cli(base + Args{"file", "get", "2:SECRET.BIN", back, "--file-password", c.password});
    INFO(got.err);
    REQUIRE(got.exit_code == 0);
    CHECK(slurp(back) == content);

    // A password no dialect carries is a usage error, sent nowhere.
    CHECK(run_cli(base + Args{"file", "rm", "2:SECRET.BIN", "--file-password", "abcde"}).exit_code == 2);
    CHECK(run_cli(base + Args{"file", "rm", "2:SECRET.BIN", "--file-password", c.wrong}).exit_code == 1);
    CHECK(fs::exists(folder / "SECRET.BIN"));
    REQUIRE(run_cli(base + Args{"file", "rm", "2:SECRET.BIN", "--file-password", c.password}).exit_code == 0);
    CHECK_FALSE(fs::exists(folder / "SECRET.BIN"));
    // --file-password belongs to file only.
    CHECK(run_cli(base + Args{"read", "D0", "--file-password", c.password}).exit_code == 2);
}
