#!/usr/bin/env python3
"""How a plant's memory and start time scale (docs/plants.md, "Memory").

Starts build/server/slmp-sim with a plant of N stations of one profile (TCP on
any free port each, or on --first-port + 0, 1, ...; 127.0.0.1), then reports:
  start_s           from exec to the ready file (every station listening)
  start_cpu_s       CPU time (user + system, all threads) the process used until then:
                    the start's cost on a machine busy with other work
  rss_idle_mib      the process's RSS once ready, and per station
  private_dirty_idle_mib  its private dirty memory then (/proc/PID/smaps_rollup):
                    what the plant really costs, without the binary's shared pages
  cpu_idle_percent  CPU the idle plant uses over --idle-seconds (default 3), from
                    /proc/PID/stat (utime + stime); idle stations sleep (docs/timing.md,
                    "What wakes a station"), so this is what is left
  (--scenario-stations N: N of them run a scenario meanwhile, so scan every scan time)
  wakeups_per_s     scan-loop wake-ups a second over that time, summed over the stations
                    (GET /api/stations "wakeups"; absent from builds without it)
  rss_written_mib   RSS after K stations had every word of D, W, R, ZR and every
                    bit of M, B written non-zero over HTTP, and the growth per such station
Nothing is asserted: this is a measurement for closing notes.

  scripts/plant-memory.py --stations 1000 --profile R08CPU --written 10
"""
import argparse, json, os, subprocess, sys, tempfile, time, urllib.request

def rss_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0

def private_dirty_kib(pid):
    try:
        with open(f"/proc/{pid}/smaps_rollup") as f:
            for line in f:
                if line.startswith("Private_Dirty:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0

def cpu_ticks(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return int(fields[11]) + int(fields[12])

def total_wakeups(port):
    stations = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/api/stations"))
    if not stations or "wakeups" not in stations[0]:
        return None
    return sum(s["wakeups"] for s in stations)

def put(port, station, address, values, view):
    body = json.dumps({"values": values}).encode()
    url = f"http://127.0.0.1:{port}/api/stations/{station}/devices/{address}?as={view}"
    req = urllib.request.Request(url, data=body, method="PUT")
    urllib.request.urlopen(req).read()

def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--stations", type=int, default=1000)
    ap.add_argument("--profile", default="R08CPU")
    ap.add_argument("--written", type=int, default=10, help="stations whose devices are all written")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--first-port", type=int, default=0,
                    help="TCP ports FIRST, FIRST+1, ... (as a real plant's \"20000+i\"); default: any free port each, "
                         "which costs the kernel a search of its bind table per station (~35 s for 10 000)")
    ap.add_argument("--idle-seconds", type=float, default=3, help="how long idle CPU is measured")
    ap.add_argument("--scenario-stations", type=int, default=0,
                    help="stations s1..sN run a ramp scenario (they scan every scan time) while idle CPU is measured")
    ap.add_argument("--binary", default="build/server/slmp-sim")
    args = ap.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        config = {"bind": "127.0.0.1", "http": {"port": 0}, "log_level": "warn",
                  "stations": [{"template": {"profile": args.profile}, "count": args.stations,
                                "name": "s{i}",
                                "tcp_port": f"{args.first_port - 1}+i" if args.first_port else 0}]}
        path = os.path.join(tmp, "plant.json")
        with open(path, "w") as f:
            json.dump(config, f)
        ready = os.path.join(tmp, "ready.json")
        cmd = [args.binary, "--config", path, "--ready-file", ready]
        if args.threads:
            cmd += ["--threads", str(args.threads)]
        began = time.monotonic()
        proc = subprocess.Popen(cmd)
        try:
            while not os.path.exists(ready):
                if proc.poll() is not None:
                    sys.exit("slmp-sim exited before it was ready")
                time.sleep(0.005)
            start_s = time.monotonic() - began
            start_cpu_s = cpu_ticks(proc.pid) / os.sysconf("SC_CLK_TCK")
            with open(ready) as f:
                http = json.load(f)["http"]
            rss_idle = rss_kib(proc.pid)
            dirty_idle = private_dirty_kib(proc.pid)
            if args.scenario_stations:
                ramp = {"stations": [f"s{i}" for i in range(1, args.scenario_stations + 1)],
                        "scenario": {"name": "ramp", "timeline": {"steps": [
                            {"at_ms": 0, "ramp": "D0", "from": 0, "to": 1000, "over_ms": 600000}]}}}
                req = urllib.request.Request(f"http://127.0.0.1:{http}/api/plant/scenarios",
                                             data=json.dumps(ramp).encode(), method="POST")
                urllib.request.urlopen(req).read()
            wakeups = total_wakeups(http)
            ticks = cpu_ticks(proc.pid)
            time.sleep(args.idle_seconds)
            cpu_idle = (cpu_ticks(proc.pid) - ticks) / os.sysconf("SC_CLK_TCK") / args.idle_seconds * 100
            wakeups_after = total_wakeups(http)
            info = json.load(urllib.request.urlopen(f"http://127.0.0.1:{http}/api/stations/s1/info"))
            sizes = info["device_sizes"]
            for k in range(1, args.written + 1):
                for area, view in (("D", "words"), ("W", "words"), ("R", "words"), ("ZR", "words"),
                                   ("M", "bits"), ("B", "bits")):
                    size = sizes.get(area, 0)
                    for first in range(0, size, 32768):
                        n = min(32768, size - first)
                        start = f"{area}{first:X}" if area in ("W", "B") else f"{area}{first}"
                        put(http, f"s{k}", start, [1] * n, view)
            rss_written = rss_kib(proc.pid)
        finally:
            proc.terminate()
            proc.wait()
    print(json.dumps({
        "stations": args.stations, "profile": args.profile, "start_s": round(start_s, 2),
        "start_cpu_s": round(start_cpu_s, 2),
        "rss_idle_mib": round(rss_idle / 1024, 1),
        "rss_idle_kib_per_station": round(rss_idle / args.stations, 1),
        "private_dirty_idle_mib": round(dirty_idle / 1024, 1),
        "private_dirty_idle_kib_per_station": round(dirty_idle / args.stations, 1),
        "scenario_stations": args.scenario_stations,
        "cpu_idle_percent": round(cpu_idle, 1),
        "wakeups_per_s": None if wakeups is None else round((wakeups_after - wakeups) / args.idle_seconds, 1),
        "written_stations": args.written,
        "rss_written_mib": round(rss_written / 1024, 1),
        "rss_kib_per_written_station": round((rss_written - rss_idle) / max(1, args.written), 1),
    }, indent=1))

if __name__ == "__main__":
    main()
