#!/usr/bin/env bash
# scripts/bench-compare.sh [--duration S] [--warmup S] [--rounds N] [--threads N]
#                          [--stations N] [--only 1,3] [--build DIR] [--json FILE]
#
# slmp-sim against `slmp-bench --baseline-server` (the machine's ceiling) on the
# plant issue's workloads, printed as one Markdown table: req/s, server CPU µs per
# request and p99 of each, and slmp-sim's ratio to the baseline (docs/bench.md,
# "Comparing with the baseline"). Workloads: 16 connections 1-word reads; 64
# connections x 8 pipelined 4E; 16 connections 960-word reads; 16 UDP sockets;
# 1 connection (p99). Both servers get --threads threads (default 2); slmp-sim is
# a plant of --stations R08CPU stations (default 2) whose profile lifts the
# commands-per-connection limit, and the connections are spread over them.
#
# Builds slmp-sim and slmp-bench in DIR first (-j1: the cores are shared). Talks
# to 127.0.0.1 only. Exit status 0; 1 when a run failed or counted errors; 2 for
# a usage error. The work is done by scripts/bench_compare.py (standard library).
set -euo pipefail
cd "$(dirname "$0")/.."

build=build
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  if [ "${args[i]}" = "--build" ] && [ $((i + 1)) -lt ${#args[@]} ]; then build=${args[i + 1]}; fi
  if [[ ${args[i]} == --build=* ]]; then build=${args[i]#--build=}; fi
done

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$build" --target slmp-sim slmp-bench -j1 >/dev/null

exec python3 scripts/bench_compare.py "$@"
