#!/usr/bin/env bash
# Installs what is missing, builds, and starts the simulator: an R08CPU on
# port 5000 (TCP and UDP). Extra arguments go to slmp-sim (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec build/server/slmp-sim "$@"
