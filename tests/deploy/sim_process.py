"""slmp-sim started by any command line (directly, in a chroot, in a network
namespace), waited for through its --ready-file, stopped with SIGTERM.

The ready file is written atomically once every port listens, so waiting for it
is the readiness signal; the bound (generous) only matters for a broken build.
"""
import json
import os
import signal
import subprocess
import time

READY_WITHIN_S = 15
STOP_WITHIN_S = 30


class SimProcess:
    def __init__(self, command, ready_file, log_file):
        """ready_file is the host's path of the file the command writes."""
        self.ready_file = ready_file
        self.log_file = log_file
        self.log = open(log_file, "wb")
        if os.path.exists(ready_file):
            os.remove(ready_file)
        print("start:", " ".join(command))
        self.process = subprocess.Popen(command, stdout=self.log, stderr=subprocess.STDOUT)

    def wait_ready(self):
        """The ready file's JSON; raises with the log when the process dies or never gets ready."""
        deadline = time.monotonic() + READY_WITHIN_S
        while not os.path.exists(self.ready_file):
            if self.process.poll() is not None:
                raise RuntimeError(f"slmp-sim exited with {self.process.returncode} before it was ready:\n{self.output()}")
            if time.monotonic() > deadline:
                raise RuntimeError(f"no ready file after {READY_WITHIN_S} s:\n{self.output()}")
            time.sleep(0.05)
        with open(self.ready_file) as f:
            return json.load(f)

    def stop(self):
        """SIGTERM, then the exit code (a clean shutdown is 0)."""
        self.process.send_signal(signal.SIGTERM)
        try:
            return self.process.wait(timeout=STOP_WITHIN_S)
        finally:
            self.log.close()

    def kill(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        self.log.close()

    def output(self):
        self.log.flush()
        with open(self.log_file, "rb") as f:
            return f.read().decode(errors="replace")
