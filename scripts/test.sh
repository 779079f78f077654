#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (unit, integration
# against the real binary, and interop with third-party clients), then the
# sanitizer build with its fuzz runs (scripts/test-sanitizers.sh). Exits
# non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cd build
# No retries: a test that fails once fails the run. Tests wait for explicit
# readiness (ready files, values, closes) with generous upper bounds, never
# for a fixed time (docs/testing.md).
ctest --output-on-failure -j"$(nproc)"
cd ..
# The same unit and integration suites under clang's ASan + UBSan, and each
# fuzz target for a bounded time.
scripts/test-sanitizers.sh
