#!/usr/bin/env bash
# scripts/soak.sh MINUTES [--keep] [--seed N] [--pace-ms MS] — runs slmp-sim for
# MINUTES under mixed load and checks it at the end. Not part of
# scripts/test.sh (it is for long local runs); `scripts/soak.sh 2` is a quick
# check, `scripts/soak.sh 30` the long run. Exits 0 when every check passed,
# 1 otherwise (the temporary directory with the simulator's log is kept), 2
# for a usage error. Builds slmp-sim and slmp-bench in build/ first (-j2,
# nice). Everything runs under nice and talks to 127.0.0.1 only.
#
# The simulator (an R08CPU, free loopback ports, a temporary directory):
#   --config: a Q62DA module at U3 (buffer memory), a state directory with a
#   snapshot every 5 s and restore "all"; --scenario: a looping timeline
#   (ramp, sine, random walk, square wave on D1000-D1006, M1100), rungs (MOV,
#   OUT T/C, SET/RST on compares), a traffic trigger that counts the writes to
#   D5000-D5099 in D1120 (int32), and faults that all match D9000-D9999 only:
#   end code C051 on 1401, FIN on 1402, no answer on 1406, 4031 on 0401, RST
#   on 0403, a corrupted answer on 0406, and delays, split and coalesced
#   answers on any command; --record: recording from the start.
#
# The load (scripts/soak.py, Python stdlib), each client with its own devices
# so that "the last acknowledged write" of every address is well defined:
#   batch-tcp    0401/1401 words (D5000-D5999), bits and bits-as-words (M7000-M7999); binary 3E/4E, Q and iQ-R forms
#   batch-udp    the same over UDP (D6000-D6999, B1000-B13FF), binary 3E/4E and ASCII 4E
#   batch-ascii  the same in ASCII over TCP (W1000-W17FF, M5000-M5999), 3E/4E
#   random       0403/1402 word, double-word and bit points (D7000-D7499, M6000-M6999)
#   block        0406/1406 word blocks (D7500-D7999) and bit blocks (B0-B3FF)
#   monitor      0801/0802 entry and execute monitor (D8000-D8199, M8000-M8255), registration per connection
#   buffer       0613/1613, 0601/1601 (03E0 and U3), U3E0\G (0082) and U3\G (0080): U3E0\G0-12287, U3\G0-4095
#   remote       0101, 0619, 1630, 1002 STOP / 1003 PAUSE / 1001 RUN with SD203 checked after each, SM50 error reset
#   chaos        every command above that the faults match, in D9000-D9999 (binary and ASCII, 3E and 4E)
#   slmp-bench   3 s bursts every 15 s: TCP and UDP, binary and ASCII, 3E and 4E, depth 8 (D0-D959, M0-M63)
#   http         every second: /api/devices, /api/state, /api/connections, /api/faults, /api/scenarios,
#                /api/recording, /api/buffer, /api/info, /metrics, and a PUT to D8500-D8599; every 30 s the
#                recording restarted (the closed file checked line by line) and a second scenario loaded or
#                stopped through /api/scenarios; /api/events read in 20 s sessions (a slow reader,
#                made to stop reading for 6 s twice during warm-up)
# Every client reconnects every 50-400 requests (UDP: a new socket). Not sent:
# 1005 Latch Clear and 1006 RESET (they clear memory, which would void the
# write check) and 1631 Lock (C810 without a password).
#
# Checks (any failure -> exit 1, each listed with examples under FAILED):
#   - every read during the load matches the last acknowledged write of its client;
#   - at the end every owned address (written or not) reads the last acknowledged
#     value, over SLMP and over HTTP, and again from the snapshot after a SIGTERM
#     and a restart (U3 module buffer memory is not part of the snapshot);
#     in D9000-D9999 a write is acknowledged or refused, never lost: a value the
#     faults refused is never visible;
#   - error counters only where faults were injected: for each drop or end-code
#     fault, times fired (/api/faults) = what the chaos client saw = the /metrics
#     counter of that command and end code; no other non-0000 end code in
#     slmp_requests_total, no unparsed frames, no error from the other clients or
#     from slmp-bench; every fault fired at least once (runs of 1 minute or more);
#   - RSS flat after warm-up: VmRSS sampled every 10 s; warm-up is 20 % of the run
#     or 1 minute, whichever is longer (at most half the run); growth from the end
#     of warm-up to the end must stay under 8 MiB or 10 % (see soak.py for why);
#     open file descriptors after the load = before it (+2);
#   - the scenario ran (the trigger counted exactly the acknowledged writes, the
#     rung MOV holds, the ramp moved), the CPU is in RUN with no remote hold and
#     no connection left open; SIGTERM exits 0 (twice); its log (info level) has
#     no warn, error or critical line.
#
# Output: progress once a minute, then a summary: requests per command family
# (sent, ok, other outcomes), slmp-bench bursts, the simulator's own count per
# command, HTTP/event/recording counts, addresses checked and mismatches, the
# fault table (matched, fired, client view, /metrics), RSS at idle, end of
# warm-up and end with the growth, slope and all samples, and PASS or FAIL.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ $# -lt 1 ] || ! [[ $1 =~ ^[0-9]+([.][0-9]+)?$ ]]; then
  echo "usage: scripts/soak.sh MINUTES [--keep] [--seed N] [--pace-ms MS]" >&2
  exit 2
fi
minutes=$1
shift

if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
# -j2 at most: the machine's two cores are shared.
nice cmake --build build --target slmp-sim slmp-bench -j"$(( $(nproc) < 2 ? $(nproc) : 2 ))" >/dev/null

exec nice python3 scripts/soak.py --minutes "$minutes" --build build "$@"
