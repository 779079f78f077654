"""Start the real slmp-sim binary on free ports and wait until it listens."""
import json
import os
import pathlib
import shutil
import subprocess
import tempfile
import time

from .client import SlmpSim

_REPO = pathlib.Path(__file__).resolve().parents[3]


def find_binary(explicit=None):
    """``explicit``, else $SLMP_SIM_BINARY, else slmp-sim on PATH, else this checkout's build/server/slmp-sim."""
    for candidate in (explicit, os.environ.get("SLMP_SIM_BINARY"), shutil.which("slmp-sim"),
                      _REPO / "build" / "server" / "slmp-sim"):
        if candidate and pathlib.Path(candidate).is_file():
            return str(pathlib.Path(candidate).resolve())
    raise FileNotFoundError("slmp-sim not found: set SLMP_SIM_BINARY, pass --slmp-sim-binary, or put it on PATH")


class SimProcess:
    """A running simulator: ``.sim`` is its ``SlmpSim`` client, ``.log`` its output file; ``stop()`` ends it."""

    def __init__(self, process, sim, workdir, log):
        self.process = process
        self.sim = sim
        self.workdir = workdir
        self.log = log

    def stop(self, timeout=10):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        return self.process.returncode

    def output(self):
        return pathlib.Path(self.log).read_text(errors="replace")


def start(binary=None, config=None, profile=None, scenarios=(), args=(), workdir=None, ready_timeout=15.0):
    """Starts slmp-sim on 127.0.0.1 with free TCP, UDP and HTTP ports and returns a ``SimProcess``.

    ``config``/``profile`` are paths (or a built-in profile name), ``scenarios`` scenario files, ``args`` any
    further options (``["--clock", "frozen"]``). Raises RuntimeError with the simulator's output when it exits
    (exit code 2: the one-line error) or is not ready within ``ready_timeout`` seconds.
    """
    workdir = pathlib.Path(workdir or tempfile.mkdtemp(prefix="slmp-sim-"))
    workdir.mkdir(parents=True, exist_ok=True)
    ready = workdir / "ready.json"
    log = workdir / "slmp-sim.log"
    command = [find_binary(binary), "--bind", "127.0.0.1", "--tcp-port", "0", "--udp-port", "0", "--http-port", "0",
               "--ready-file", str(ready)]
    if config:
        command += ["--config", str(config)]
    if profile:
        command += ["--profile", str(profile)]
    for scenario in scenarios:
        command += ["--scenario", str(scenario)]
    command += [str(a) for a in args]
    with open(log, "wb") as out:
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, cwd=str(workdir))
    # The simulator renames the ready file into place once every port listens,
    # so it is whole when it appears; the loop only bounds how long that takes.
    deadline = time.monotonic() + ready_timeout
    while not ready.exists():
        if process.poll() is not None:
            raise RuntimeError("slmp-sim exited with %d: %s" % (process.returncode, log.read_text(errors="replace")))
        if time.monotonic() > deadline:
            process.kill()
            process.wait()
            raise RuntimeError("slmp-sim was not ready within %.0f s: %s" % (ready_timeout, log.read_text()))
        try:
            process.wait(0.02)
        except subprocess.TimeoutExpired:
            pass
    ports = json.loads(ready.read_text())
    sim = SlmpSim(ports["http"], tcp_port=ports["tcp"][0] if ports["tcp"] else None,
                  udp_port=ports["udp"][0] if ports["udp"] else None)
    return SimProcess(process, sim, workdir, log)
