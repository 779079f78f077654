"""slmp-sim's CI kit: start the simulator, drive it over its HTTP API.

Standard library only. ``SlmpSim`` is the HTTP client, ``start`` launches the
real binary on free ports (``--ready-file``), and ``slmp_sim.pytest_plugin``
turns both into pytest fixtures. See docs/ci.md.
"""
from .client import Clock, Faults, Scenarios, SlmpSim, SlmpSimError, WaitTimeout
from .process import SimProcess, find_binary, start

__all__ = ["SlmpSim", "SlmpSimError", "WaitTimeout", "Clock", "Faults", "Scenarios", "SimProcess", "start",
           "find_binary"]
