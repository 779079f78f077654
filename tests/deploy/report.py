"""One test's verdict: failed checks, skipped parts, and the exit code CTest reads.

A part that cannot run here (a tool is absent, the container runtime is
refused) is printed as "SKIPPED part: ..." with the reason; the test passes only
when every part that ran passed. exit 77 (CTest: skipped) is for a test that
cannot run at all, with the missing package named.
"""
import sys
import time

SKIP = 77


def skip_test(reason):
    print(f"SKIPPED: {reason}")
    sys.exit(SKIP)


class Report:
    def __init__(self):
        self.failures = []
        self.started = time.monotonic()

    def check(self, condition, message):
        """Records a failed check (and prints it) unless condition holds; returns condition."""
        if not condition:
            self.failures.append(message)
            print(f"FAIL: {message}")
        return condition

    def equal(self, actual, expected, what):
        if isinstance(actual, set) and isinstance(expected, set):
            return self.check(actual == expected, f"{what}: extra {sorted(actual - expected)}, "
                                                  f"missing {sorted(expected - actual)}")
        return self.check(actual == expected, f"{what}: got {actual!r}, expected {expected!r}")

    def skip_part(self, part, reason):
        print(f"SKIPPED part: {part}: {reason}")

    def timing(self, what, since):
        print(f"time: {what}: {time.monotonic() - since:.1f} s")

    def finish(self):
        self.timing("total", self.started)
        if self.failures:
            print(f"{len(self.failures)} check(s) failed")
            sys.exit(1)
        print("all checks passed")
        sys.exit(0)
