#!/usr/bin/env bash
# Runs the Python kit's own suite (clients/python/tests) under Debian's
# python3-pytest against $SLMP_SIM_BINARY. Skipped (exit 77) when pytest is
# not installed; scripts/setup.sh installs it.
set -euo pipefail
kit="$1"
export PYTHONPATH="$kit${PYTHONPATH:+:$PYTHONPATH}"
# -p no:cacheprovider: nothing is written into the source tree.
exec "$(dirname "$0")/with_python.sh" pytest python3-pytest -m pytest -q -p no:cacheprovider "$kit/tests"
