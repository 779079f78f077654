#!/usr/bin/env bash
# scripts/instructions-per-request.sh [BINARY] [MIX] [CONNECTIONS] [slmp-bench options...]
#
# Server instructions per request, by valgrind's callgrind: slmp-sim runs under
# callgrind with instrumentation off until it listens, `slmp-bench` (default: 16
# connections of 1-word reads for 4 s, loopback) runs while it is on, and the
# total is divided by the requests sent. Unlike CPU time on a shared VM, the
# count repeats within a few per cent from run to run: use it to compare two
# builds of the request path (docs/bench.md, "Cheaper requests"). The profile is
# left in /tmp for callgrind_annotate. Needs valgrind; builds nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/server/slmp-sim}
mix=${2:-read1}
connections=${3:-16}
shift $(($# > 3 ? 3 : $#))
port=$((8000 + RANDOM % 1000))
out=$(mktemp /tmp/slmp-callgrind.XXXXXX)
valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$out" "$bin" --bind 127.0.0.1 \
    --tcp-port "$port" --udp-port "$port" --no-http --log-level warn --threads 2 >/dev/null 2>&1 &
sim=$!
sleep 3   # valgrind's start; the bench below fails loudly if the port is not open yet
callgrind_control -i on "$sim" >/dev/null 2>&1
report=$(build/tools/slmp-bench --port "$port" -c "$connections" --mix "$mix" --duration 4 --warmup 0 "$@" --json)
callgrind_control -i off "$sim" >/dev/null 2>&1
kill -INT "$sim"
wait "$sim" || true
python3 - "$out" "$report" <<'PY'
import json, sys
total = 0
for line in open(sys.argv[1]):
    if line.startswith(("summary:", "totals:")):
        total = int(line.split()[1])
sent = json.loads(sys.argv[2])["sent"]
print(f"{total / sent:.0f} instructions a request ({sent} requests; profile {sys.argv[1]})")
PY
