#!/usr/bin/env bash
# scripts/fuzz.sh TARGET SECONDS — runs one libFuzzer target (tests/fuzz/) for
# SECONDS on a copy of its committed corpus with its dictionary
# (tests/fuzz/<target>.dict if there is one, else tests/fuzz/slmp.dict). Builds
# build-asan (clang, ASan + UBSan, SLMP_FUZZ=ON) first if needed. Prints the
# executions and whether anything was found; on a crash exits non-zero and
# prints the sanitizer report, the reproducer's path and a hexdump of it.
# Targets: fuzz_engine fuzz_fields fuzz_frame_prefix fuzz_config fuzz_scenario fuzz_http fuzz_frontends fuzz_program
# Re-run a reproducer: build-asan/tests/fuzz/TARGET path/to/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."

if [ $# -ne 2 ] || ! [[ $2 =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh TARGET SECONDS   (TARGET: $(ls tests/fuzz/corpus | tr '\n' ' '))" >&2
  exit 2
fi
target=$1 seconds=$2
if [ ! -d "tests/fuzz/corpus/$target" ]; then
  echo "fuzz: no target '$target' (no tests/fuzz/corpus/$target)" >&2
  exit 2
fi

if [ ! -f build-asan/CMakeCache.txt ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DSLMP_FUZZ=ON >/dev/null
fi
# -j2 at most: the machine's two cores are shared.
cmake --build build-asan --target "$target" -j"$(( $(nproc) < 2 ? $(nproc) : 2 ))" >/dev/null

work=$(mktemp -d "${TMPDIR:-/tmp}/slmp-fuzz-$target.XXXXXX")
cp -r "tests/fuzz/corpus/$target" "$work/corpus"
mkdir "$work/artifacts"
log="$work/fuzz.log"
dict=tests/fuzz/slmp.dict
[ -f "tests/fuzz/$target.dict" ] && dict="tests/fuzz/$target.dict"

# -timeout: an input that takes 10 s is a hang worth reporting (the default is 20 min).
set +e
"build-asan/tests/fuzz/$target" "$work/corpus" -dict="$dict" -max_total_time="$seconds" \
  -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/artifacts/" >"$log" 2>&1
rc=$?
set -e

execs=$(awk '/stat::number_of_executed_units/ {print $2}' "$log" | tail -1)
found=$(find "$work/artifacts" -type f | sort)
if [ $rc -ne 0 ] || [ -n "$found" ]; then
  echo "fuzz: $target FOUND A PROBLEM (exit $rc) after ${execs:-?} executions; the report:"
  grep -v -E '^#[0-9]+\s+(NEW|REDUCE|pulse|INITED)' "$log" | tail -n 80
  for f in $found; do
    echo "fuzz: reproducer $f ($(stat -c %s "$f") bytes):"
    od -A x -t x1z -v "$f" | head -n 64
  done
  echo "fuzz: re-run with: build-asan/tests/fuzz/$target $found"
  exit 1
fi
echo "fuzz: $target: ${execs:-?} executions in ${seconds} s, nothing found" \
     "(corpus $(ls "tests/fuzz/corpus/$target" | wc -l) -> $(ls "$work/corpus" | wc -l) inputs; log $log)"
