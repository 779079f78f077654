#!/usr/bin/env bash
# ThreadSanitizer over the threads of a plant (docs/plants.md, "Threads"):
# builds slmp-sim with -fsanitize=thread in build-tsan, then runs the
# integration tests of build/ against it ($SLMP_SIM_UNDER_TEST). A data race
# makes the simulator exit 66, which fails the test that started it.
# Not part of scripts/test.sh (a third full build would not fit CI's time);
# run it after changing anything that crosses threads. Default filter: the
# one-station threads test, the plant tests and the HTTP API tests; give a
# Catch2 filter to run others.
set -euo pipefail
cd "$(dirname "$0")/.."
filter=${1:-"[threads],[plant],[http]"}
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g -DNDEBUG" -DSLMP_TSAN=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build build-tsan -j"$(nproc)" --target slmp-sim
cmake --build build -j"$(nproc)" --target slmp-integration-tests slmp
export TSAN_OPTIONS="halt_on_error=1:exitcode=66:second_deadlock_stack=1"
# Start and stop bounds × 8: the instrumented binary starts a 200-station plant in
# 20–45 s (most of it system time: the sanitizer maps shadow memory for every store).
export SLMP_TEST_TIME_SCALE=8
SLMP_SIM_UNDER_TEST="$PWD/build-tsan/server/slmp-sim" build/tests/slmp-integration-tests "$filter"
