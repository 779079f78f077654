// Remote Password Unlock 1630 / Lock 1631 — SLMP Reference Manual §5.7,
// real-CPU measurements (C201 while locked, C810 wrong password), byte-exact
// in binary and ASCII. The lock state is per connection (Session).
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

const std::string kAlphabet = "abcdefghijklmnopqrstuvwxyz";

Payload password_req(std::uint16_t command, const std::string& password, std::size_t length = std::string::npos) {
    auto n = static_cast<std::uint16_t>(length == std::string::npos ? password.size() : length);
    return word(command) + word(0x0000) + word(n) + Payload{hex(text(password)), password};
}
Payload unlock(const std::string& pw) { return password_req(0x1630, pw); }
Payload lock(const std::string& pw) { return password_req(0x1631, pw); }

struct Client {
    protocol::Session session{};
    explicit Client(std::uint64_t id) { session.id = id; }
    std::string exchange(devicemodel::Cpu& cpu, const Wire& w, const Payload& p) {
        return w.show(engine_for(cpu).process(w.request(p), DataCodePolicy::Auto, session));
    }
};

devicemodel::Cpu cpu_with_password(const std::string& password, const std::string& profile = "R08CPU",
                                   unsigned attempts = 10) {
    auto cpu = make_cpu(profile);
    devicemodel::RuntimeConfig c;
    c.password = password;
    c.lockout_attempts = attempts;
    cpu.runtime().configure(std::move(c), cpu.memory());
    return cpu;
}

}  // namespace

TEST_CASE("1630/1631 request data as the manual prints it (§6)", "[password][spec]") {
    CHECK(unlock(kAlphabet).ascii == "16300000001Aabcdefghijklmnopqrstuvwxyz");
    CHECK(unlock(kAlphabet).binary ==
          "30 16 00 00 1A 00 61 62 63 64 65 66 67 68 69 6A 6B 6C 6D 6E 6F 70 71 72 73 74 75 76 77 78 79 7A");
    CHECK(lock(kAlphabet).ascii == "16310000001Aabcdefghijklmnopqrstuvwxyz");
    CHECK(lock(kAlphabet).binary.substr(0, 17) == "31 16 00 00 1A 00");
}

TEST_CASE("a locked connection gets C201 for everything but Unlock, Unlock opens only that connection", "[password]") {
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto cpu = cpu_with_password(kAlphabet);
    Client a(1), b(2);
    CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(error(0xC201, 0x0401, 0x0000)));
    CHECK(a.exchange(cpu, wire, word(0x0101) + word(0x0000)) == wire.expect(error(0xC201, 0x0101, 0x0000)));
    CHECK(a.exchange(cpu, wire, word(0x1234) + word(0x0000)) == wire.expect(error(0xC201, 0x1234, 0x0000)));
    CHECK(a.exchange(cpu, wire, unlock(kAlphabet)) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words({0}))));
    CHECK(b.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(error(0xC201, 0x0401, 0x0000)));
    SECTION("Lock with the password locks again") {
        CHECK(a.exchange(cpu, wire, lock(kAlphabet)) == wire.expect(ok()));
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(error(0xC201, 0x0401, 0x0000)));
    }
    SECTION("Lock with a wrong password: C810, still unlocked") {
        CHECK(a.exchange(cpu, wire, lock("abcdefg")) == wire.expect(error(0xC810, 0x1631, 0x0000)));
        CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words({0}))));
    }
    SECTION("Unlock while unlocked and Lock while locked are no-ops without a check") {
        CHECK(a.exchange(cpu, wire, unlock("whatever")) == wire.expect(ok()));
        CHECK(b.exchange(cpu, wire, lock("whatever")) == wire.expect(ok()));
    }
}

TEST_CASE("wrong passwords: C810, then the C815 lock-out", "[password]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = cpu_with_password("secret", "R08CPU", 3);
    Client a(1), b(2);
    CHECK(a.exchange(cpu, wire, unlock("Secret")) == wire.expect(error(0xC810, 0x1630, 0x0000)));
    CHECK(a.exchange(cpu, wire, unlock("secre")) == wire.expect(error(0xC810, 0x1630, 0x0000)));
    CHECK(b.exchange(cpu, wire, unlock("secrets")) == wire.expect(error(0xC810, 0x1630, 0x0000)));   // counted per CPU
    CHECK(a.exchange(cpu, wire, unlock("secret")) == wire.expect(error(0xC815, 0x1630, 0x0000)));
    CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(error(0xC201, 0x0401, 0x0000)));
    // The lock-out ends with time (the scan clock).
    cpu.runtime().scan(cpu.memory(), cpu.runtime().now() + std::chrono::seconds(61), {});
    CHECK(a.exchange(cpu, wire, unlock("secret")) == wire.expect(ok()));
}

// The station gives each request its clock's time (Session::now); before the
// CPU's first scan (a frozen clock not yet stepped) the last scan's time is the
// epoch, and a lock-out counted from it ended at the first scan.
TEST_CASE("the lock-out counts on the request's clock, also before the CPU's first scan", "[password]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = cpu_with_password("secret", "R08CPU", 1);
    Client a(1);
    const auto start = std::chrono::steady_clock::time_point{} + std::chrono::hours(1000);
    a.session.now = start;
    CHECK(a.exchange(cpu, wire, unlock("Secret")) == wire.expect(error(0xC810, 0x1630, 0x0000)));   // the lock-out begins
    a.session.now = start + std::chrono::seconds(59);
    CHECK(a.exchange(cpu, wire, unlock("secret")) == wire.expect(error(0xC815, 0x1630, 0x0000)));
    a.session.now = start + std::chrono::seconds(61);
    CHECK(a.exchange(cpu, wire, unlock("secret")) == wire.expect(ok()));
}

TEST_CASE("Q/L: 4-character passwords, bad lengths", "[password]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = cpu_with_password("A1b2", "Q26UDEHCPU");
    Client a(1);
    CHECK(a.exchange(cpu, wire, unlock("A1b2")) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, lock("A1b2")) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, unlock("A1b2x")) == wire.expect(error(0xC810, 0x1630, 0x0000)));
    CHECK(a.exchange(cpu, wire, password_req(0x1630, "A1b2", 5)) == wire.expect(error(0xC061, 0x1630, 0x0000)));
    CHECK(a.exchange(cpu, wire, password_req(0x1630, "A1b2", 3)) == wire.expect(error(0xC061, 0x1630, 0x0000)));
}

TEST_CASE("no password configured: nothing is locked, Lock answers C810", "[password]") {
    auto wire = GENERATE(kBinary3E, kAscii3E);
    auto cpu = make_cpu();
    Client a(1);
    CHECK(a.exchange(cpu, wire, read_words_req(Form::Q, "D0", 1)) == wire.expect(ok(words({0}))));
    CHECK(a.exchange(cpu, wire, unlock("abcdef")) == wire.expect(ok()));
    CHECK(a.exchange(cpu, wire, lock("abcdef")) == wire.expect(error(0xC810, 0x1631, 0x0000)));
}
