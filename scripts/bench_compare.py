"""slmp-sim against the baseline server, workload by workload (scripts/bench-compare.sh).

Starts `slmp-bench --baseline-server` and slmp-sim (a plant of --stations R08CPU
stations on --threads threads, with a profile that lifts the commands-per-connection
limit so deep pipelining is served rather than answered CEE0), runs each workload of
the plant issue against both with `slmp-bench --json --server-pid`, and prints one
Markdown table: requests per second, server CPU per request and p99 latency of each,
with the simulator's share of the baseline. Connections to the simulator are spread
over its stations with --targets; the baseline serves all of them on one port.

Each round runs every workload on both servers, the order alternating between rounds
so a drift in the machine's load falls on both; the table gives the median of the
rounds. Standard library only. Exit status: 0, 1 when a run failed or counted errors
(the table says which), 2 for a usage error.
"""

import argparse
import datetime
import json
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time

WORKLOADS = [
    # (name in the table, slmp-bench arguments, TCP or UDP)
    ("16 connections, 1-word read", ["-c", "16", "--mix", "read1"], "tcp"),
    ("64 connections × 8 pipelined 4E", ["-c", "64", "--4e", "-d", "8", "--mix", "read1"], "tcp"),
    ("16 connections, 960-word read", ["-c", "16", "--mix", "read960"], "tcp"),
    ("16 UDP sockets, 1-word read", ["--udp", "-c", "16", "--mix", "read1"], "udp"),
    ("1 connection, 1-word read (p99)", ["-c", "1", "--mix", "read1"], "tcp"),
]

# R08CPU as the simulator serves it by default, without its commands-per-connection
# limit (docs/end-codes.md): with 64 connections an R08CPU serves 1 + 32 / 64 = 1
# request of a pipelined burst and answers the rest CEE0. "buffer": 0 is no limit.
PROFILE = {
    "name": "R08CPU-bench",
    "extends": "R08CPU",
    "description": "R08CPU without the commands-per-connection limit (scripts/bench-compare.sh)",
    "pipeline": {"buffer": 0},
}


def parse_args():
    p = argparse.ArgumentParser(prog="scripts/bench-compare.sh", description=__doc__.split("\n\n")[0])
    p.add_argument("--duration", type=float, default=5.0, help="seconds measured per run (default 5)")
    p.add_argument("--warmup", type=float, default=0.5, help="seconds of load before measuring (default 0.5)")
    p.add_argument("--rounds", type=int, default=1, help="rounds of every workload on both servers; medians (default 1)")
    p.add_argument("--threads", type=int, default=2, help="threads of both servers (default 2)")
    p.add_argument("--stations", type=int, default=2,
                   help="stations of the simulator's plant, the connections spread over them (default 2; "
                        "1 = one station, which one thread serves)")
    p.add_argument("--only", default="", help="comma list of workload numbers (1-5) to run")
    p.add_argument("--build", default="build", help="build directory (default build)")
    p.add_argument("--json", dest="json_out", default="", help="also write every run's slmp-bench JSON here")
    a = p.parse_args()
    if a.duration <= 0 or a.warmup < 0 or a.rounds < 1 or a.threads < 1 or a.stations < 1:
        p.error("--duration above 0, --warmup not negative, --rounds, --threads and --stations at least 1")
    try:
        a.only = [int(n) for n in a.only.split(",") if n] or list(range(1, len(WORKLOADS) + 1))
    except ValueError:
        p.error("--only: workload numbers, e.g. 1,3")
    if any(n < 1 or n > len(WORKLOADS) for n in a.only):
        p.error("--only: workload numbers are 1-%d" % len(WORKLOADS))
    return a


class Server:
    """A server process started with --ready-file; its ports read from that file."""

    def __init__(self, name, argv, workdir):
        self.name = name
        self.ready_file = os.path.join(workdir, name + "-ready.json")
        self.log_path = os.path.join(workdir, name + ".log")
        self.log = open(self.log_path, "w")
        self.process = subprocess.Popen(argv + ["--ready-file", self.ready_file], stdout=self.log,
                                        stderr=subprocess.STDOUT)
        deadline = time.monotonic() + 15
        while True:
            if self.process.poll() is not None:
                raise RuntimeError("%s exited (%d) before it was ready; see %s:\n%s"
                                   % (name, self.process.returncode, self.log_path, open(self.log_path).read()))
            try:
                with open(self.ready_file) as f:
                    self.ready = json.load(f)
                break
            except (OSError, ValueError):
                pass
            if time.monotonic() > deadline:
                self.stop()
                raise RuntimeError("%s wrote no ready file within 15 s; see %s" % (name, self.log_path))
            time.sleep(0.05)   # waiting for a process to start, not synchronising a test

    def stop(self):
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.log.close()


def start_servers(a, workdir):
    bench = os.path.join(a.build, "tools", "slmp-bench")
    sim = os.path.join(a.build, "server", "slmp-sim")
    profile = os.path.join(workdir, "R08CPU-bench.json")
    with open(profile, "w") as f:
        json.dump(PROFILE, f)
    plant = {
        "bind": "127.0.0.1",
        "log_level": "warn",
        "threads": a.threads,
        "stations": [{"template": {"profile": profile}, "count": a.stations, "name": "bench-{i}",
                      "tcp_port": 0, "udp_port": 0}],
    }
    config = os.path.join(workdir, "plant.json")
    with open(config, "w") as f:
        json.dump(plant, f)
    baseline = Server("baseline", [bench, "--baseline-server", "--threads", str(a.threads), "--tcp-port", "0",
                                   "--udp-port", "0"], workdir)
    try:
        simulator = Server("slmp-sim", [sim, "--config", config, "--no-http", "--max-connections", "1024",
                                        "--idle-timeout", "0"], workdir)
    except Exception:
        baseline.stop()
        raise
    return baseline, simulator


def targets(server, transport):
    """slmp-bench arguments that address `server` over `transport`."""
    if "stations" in server.ready:
        ports = [s[transport][0] for s in server.ready["stations"]]
        return ["--targets", ",".join("127.0.0.1:%d" % p for p in ports)]
    return ["--port", str(server.ready[transport][0])]


def run_one(a, server, workload):
    name, args, transport = workload
    argv = [os.path.join(a.build, "tools", "slmp-bench")] + targets(server, transport) + args + [
        "--duration", str(a.duration), "--warmup", str(a.warmup), "--json",
        "--server-pid", str(server.ready["pid"])]
    done = subprocess.run(argv, capture_output=True, text=True, timeout=a.duration + a.warmup + 60)
    try:
        result = json.loads(done.stdout)
    except ValueError:
        result = {"fatal": "no JSON from slmp-bench (exit %d): %s" % (done.returncode, done.stderr.strip())}
    result["exit_code"] = done.returncode
    result["server"] = server.name
    result["workload"] = name
    return result


def summary(runs):
    """Medians over the rounds of one workload on one server."""
    def median(get):
        values = [get(r) for r in runs if r.get("cpu") and "total" in r]
        return statistics.median(values) if values else None
    return {
        "rps": median(lambda r: r["total"]["requests_per_s"]),
        "cpu_us": median(lambda r: r["cpu"]["server_us_per_request"]),
        "p99": median(lambda r: r["total"]["latency_us"]["p99"]),
        "client_cores": median(lambda r: r["cpu"]["client_cores"]),
        "problems": [problem(r) for r in runs if problem(r)],
    }


def problem(r):
    if r.get("fatal"):
        return r["fatal"]
    errors = r.get("total", {}).get("errors", {}).get("total", 0)
    if errors:
        return "%d errors %s" % (errors, json.dumps(r["total"]["end_codes"]) if r["total"]["end_codes"] else "")
    if r["exit_code"] != 0:
        return "slmp-bench exit %d" % r["exit_code"]
    if r.get("cpu") is None:
        return "server CPU not measured"
    return ""


def fmt(value, pattern):
    return "—" if value is None else pattern % value


def ratio(sim, base):
    return "—" if not sim or not base else "%.2f" % (sim / base)


def print_table(a, results, started, load_before):
    rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    print("slmp-sim vs baseline server — %s, commit %s, %d CPU(s), load average %s before, %s after"
          % (started, rev or "?", os.cpu_count() or 0, load_before, "%.2f" % os.getloadavg()[0]))
    print("both servers %d thread(s); slmp-sim a plant of %d R08CPU station(s), no pipelining limit; "
          "%g s runs after %g s warm-up; median of %d round(s)\n" % (a.threads, a.stations, a.duration, a.warmup, a.rounds))
    print("| workload | baseline req/s | sim req/s | ratio | baseline CPU µs/req | sim CPU µs/req | ratio "
          "| baseline p99 µs | sim p99 µs |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    notes = []
    for number in a.only:
        name = WORKLOADS[number - 1][0]
        b, s = results[(name, "baseline")], results[(name, "slmp-sim")]
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, fmt(b["rps"], "%.0f"), fmt(s["rps"], "%.0f"), ratio(s["rps"], b["rps"]),
            fmt(b["cpu_us"], "%.1f"), fmt(s["cpu_us"], "%.1f"), ratio(s["cpu_us"], b["cpu_us"]),
            fmt(b["p99"], "%.0f"), fmt(s["p99"], "%.0f")))
        for who, r in (("baseline", b), ("slmp-sim", s)):
            notes += ["%s, %s: %s" % (name, who, p) for p in r["problems"]]
            if r["client_cores"] is not None and r["client_cores"] > 0.9:
                notes.append("%s, %s: slmp-bench used %.2f cores — the client was (near) saturated"
                             % (name, who, r["client_cores"]))
    print("\nratio = slmp-sim ÷ baseline (req/s: higher is better; CPU: lower is better). "
          "CPU = the server's user + system time per answered request (/proc/PID/stat).")
    for note in notes:
        print("- " + note)
    return not any(r["problems"] for r in results.values())


def main():
    a = parse_args()
    started = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    load_before = "%.2f" % os.getloadavg()[0]
    all_runs = []
    with tempfile.TemporaryDirectory(prefix="bench-compare-") as workdir:
        try:
            baseline, simulator = start_servers(a, workdir)
        except RuntimeError as e:
            print("bench-compare: %s" % e, file=sys.stderr)
            return 1
        try:
            for round_index in range(a.rounds):
                servers = [baseline, simulator] if round_index % 2 == 0 else [simulator, baseline]
                for number in a.only:
                    for server in servers:
                        result = run_one(a, server, WORKLOADS[number - 1])
                        all_runs.append(result)
                        print("round %d, %s, %s: %s req/s" % (round_index + 1, result["workload"], server.name,
                                                              fmt(result.get("total", {}).get("requests_per_s"), "%.0f")),
                              file=sys.stderr)
        finally:
            baseline.stop()
            simulator.stop()
    if a.json_out:
        with open(a.json_out, "w") as f:
            json.dump(all_runs, f, indent=1)
    results = {}
    for number in a.only:
        name = WORKLOADS[number - 1][0]
        for who in ("baseline", "slmp-sim"):
            results[(name, who)] = summary([r for r in all_runs if r["workload"] == name and r["server"] == who])
    return 0 if print_table(a, results, started, load_before) else 1


if __name__ == "__main__":
    sys.exit(main())
