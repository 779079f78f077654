#!/usr/bin/env bash
# run.sh MANIFEST...: check_schema.js under node, with the schemas `npm ci`
# installs here. Exit 77 (CTest: skipped), naming what is missing, without
# node or without node_modules; scripts/setup.sh installs both.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if ! command -v node >/dev/null; then
  echo "SKIPPED: node is not installed (apt-get install nodejs npm, or run scripts/setup.sh)"
  exit 77
fi
if [ ! -d "$here/node_modules/kubernetes-models" ]; then
  echo "SKIPPED: the schemas are not installed (npm ci in tests/deploy/k8s_schema, or run scripts/setup.sh)"
  exit 77
fi
exec node "$here/check_schema.js" "$@"
