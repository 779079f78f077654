#!/usr/bin/env bash
# with_python.sh MODULE DEBIAN_PACKAGE ARGS...: runs `python3 ARGS...` with the
# first interpreter that can import MODULE — python3 on PATH, then Debian's
# /usr/bin/python3 (a pyenv or venv python3 on PATH does not see Debian's
# python3-pytest/python3-yaml). Exit 77 (CTest: skipped) when none can.
set -euo pipefail
module="$1"; package="$2"; shift 2
for python in "$(command -v python3 || true)" /usr/bin/python3; do
  [ -n "$python" ] && [ -x "$python" ] || continue
  if "$python" -c "import $module" 2>/dev/null; then exec "$python" "$@"; fi
done
echo "SKIPPED: $package is not installed (apt-get install $package, or run scripts/setup.sh)"
exit 77
