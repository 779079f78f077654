#!/usr/bin/env bash
# Runs the Python kit's own suite (clients/python/tests) under Debian's
# python3-pytest against $SLMP_SIM_BINARY. Exit 77 (CTest: skipped) when
# pytest is not installed; scripts/setup.sh installs it.
set -euo pipefail
kit="$1"
if ! python3 -c 'import pytest' 2>/dev/null; then
  echo "SKIPPED: python3-pytest is not installed (apt-get install python3-pytest, or run scripts/setup.sh)"
  exit 77
fi
export PYTHONPATH="$kit${PYTHONPATH:+:$PYTHONPATH}"
# -p no:cacheprovider: nothing is written into the source tree.
exec python3 -m pytest -q -p no:cacheprovider "$kit/tests"
