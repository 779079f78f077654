"""``python3 -m slmp_sim`` — the kit's command line for scripts and CI steps (docs/ci.md).

  python3 -m slmp_sim [--host H] [--http-port N] snapshot NAME [--file F]
  python3 -m slmp_sim restore NAME [--drop-connections] | reset [--drop-connections] | snapshots
  python3 -m slmp_sim clock [frozen | realtime [--speed X] | step (--scans N | --ms T)]
  python3 -m slmp_sim wait DEVICE (--equals N | --not-equals N | --greater N | --less N | --changes) [--timeout-ms T]
  python3 -m slmp_sim get DEVICE [--count N] | set DEVICE VALUE... | save NAME FILE

Prints the API's JSON answer; exit 0, 1 when the API refused (its message on stderr), 3 when a wait timed out.
"""
import argparse
import json
import sys

from .client import SlmpSim, SlmpSimError, WaitTimeout


def _parser():
    p = argparse.ArgumentParser(prog="python3 -m slmp_sim", description="drive slmp-sim's HTTP API")
    p.add_argument("--host", default="127.0.0.1")
    p.add_argument("--http-port", type=int, default=8080)
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("snapshot", help="take a station snapshot")
    s.add_argument("name")
    s.add_argument("--file", help="also write its file form here (on the simulator's side)")
    sub.add_parser("snapshots", help="list the snapshots")
    s = sub.add_parser("save", help="download a snapshot's file form (for --snapshot)")
    s.add_argument("name")
    s.add_argument("file")
    for name in ("restore", "reset"):
        s = sub.add_parser(name, help=name + " the station")
        if name == "restore":
            s.add_argument("name")
        s.add_argument("--drop-connections", action="store_true")
    s = sub.add_parser("clock", help="show, freeze, run or step the CPU clock")
    s.add_argument("mode", nargs="?", choices=["frozen", "realtime", "step"])
    s.add_argument("--speed", type=float)
    s.add_argument("--scans", type=int)
    s.add_argument("--ms", type=float)
    s = sub.add_parser("wait", help="wait for a device value")
    s.add_argument("device")
    for option in ("equals", "not-equals", "greater", "less"):
        s.add_argument("--" + option, type=int)
    s.add_argument("--changes", action="store_true")
    s.add_argument("--timeout-ms", type=int, default=10000)
    s = sub.add_parser("get", help="read devices")
    s.add_argument("device")
    s.add_argument("--count", type=int, default=1)
    s = sub.add_parser("set", help="write devices")
    s.add_argument("device")
    s.add_argument("values", nargs="+", type=int)
    return p


def _run(a, sim):
    if a.command == "snapshot":
        return sim.snapshot(a.name, a.file)
    if a.command == "snapshots":
        return sim.snapshots()
    if a.command == "save":
        data = sim.request("GET", "/api/snapshots/%s/file" % a.name)
        with open(a.file, "wb") as out:
            out.write(data)
        return {"saved": a.name, "file": a.file, "bytes": len(data)}
    if a.command == "restore":
        return sim.restore(a.name, a.drop_connections)
    if a.command == "reset":
        return sim.reset(a.drop_connections)
    if a.command == "clock":
        if a.mode == "frozen":
            return sim.clock.freeze()
        if a.mode == "realtime":
            return sim.clock.realtime(a.speed)
        if a.mode == "step":
            return sim.clock.step(scans=a.scans, ms=a.ms)
        return sim.clock.get()
    if a.command == "wait":
        return {"value": sim.wait(a.device, equals=a.equals, not_equals=a.not_equals, greater=a.greater, less=a.less,
                                  changes=a.changes, timeout_ms=a.timeout_ms)}
    if a.command == "get":
        return sim.get(a.device, count=a.count)
    if a.command == "set":
        return sim.set(a.device, a.values)
    raise AssertionError(a.command)


def main(argv=None):
    a = _parser().parse_args(argv)
    sim = SlmpSim(a.http_port, host=a.host)
    try:
        print(json.dumps(_run(a, sim)))
        return 0
    except WaitTimeout as e:
        print("slmp_sim: %s" % e.message, file=sys.stderr)
        return 3
    except SlmpSimError as e:
        print("slmp_sim: %s" % e.message, file=sys.stderr)
        return 1
    except ValueError as e:
        print("slmp_sim: %s" % e, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
