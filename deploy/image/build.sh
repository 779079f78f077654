#!/usr/bin/env bash
# deploy/image/build.sh [--binary PATH] [--output DIR] [--tag TAG] [--mirror URL] [--no-load]
#
# Builds the slmp-sim container image as an OCI image layout (DIR/slmp-sim:
# one image tagged TAG, as `podman load` wants it) without a container daemon
# or a registry, then loads it into podman when podman is installed. What the
# Dockerfile builds, from a binary that is already built:
#
#   layer 1  Debian 12 minbase + deploy/image/runtime-packages.txt + user
#            slmp-sim (uid/gid 10001)       (base-rootfs.sh; cached, see there)
#   layer 2  /usr/local/bin/slmp-sim (debug info stripped),
#            /usr/local/bin/slmp-sim-healthcheck, /etc/slmp-sim/config.json,
#            /usr/share/slmp-sim/examples/
#   config   entrypoint slmp-sim, cmd --config /etc/slmp-sim/config.json,
#            user 10001:10001, ports 5000/tcp 5000/udp 8080/tcp, OCI labels
#
# Defaults: --binary build/server/slmp-sim, --output build/image, --tag the
# project version; --mirror is read from this machine's apt sources
# (debian-mirror.sh). Needs root, debootstrap, umoci and chroot. docs/deploy.md.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"

binary="$repo/build/server/slmp-sim"
output="$repo/build/image"
tag=""
mirror=""
load=1
while [ $# -gt 0 ]; do
  case "$1" in
    --binary|--output|--tag|--mirror)
      [ $# -ge 2 ] || { echo "build.sh: $1 needs a value (see --help)" >&2; exit 2; } ;;
  esac
  case "$1" in
    --binary) binary="$2"; shift 2 ;;
    --output) output="$2"; shift 2 ;;
    --tag) tag="$2"; shift 2 ;;
    --mirror) mirror="$2"; shift 2 ;;
    --no-load) load=0; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "build.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done

fail() { echo "build.sh: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || fail "needs root (debootstrap creates device nodes; the checks chroot)"
for tool in debootstrap umoci chroot tar flock; do
  command -v "$tool" >/dev/null || fail "'$tool' is not installed (apt-get install debootstrap umoci, or run scripts/setup.sh)"
done
[ -x "$binary" ] || fail "no slmp-sim binary at $binary (build it first, or pass --binary PATH)"
binary="$(realpath "$binary")"

version=$(sed -n 's/^project(slmp-sim VERSION \([0-9.]*\).*/\1/p' "$repo/CMakeLists.txt")
[ -n "$tag" ] || tag="$version"
[ -n "$mirror" ] || mirror=$("$here/debian-mirror.sh" bookworm)
revision=$(git -C "$repo" rev-parse HEAD 2>/dev/null || echo unknown)

started=$SECONDS
step_started=$SECONDS
step() {  # step NAME: prints how long the previous step took, then NAME
  echo "build.sh: [$((SECONDS - step_started)) s] $1"
  step_started=$SECONDS
}

step "base root filesystem (mirror $mirror)"
base_tar=$("$here/base-rootfs.sh" "$mirror" "$here/runtime-packages.txt")

step "OCI layout $output/slmp-sim, tag $tag"
mkdir -p "$output"
layout="$output/slmp-sim"
bundle="$output/bundle"
rm -rf "$layout" "$bundle"
trap 'rm -rf "$bundle"' EXIT
umoci init --layout "$layout"
umoci new --image "$layout:$tag"
umoci unpack --image "$layout:$tag" "$bundle"
rootfs="$bundle/rootfs"
tar -C "$rootfs" --numeric-owner --xattrs -xf "$base_tar"
umoci repack --refresh-bundle --image "$layout:$tag" \
  --history.created_by "debootstrap --variant=minbase bookworm + runtime-packages.txt + user slmp-sim (10001)" \
  "$bundle"

step "slmp-sim, its health check, configuration and examples"
install -d "$rootfs/usr/local/bin" "$rootfs/etc/slmp-sim" "$rootfs/usr/share/slmp-sim"
# The debug info is most of a RelWithDebInfo binary (~140 of ~150 MB).
strip --strip-debug -o "$rootfs/usr/local/bin/slmp-sim" "$binary"
chmod 0755 "$rootfs/usr/local/bin/slmp-sim"
install -m 0755 "$here/healthcheck.sh" "$rootfs/usr/local/bin/slmp-sim-healthcheck"
install -m 0644 "$here/config.json" "$rootfs/etc/slmp-sim/config.json"
cp -r "$repo/examples" "$rootfs/usr/share/slmp-sim/examples"
chmod -R a+rX "$rootfs/usr/share/slmp-sim"

# A library missing from runtime-packages.txt shows here, not in a cluster.
if ! chroot --userspec=10001:10001 "$rootfs" /usr/local/bin/slmp-sim --version; then
  fail "slmp-sim does not start in the image's root filesystem (above); add the package of each missing library to deploy/image/runtime-packages.txt"
fi
for config in "$rootfs"/etc/slmp-sim/config.json "$rootfs"/usr/share/slmp-sim/examples/plants/*.json; do
  [ -f "$config" ] || continue
  chroot --userspec=10001:10001 "$rootfs" /usr/local/bin/slmp-sim --check-config "${config#"$rootfs"}" >/dev/null \
    || fail "${config#"$rootfs"} does not pass slmp-sim --check-config in the image"
done
umoci repack --image "$layout:$tag" --history.created_by "slmp-sim $version ($revision)" "$bundle"

step "image configuration"
umoci config --image "$layout:$tag" \
  --os linux --architecture "$(dpkg --print-architecture 2>/dev/null || echo amd64)" \
  --config.entrypoint slmp-sim \
  --config.cmd --config --config.cmd /etc/slmp-sim/config.json \
  --config.user 10001:10001 \
  --config.workingdir /var/lib/slmp-sim \
  --config.env PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  --config.exposedports 5000/tcp --config.exposedports 5000/udp --config.exposedports 8080/tcp \
  --config.stopsignal SIGTERM \
  --config.label org.opencontainers.image.title=slmp-sim \
  --config.label "org.opencontainers.image.description=MELSEC PLC simulator (SLMP over TCP/UDP, HTTP API, web monitor)" \
  --config.label "org.opencontainers.image.version=$version" \
  --config.label "org.opencontainers.image.revision=$revision" \
  --config.label "org.opencontainers.image.created=$(date -u +%Y-%m-%dT%H:%M:%SZ)" \
  --history.created_by "entrypoint, user, ports, labels"
umoci gc --layout "$layout"

if [ "$load" -eq 1 ] && command -v podman >/dev/null; then
  step "podman load"
  # podman names an image loaded from a layout after the layout's path
  # (localhost/tmp/out/slmp-sim); it is renamed to ours.
  previous=$(podman image inspect --format '{{.Id}}' "localhost/slmp-sim:$tag" 2>/dev/null || true)
  loaded=$(podman load -i "$layout" | sed -n 's/^Loaded image: //p' | tail -n 1)
  [ -n "$loaded" ] || fail "podman load printed no image name"
  podman tag "$loaded" "localhost/slmp-sim:$tag" "localhost/slmp-sim:latest"
  case "$loaded" in
    localhost/slmp-sim|localhost/slmp-sim:*) ;;
    *) podman untag "$loaded" "$loaded" ;;
  esac
  # The build it replaces, unless something else still names it.
  current=$(podman image inspect --format '{{.Id}}' "localhost/slmp-sim:$tag")
  if [ -n "$previous" ] && [ "$previous" != "$current" ]; then
    podman rmi "$previous" >/dev/null 2>&1 || true
  fi
  echo "build.sh: podman has localhost/slmp-sim:$tag and localhost/slmp-sim:latest"
fi

step "done"
echo "build.sh: $layout (tag $tag; $(du -sh "$layout" | cut -f1)) in $((SECONDS - started)) s"
