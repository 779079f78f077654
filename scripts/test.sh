#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, integration
# against the real binary, and interop with third-party clients), then the
# sanitizer build with its fuzz runs (scripts/test-sanitizers.sh). Exits
# non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cd build
# Integration tests drive a real server process over sockets; on a loaded
# machine one retry absorbs a scheduling hiccup. A test that fails twice fails
# the run.
ctest --output-on-failure -j"$(nproc)" --repeat until-pass:2
cd ..
# The same unit and integration suites under clang's ASan + UBSan, and each
# fuzz target for a bounded time.
scripts/test-sanitizers.sh
