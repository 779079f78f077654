#!/usr/bin/env bash
# Installs what is missing (Debian packages; the npm packages of the interop and
# browser tests and uPlot, which the web monitor embeds), then configures and
# builds slmp-sim in build/. Safe to run again:
# it only installs what is absent and ccache keeps rebuilds short.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ cmake ninja-build ccache libboost-dev libboost-program-options-dev
          nlohmann-json3-dev libspdlog-dev catch2 python3-jsonschema
          python3-pytest python3-yaml   # the Python CI kit's suite and the CI examples' check (docs/ci.md)
          chromium    # the web monitor's browser test (tests/browser)
          tshark      # the Wireshark dissector's test (tests/wireshark)
          debootstrap umoci podman iproute2   # the container image's build and test (tests/deploy, docs/deploy.md)
          clang libclang-rt-14-dev)   # the sanitizer build and fuzzers (scripts/test-sanitizers.sh)
command -v node >/dev/null 2>&1 || packages+=(nodejs)
command -v npm >/dev/null 2>&1 || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# The third-party client for the interop tests (pinned by package-lock.json).
if [ -f tests/interop/package.json ] && [ ! -d tests/interop/node_modules ]; then
  echo "setup: installing npm packages for tests/interop"
  (cd tests/interop && npm ci --no-audit --no-fund --loglevel=error)
fi

# The Kubernetes API's JSON schemas for the manifests' test (tests/deploy).
if [ -f tests/deploy/k8s_schema/package.json ] && [ ! -d tests/deploy/k8s_schema/node_modules ]; then
  echo "setup: installing npm packages for tests/deploy/k8s_schema"
  (cd tests/deploy/k8s_schema && npm ci --no-audit --no-fund --loglevel=error)
fi

# playwright-core for the browser test; it drives Debian's chromium and
# downloads no browser of its own.
if [ -f tests/browser/package.json ] && [ ! -d tests/browser/node_modules ]; then
  echo "setup: installing npm packages for tests/browser"
  (cd tests/browser && npm ci --no-audit --no-fund --loglevel=error)
fi

# uPlot, which the build embeds into the web monitor (control/web/web_deps.cmake);
# installed again when package-lock.json is newer than what npm ci last wrote.
if [ ! -f control/web-deps/node_modules/.package-lock.json ] ||
   [ control/web-deps/package-lock.json -nt control/web-deps/node_modules/.package-lock.json ]; then
  echo "setup: installing npm packages for control/web-deps"
  (cd control/web-deps && npm ci --no-audit --no-fund --loglevel=error)
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)"
