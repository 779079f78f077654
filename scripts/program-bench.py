#!/usr/bin/env python3
"""Host time per executed PLC instruction, measured on the real binary.

Generates a program of about --steps instructions mixing contacts, coils, MOV,
+, compare contacts and timers (the mix of docs/bench.md "Program execution"),
starts slmp-sim on a frozen clock twice — with the program and with an empty
one (END only) — steps --scans scans through POST /api/clock/step in each, and
reads the process's CPU time from /proc/PID/stat before and after. The
difference, divided by the instructions executed (GET /api/program's
executed_last × scans), is the host cost of one instruction; the scan loop,
the runtime's END processing and the HTTP request are in both runs and cancel.

    python3 scripts/program-bench.py [--binary build/server/slmp-sim] [--steps 10000] [--scans 20000] [--rounds 3]
"""
import argparse
import json
import os
import subprocess
import tempfile
import time
import urllib.request


def generate(steps):
    """Rungs of ~10 instructions until `steps` instructions are written."""
    lines, n, rung = [], 0, 0
    while n < steps:
        r = rung % 4
        m, d, t = rung % 4000, rung % 4000, rung // 4   # one timer a timer rung (no double coils)
        if r == 0:    # contacts and a coil
            lines += [f"LD X{m % 256:X}", f"AND M{m}", f"ORI M{m + 1}", f"ANI X{(m + 1) % 256:X}", f"OUT M{m + 4000}"]
        elif r == 1:  # word moves and arithmetic
            lines += ["LD SM400", f"MOV K{rung} D{d}", f"+ D{d} K1 D{d + 4000}", f"MOV D{d + 4000} D{d + 1}"]
        elif r == 2:  # compare contacts
            lines += [f"LD> D{d} K100", f"AND<= D{d + 1} K200", f"OUT M{m + 8000}"]
        else:         # a timer
            lines += [f"LD M{m}", f"OUT T{t} K10", f"LD T{t}", f"OUT Y{t % 256:X}"]
        n = len(lines)
        rung += 1
    return "\n".join(lines + ["END"]) + "\n"


def http(port, method, path, body=None):
    data = None if body is None else json.dumps(body).encode()
    req = urllib.request.Request(f"http://127.0.0.1:{port}{path}", data=data, method=method)
    with urllib.request.urlopen(req, timeout=600) as response:
        return json.loads(response.read())


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def run(binary, program_file, scans, workdir):
    ready = os.path.join(workdir, "ready.json")
    if os.path.exists(ready):
        os.remove(ready)
    proc = subprocess.Popen([binary, "--clock", "frozen", "--program", program_file, "--tcp-port", "0", "--udp-port", "0",
                             "--http-port", "0", "--threads", "1", "--log-level", "warn", "--ready-file", ready],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.time() + 30
        while not os.path.exists(ready):
            if time.time() > deadline or proc.poll() is not None:
                raise SystemExit("slmp-sim did not start with " + program_file)
            time.sleep(0.05)
        port = json.load(open(ready))["http"]
        http(port, "POST", "/api/clock/step", {"scans": 10})    # warm: first scans, caches
        before = cpu_seconds(proc.pid)
        http(port, "POST", "/api/clock/step", {"scans": scans})
        after = cpu_seconds(proc.pid)
        executed = http(port, "GET", "/api/program")["executed_last"]
        return after - before, executed
    finally:
        proc.terminate()
        proc.wait(timeout=30)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--binary", default="build/server/slmp-sim")
    p.add_argument("--steps", type=int, default=10000)
    p.add_argument("--scans", type=int, default=20000)
    p.add_argument("--rounds", type=int, default=3)
    a = p.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        full = os.path.join(workdir, "bench.il")
        empty = os.path.join(workdir, "empty.il")
        open(full, "w").write(generate(a.steps))
        open(empty, "w").write("END\n")
        results = []
        for _ in range(a.rounds):
            with_program, executed = run(a.binary, full, a.scans, workdir)
            without, _ = run(a.binary, empty, a.scans, workdir)
            ns = (with_program - without) * 1e9 / (executed * a.scans)
            results.append(ns)
            print(f"round: {executed} instructions a scan, {a.scans} scans: with program {with_program:.3f} s CPU, "
                  f"without {without:.3f} s CPU -> {ns:.2f} ns per executed instruction")
        print(json.dumps({"instructions_per_scan": executed, "scans": a.scans,
                          "ns_per_instruction_best": round(min(results), 2),
                          "ns_per_instruction_median": round(sorted(results)[len(results) // 2], 2),
                          "us_per_scan_best": round(min(results) * executed / 1000, 1)}))


if __name__ == "__main__":
    main()
