#!/usr/bin/env python3
"""scripts/slowloris.py [--half N] [--garbage N] [--build DIR] [--sim-arg=ARG ...] — the slowloris
measurement of issue 16 (docs/testing.md, "Slow and hostile clients").

Starts slmp-sim with its default port settings (the R08CPU profile's 16 connections per port, 5 s
partial-frame timeout, 300 s idle timeout) on free loopback ports, then:
  1. baseline: slmp-bench, 1 connection, 5 s of 1-word reads -> p99;
  2. attack: M garbage frames (default 10000) on short connections, then N
     connections (default 1000) that each send 4 bytes of a 3E header and wait;
  3. a well-behaved client (loopback 0619) tries to connect and be answered
     from the moment the attack is in place; the time until it is served;
  4. during: slmp-bench for 2 s while the half-frame connections are open
     (reported, no bound);
  5. after: once the partial-frame timeout has closed them, slmp-bench again
     -> p99, compared with the baseline (bound: 2x).
Prints one line per step and exits non-zero when the client was not served
within the partial-frame timeout plus a margin, or the p99 bound is broken.
Talks only to 127.0.0.1. Raises its own open-file limit to fit N sockets.
"""
import argparse
import json
import os
import random
import resource
import socket
import subprocess
import sys
import tempfile
import time

PARTIAL_FRAME_TIMEOUT_S = 5.0   # slmp-sim's default (docs/configuration.md)


def loopback_request(data: bytes) -> bytes:
    body = bytes([0x10, 0x00, 0x19, 0x06, 0x00, 0x00, len(data), 0]) + data
    return bytes([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, len(body) & 0xFF, len(body) >> 8]) + body


def served(port: int, timeout: float = 1.0) -> bool:
    """One loopback round trip on a new connection; True when answered with end code 0000."""
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
            s.sendall(loopback_request(b"PING"))
            reply = b""
            while len(reply) < 11:
                chunk = s.recv(64)
                if not chunk:
                    return False
                reply += chunk
            return reply[0] == 0xD0 and reply[9:11] == b"\x00\x00"
    except OSError:
        return False


def garbage_frame(rng: random.Random) -> bytes:
    kind = rng.randrange(4)
    if kind == 0:   # random bytes
        return bytes(rng.randrange(256) for _ in range(rng.randrange(1, 64)))
    if kind == 1:   # a 3E header with a wrong length, then junk
        return bytes([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x02, 0x00, 0x10, 0x00, 0x99, 0x99])
    if kind == 2:   # an unknown command in a well-formed frame
        return bytes([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x06, 0x00, 0x10, 0x00, 0xEE, 0xEE, 0x00, 0x00])
    return b"5000" + bytes(rng.randrange(0x30, 0x47) for _ in range(rng.randrange(4, 40)))   # broken ASCII


def send_garbage(port: int, count: int, rng: random.Random) -> tuple[int, int]:
    """Sends `count` garbage frames, 10 per connection; returns (frames sent, connections refused)."""
    sent = refused = 0
    while sent < count and refused < count:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=1.0) as s:
                for _ in range(min(10, count - sent)):
                    s.sendall(garbage_frame(rng))
                    sent += 1
        except OSError:
            refused += 1   # refused or reset: the port is full, or the server closed it mid-way
    return sent, refused


def bench(bench_bin: str, port: int, seconds: float = 5) -> float:
    out = subprocess.run([bench_bin, "--port", str(port), "--duration", str(seconds), "--json"],
                         check=True, capture_output=True, text=True).stdout
    return float(json.loads(out)["total"]["latency_us"]["p99"])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--half", type=int, default=1000, help="half-frame connections (default 1000)")
    parser.add_argument("--garbage", type=int, default=10000, help="garbage frames (default 10000)")
    parser.add_argument("--build", default="build", help="build directory (default build)")
    parser.add_argument("--sim-arg", action="append", default=[],
                        help="an extra slmp-sim argument, repeatable (e.g. --sim-arg=--max-connections=2000)")
    args = parser.parse_args()

    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    resource.setrlimit(resource.RLIMIT_NOFILE, (min(hard, max(soft, args.half + 256)), hard))

    sim_bin = os.path.join(args.build, "server", "slmp-sim")
    bench_bin = os.path.join(args.build, "tools", "slmp-bench")
    with tempfile.TemporaryDirectory() as tmp:
        ready = os.path.join(tmp, "ready.json")
        sim = subprocess.Popen([sim_bin, "--bind", "127.0.0.1", "--tcp-port", "0", "--udp-port", "0", "--no-http",
                                "--log-level", "error", "--ready-file", ready] + args.sim_arg)
        try:
            deadline = time.monotonic() + 10
            while not os.path.exists(ready):
                if time.monotonic() > deadline or sim.poll() is not None:
                    print("slowloris: slmp-sim did not start", file=sys.stderr)
                    return 1
                time.sleep(0.05)
            port = json.load(open(ready))["tcp"][0]

            baseline = bench(bench_bin, port)
            print(f"baseline: p99 {baseline:.1f} us (slmp-bench, 1 connection, 5 s of read1)")

            rng = random.Random(16)
            started = time.monotonic()
            # Garbage first, while the port has free slots, so the frames reach the server.
            sent, refused = send_garbage(port, args.garbage, rng)
            half, half_started = [], time.monotonic()
            for _ in range(args.half):
                try:
                    s = socket.create_connection(("127.0.0.1", port), timeout=0.5)
                    s.sendall(loopback_request(b"HALF")[:4])
                    half.append(s)
                except OSError:
                    pass   # refused: the port is at its connection limit
            attack_s = time.monotonic() - started
            print(f"attack: {sent} garbage frames sent ({refused} connection(s) refused or reset), then "
                  f"{len(half)} of {args.half} half-frame connections accepted by the kernel, in {attack_s:.1f} s")

            # The well-behaved client, from the moment the attack is in place.
            attack_done = time.monotonic()
            while not served(port):
                if time.monotonic() - attack_done > PARTIAL_FRAME_TIMEOUT_S + 10:
                    print("slowloris: FAIL: the client was not served within the partial-frame timeout + 10 s")
                    return 1
                time.sleep(0.05)
            waited = time.monotonic() - attack_done
            print(f"client: served {waited:.2f} s after the attack (partial-frame timeout {PARTIAL_FRAME_TIMEOUT_S:.0f} s)")

            during = bench(bench_bin, port, 2)
            print(f"during: p99 {during:.1f} us while the half-frame connections are open (2 s, no bound)")

            # Afterwards: once the partial-frame timeout has closed every half-frame connection.
            time.sleep(max(0.0, half_started + PARTIAL_FRAME_TIMEOUT_S + 1 - time.monotonic()))
            after = bench(bench_bin, port)
            ratio = after / baseline if baseline > 0 else float("inf")
            print(f"after: p99 {after:.1f} us = {ratio:.2f}x the baseline (bound 2x)")
            for s in half:
                s.close()
            if ratio > 2.0:
                print("slowloris: FAIL: p99 after the attack is over 2x the baseline")
                return 1
            print("slowloris: PASS")
            return 0
        finally:
            sim.terminate()
            sim.wait(timeout=10)


if __name__ == "__main__":
    sys.exit(main())
