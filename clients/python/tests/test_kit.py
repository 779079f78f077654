"""The kit's own suite, against the real slmp-sim. No sleeps: waits are the simulator's."""
import json
import threading

import pytest

from slmp_sim import SlmpSimError, WaitTimeout

from slmp_raw import write_words

TIMER_CONFIG = {"cpu": {"scan_time_ms": 100, "timers": [{"device": "T0", "preset": 20, "base_ms": 100}]},
                "devices": {"D0": [7, 8]}}


def test_set_and_get(slmp_sim):
    slmp_sim.set("D100", [1, -1, 3])
    assert slmp_sim.get("D100", count=3) == [1, 65535, 3]
    slmp_sim.set("M0", True)
    assert slmp_sim.get("M0") == 1
    slmp_sim.set("D200", "HELLO")
    assert slmp_sim.get("D200", count=3, as_="string") == "HELLO"


def test_each_test_starts_clean_part1(slmp_sim):
    slmp_sim.set("D900", 99)
    slmp_sim.set_switch("STOP")


def test_each_test_starts_clean_part2(slmp_sim):
    # Whatever order pytest chose, the restore before each test put these back.
    assert slmp_sim.get("D900") == 0
    assert slmp_sim.state()["switch"] == "RUN"


def test_snapshot_restore_reset(slmp_sim):
    slmp_sim.set("D10", 5)
    slmp_sim.snapshot("mine")
    slmp_sim.set("D10", 6)
    assert slmp_sim.restore("mine")["restored"] == "mine"
    assert slmp_sim.get("D10") == 5
    assert "mine" in [s["name"] for s in slmp_sim.snapshots()]
    slmp_sim.reset()
    assert slmp_sim.get("D10") == 0
    slmp_sim.delete_snapshot("mine")
    with pytest.raises(SlmpSimError) as e:
        slmp_sim.restore("mine")
    assert e.value.status == 404


def test_wait_for_a_client_write(slmp_sim):
    """The example of docs/ci.md: seed, let the client write, wait for it — no sleep."""
    slmp_sim.set("D0", 41)
    client = threading.Thread(target=write_words, args=(slmp_sim.tcp_port, "D", 100, [1234]))
    client.start()
    assert slmp_sim.wait("D100", equals=1234, timeout_ms=10000) == 1234
    client.join()


def test_wait_timeout_reports_the_last_value(slmp_sim):
    slmp_sim.set("D5", 3)
    with pytest.raises(WaitTimeout) as e:
        slmp_sim.wait("D5", equals=4, timeout_ms=50)
    assert e.value.status == 408
    assert e.value.value == 3


def test_bad_wait_names_the_fix(slmp_sim):
    with pytest.raises(SlmpSimError) as e:
        slmp_sim.wait("D5", equals="five")
    assert e.value.status == 400
    assert "not a number" in e.value.message


def test_frozen_clock_and_steps(slmp_sim_factory, tmp_path):
    config = tmp_path / "timer.json"
    config.write_text(json.dumps(TIMER_CONFIG))
    sim = slmp_sim_factory(config=config, args=["--clock", "frozen"])
    assert sim.get("D0", count=2) == [7, 8]
    sim.set("TC0", 1)
    sim.clock.step(scans=1)                  # this scan starts timing
    for step in range(1, 20):
        sim.clock.step(scans=1)
        assert sim.get("TS0") == 0, "contact on at step %d" % step
    sim.clock.step(scans=1)
    assert sim.get("TS0") == 1
    assert sim.get("TN0") == 20
    sim.clock.realtime(speed=2)
    assert sim.clock.get()["mode"] == "realtime"
    with pytest.raises(SlmpSimError) as e:
        sim.clock.step(ms=100)
    assert e.value.status == 409


def test_clock_freeze_in_the_shared_sim(slmp_sim):
    slmp_sim.clock.freeze()
    before = slmp_sim.clock.get()["clock_ms"]
    after = slmp_sim.clock.step(ms=1500)["clock_ms"]
    assert after == pytest.approx(before + 1500)


def test_scenario_load_and_fault(slmp_sim):
    slmp_sim.scenario.load(body={"name": "refuse", "faults": [
        {"id": "no-d100", "do": "end_code", "end_code": "C051", "match": {"devices": "D100-D199"}}]})
    assert write_words(slmp_sim.tcp_port, "D", 100, [1]) == 0xC051
    slmp_sim.fault.enable("no-d100", False)
    assert write_words(slmp_sim.tcp_port, "D", 100, [1]) == 0
    slmp_sim.scenario.stop("refuse")
    assert slmp_sim.scenario.list() == []


def test_command_line(slmp_sim):
    import subprocess
    import sys

    def cli(*args):
        return subprocess.run([sys.executable, "-m", "slmp_sim", "--http-port", str(slmp_sim.http_port)] + list(args),
                              capture_output=True, text=True, timeout=60)

    assert json.loads(cli("set", "D30", "7").stdout)["values"] == [7]
    assert json.loads(cli("snapshot", "cli").stdout)["name"] == "cli"
    assert json.loads(cli("wait", "D30", "--equals", "7", "--timeout-ms", "1000").stdout) == {"value": 7}
    timed_out = cli("wait", "D30", "--equals", "8", "--timeout-ms", "20")
    assert timed_out.returncode == 3
    assert "last value is 7" in timed_out.stderr
    assert json.loads(cli("clock", "frozen").stdout)["mode"] == "frozen"
    assert json.loads(cli("clock", "step", "--scans", "2").stdout)["mode"] == "frozen"
    cli("set", "D30", "9")
    assert json.loads(cli("restore", "cli").stdout)["restored"] == "cli"
    assert slmp_sim.get("D30") == 7
    refused = cli("restore", "nope")
    assert refused.returncode == 1
    assert "no snapshot 'nope'" in refused.stderr


# The HMI-style test of docs/ci.md: the CPU runs the line's program; the HMI
# presses a start button (M0) over SLMP; 3 s of scans later the motor output
# is on and the cycle counter counted once.
CONVEYOR_PROGRAM = """
;; start button M0 latches the motor request M100, stop button M1 drops it
LD M0
OR M100
ANI M1
OUT M100
;; the motor starts 3 s after the request (T0, 100 ms base)
LD M100
OUT T0 K30
LD T0
OUT Y20
;; every motor start counts once
LD Y20
OUT C0 K9999
END
"""


def test_program_reacts_to_an_hmi_button(slmp_sim_factory):
    sim = slmp_sim_factory(args=["--clock", "frozen"])
    info = sim.program.load(text=CONVEYOR_PROGRAM, name="conveyor.il")
    assert info["state"] == "loaded" and info["file"] == "conveyor.il"
    assert write_words(sim.tcp_port, "M", 0, [0b01]) == 0      # press start (M0 ON)
    sim.clock.step(scans=1)
    assert write_words(sim.tcp_port, "M", 0, [0b00]) == 0      # release it
    sim.clock.step(ms=2900)
    assert sim.get("Y20") == 0
    sim.clock.step(ms=200)
    assert sim.get("Y20") == 1
    assert sim.get("CN0") == 1
    assert "OUT T0 K30" in sim.program.source("text")
    sim.program.unload()
    assert sim.program.get()["state"] == "none"
