#!/usr/bin/env bash
# The sanitizer build (scripts/test.sh runs it after the g++ suite): clang 14
# with ASan + UBSan (-DSLMP_FUZZ=ON, which implies -DSLMP_SANITIZE=ON) in
# build-asan; the unit suites built there; the integration suite of build/
# (g++) run against build-asan's slmp-sim, slmp and slmp-replay
# ($SLMP_BUILD_UNDER_TEST, tests/integration/sim_process.hpp) — the tests talk
# to those programs over sockets and pipes, so the programs are what must be
# sanitized, not the test binary; then every fuzz target for FUZZ_SECONDS
# (default 20) from its committed corpus. Needs the packages that
# scripts/setup.sh installs (clang, libclang-rt-14-dev). Exits non-zero on any
# failure, sanitizer report or fuzz finding (its reproducer is printed).
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${FUZZ_SECONDS:-20}

# -O0 with line tables only: stack traces keep file:line, and a heavy file
# compiles in 60 % of -O1's time (5.2 s against 8.5 s of CPU); CI builds this
# tree cold, so its compile time is most of the stage. The suites run slower
# (the bounds below are doubled) and the fuzzers make fewer executions in
# their FUZZ_SECONDS.
cmake -S . -B build-asan -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -gline-tables-only -DNDEBUG" -DSLMP_FUZZ=ON >/dev/null
# Only what runs below (not slmp-bench, which only loads the server, nor the
# integration test binary: build/'s runs).
cmake --build build-asan -j"$(nproc)" --target slmp-sim slmp slmp-replay slmp-unit-tests slmp-program-tests \
      slmp-face-tests fuzz-targets
[ -f build/CMakeCache.txt ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)" --target slmp-integration-tests

# Any report fails the test that hit it: UBSan stops at the first finding
# (-fno-sanitize-recover) and prints where; ASan's leak check runs at exit.
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:check_initialization_order=1
# Unit and integration only: the browser and interop tests exercise Chromium
# and node, not our code, and run in the g++ suite.
(cd build-asan && ctest --output-on-failure -j"$(nproc)" -R '^unit:')
asan_tree="$PWD/build-asan"
(cd build && SLMP_BUILD_UNDER_TEST="$asan_tree" SLMP_TEST_TIME_SCALE=2 \
   ctest --output-on-failure -j"$(nproc)" -R '^integration:' -LE '^(browser|interop)$')

status=0
# Every target in tests/fuzz/ (a list here once forgot fuzz_frontends).
for source in tests/fuzz/fuzz_*.cpp; do
  target=$(basename "$source" .cpp)
  scripts/fuzz.sh "$target" "$fuzz_seconds" || status=1
done
exit $status
