// Station::handle(), the one entry point every transport calls: a frame is
// handled once it is whole, then reported to the activity observers with the
// peer it came from and the session's id; an incomplete one is not reported.
#include <catch2/catch.hpp>

#include <span>
#include <string>

#include "station/station.hpp"
#include "support/fixtures.hpp"

using slmp::protocol::DataCodePolicy;
using slmp::protocol::Outcome;

namespace {

struct SeenRequests final : slmp::station::ActivityObserver {
    int starting = 0;
    int requests = 0;
    std::string peer;
    std::uint64_t connection = 0;
    std::size_t bytes = 0;

    void on_request_starting() override { ++starting; }
    void on_request(const slmp::station::RequestRecord& record) override {
        ++requests;
        peer = record.peer.text();
        connection = record.connection;
        bytes = record.frame.size();
    }
};

}  // namespace

TEST_CASE("station: handle() answers a whole frame and reports it with its peer", "[station]") {
    slmp::station::Station station(slmp::config::load_profile("R08CPU"), {});
    SeenRequests seen;
    station.activity().add_observer(&seen);
    slmp::protocol::Session session;
    session.id = station.next_session_id();
    CHECK(station.next_session_id() == session.id + 1);
    const slmp::protocol::Peer peer{slmp::protocol::Transport::Tcp, "192.0.2.7", 50312, 5000};
    // 3E binary, 0401 batch read of D100, one word.
    const auto frame = slmp::test::bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00");

    auto part = station.handle(std::span(frame).first(10), DataCodePolicy::Auto, session, peer);
    CHECK(part.outcome.action == Outcome::Action::NeedMore);
    CHECK(seen.starting == 1);
    CHECK(seen.requests == 0);

    auto whole = station.handle(frame, DataCodePolicy::Auto, session, peer);
    CHECK(whole.outcome.action == Outcome::Action::Respond);
    CHECK(whole.outcome.consumed == frame.size());
    CHECK(seen.starting == 2);
    CHECK(seen.requests == 1);
    CHECK(seen.peer == "tcp:192.0.2.7:50312");
    CHECK(seen.connection == session.id);
    CHECK(seen.bytes == frame.size());
    station.activity().remove_observer(&seen);
}
