#!/usr/bin/env bash
# The sanitizer build (scripts/test.sh runs it after the g++ suite): clang 14
# with ASan + UBSan (-DSLMP_FUZZ=ON, which implies -DSLMP_SANITIZE=ON) in
# build-asan, the unit and integration suites, then every fuzz target for
# FUZZ_SECONDS (default 20) from its committed corpus. Needs the packages that
# scripts/setup.sh installs (clang, libclang-rt-14-dev). Exits non-zero on any
# failure, sanitizer report or fuzz finding (its reproducer is printed).
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${FUZZ_SECONDS:-20}

# -O1 with line tables only, as ASan's documentation suggests: stack traces keep
# file:line, and a heavy file compiled a quarter faster than at -O2 -g here (CI
# runs this build cold, so its compile time is most of the stage).
cmake -S . -B build-asan -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" -DSLMP_FUZZ=ON >/dev/null
# Only what runs below (slmp-bench is left out: nothing here runs it).
cmake --build build-asan -j"$(nproc)" --target slmp-unit-tests slmp-program-tests slmp-integration-tests fuzz-targets

# Any report fails the test that hit it: UBSan stops at the first finding
# (-fno-sanitize-recover) and prints where; ASan's leak check runs at exit.
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:check_initialization_order=1
# Unit and integration only: the browser and interop tests exercise Chromium
# and node, not our code, and run in the g++ suite.
(cd build-asan && ctest --output-on-failure -j"$(nproc)" -R '^(unit|integration):' -LE '^(browser|interop)$')

status=0
for target in fuzz_engine fuzz_fields fuzz_frame_prefix fuzz_config fuzz_scenario fuzz_http fuzz_program; do
  scripts/fuzz.sh "$target" "$fuzz_seconds" || status=1
done
exit $status
