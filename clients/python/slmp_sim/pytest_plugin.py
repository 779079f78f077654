"""pytest fixtures for slmp-sim (docs/ci.md).

Enable with ``pytest -p slmp_sim.pytest_plugin`` or ``pytest_plugins = ["slmp_sim.pytest_plugin"]`` in a
conftest.py, with clients/python on PYTHONPATH (or the package vendored).

* ``slmp_sim`` — an ``SlmpSim`` client for one simulator shared by the session, put back to the state it started
  in before every test (a station snapshot named ``slmp-sim-clean``, restored in well under 10 ms), so each test
  starts clean without a restart. The clock is put back in the mode and speed it started with.
* ``slmp_sim_factory`` — ``slmp_sim_factory(config=..., profile=..., scenarios=[...], args=[...])`` starts a
  simulator of its own for this test (stopped at its end).

Options (command line or ini): ``--slmp-sim-binary``, ``--slmp-sim-config``, ``--slmp-sim-profile``,
``--slmp-sim-scenario`` (repeatable), ``--slmp-sim-arg`` (repeatable, e.g. ``--slmp-sim-arg=--clock=frozen``).
"""
import pytest

from .process import start

CLEAN = "slmp-sim-clean"


def pytest_addoption(parser):
    group = parser.getgroup("slmp-sim")
    group.addoption("--slmp-sim-binary", default=None, help="the slmp-sim executable (default: $SLMP_SIM_BINARY, PATH)")
    group.addoption("--slmp-sim-config", default=None, help="configuration file for the shared simulator")
    group.addoption("--slmp-sim-profile", default=None, help="CPU profile of the shared simulator")
    group.addoption("--slmp-sim-scenario", action="append", default=[], help="scenario file (repeatable)")
    group.addoption("--slmp-sim-arg", action="append", default=[], help="further slmp-sim option (repeatable)")


def _options(config):
    return {
        "binary": config.getoption("--slmp-sim-binary"),
        "config": config.getoption("--slmp-sim-config"),
        "profile": config.getoption("--slmp-sim-profile"),
        "scenarios": config.getoption("--slmp-sim-scenario"),
        "args": config.getoption("--slmp-sim-arg"),
    }


@pytest.fixture(scope="session")
def slmp_sim_process(request, tmp_path_factory):
    """The session's simulator process (``SimProcess``); most tests want ``slmp_sim``."""
    process = start(workdir=tmp_path_factory.mktemp("slmp-sim"), **_options(request.config))
    process.sim.snapshot(CLEAN)
    process.start_clock = process.sim.clock.get()
    yield process
    code = process.stop()
    assert code == 0, "slmp-sim exited with %s:\n%s" % (code, process.output())


@pytest.fixture
def slmp_sim(slmp_sim_process):
    """The shared simulator's client, restored to its starting state (and clock mode) before the test."""
    sim = slmp_sim_process.sim
    clock = slmp_sim_process.start_clock
    # A snapshot keeps the PLC, not the harness: the clock's mode is put back here.
    if clock["mode"] == "frozen":
        sim.clock.freeze()
    else:
        sim.clock.realtime(clock["speed"])
    sim.restore(CLEAN)
    return sim


@pytest.fixture
def slmp_sim_factory(request, tmp_path):
    """Starts simulators of this test's own: ``slmp_sim_factory(config=..., scenarios=[...], args=[...])``."""
    started = []
    defaults = _options(request.config)

    def factory(config=None, profile=None, scenarios=(), args=()):
        process = start(binary=defaults["binary"], config=config, profile=profile, scenarios=scenarios, args=args,
                        workdir=tmp_path / ("sim%d" % len(started)))
        started.append(process)
        return process.sim

    yield factory
    for process in started:
        process.stop()
