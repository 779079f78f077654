#!/usr/bin/env bash
# base-rootfs.sh MIRROR PACKAGES_FILE: prints the path of a tarball holding the
# image's base root filesystem, building it first when it is not cached.
#
# The base is everything that does not depend on the slmp-sim build: a Debian 12
# minbase system with the runtime packages, the unprivileged user slmp-sim
# (uid/gid 10001, as in the Dockerfile) and its state directory. It is cached in
# $SLMP_IMAGE_CACHE (default ~/.cache/slmp-sim-image), keyed by everything that
# goes into it, so a re-run unpacks a tarball in seconds instead of running
# debootstrap again; downloaded .debs are kept there too, so a changed package
# list downloads only what is new. Needs root (debootstrap creates device nodes
# and chroots). Progress goes to stderr; stdout is only the path.
set -euo pipefail
mirror="$1"; packages_file="$2"
suite=bookworm
uid=10001
cache="${SLMP_IMAGE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/slmp-sim-image}"
mkdir -p "$cache/debs"

packages=$(grep -v -e '^[[:space:]]*#' -e '^[[:space:]]*$' "$packages_file" | tr -d '[:blank:]' | sort -u)
# Bump the recipe version when the steps below change what the tarball holds.
recipe="recipe=3 suite=$suite variant=minbase uid=$uid mirror=$mirror packages=$(echo $packages)"
key=$(printf '%s' "$recipe" | sha256sum | cut -c1-16)
tarball="$cache/base-$key.tar"

# Two builds at once (two CI jobs on one machine) must not both write the cache.
exec 9>"$cache/lock"
flock 9
if [ -f "$tarball" ]; then
  echo "base-rootfs: cached $tarball ($recipe)" >&2
  echo "$tarball"
  exit 0
fi

work=$(mktemp -d "$cache/build.XXXXXX")
trap 'rm -rf "$work"' EXIT
rootfs="$work/rootfs"
start=$SECONDS
echo "base-rootfs: debootstrap --variant=minbase $suite from $mirror (+ $(echo $packages | tr ' ' ','))" >&2
if ! debootstrap --variant=minbase --cache-dir="$cache/debs" --include="$(echo $packages | tr ' ' ',')" \
       "$suite" "$rootfs" "$mirror" > "$work/debootstrap.out" 2>&1; then
  tail -n 20 "$work/debootstrap.out" >&2
  [ -f "$rootfs/debootstrap/debootstrap.log" ] && tail -n 20 "$rootfs/debootstrap/debootstrap.log" >&2
  echo "base-rootfs: debootstrap failed (above)" >&2
  exit 1
fi
echo "base-rootfs: debootstrap took $((SECONDS - start)) s" >&2

# The same user as the Dockerfile's: a fixed uid, so Kubernetes' runAsUser and
# volume ownership can name it.
chroot "$rootfs" useradd --uid "$uid" --user-group --home-dir /var/lib/slmp-sim \
  --no-create-home --shell /usr/sbin/nologin slmp-sim
install -d -o "$uid" -g "$uid" -m 0750 "$rootfs/var/lib/slmp-sim"

# What debian:12-slim drops too: package caches, indexes, logs, manuals,
# message translations (33 MB of the 118) and documentation (the copyright
# files stay: the licences travel with the image).
rm -rf "$rootfs"/var/cache/apt/archives/*.deb "$rootfs"/var/cache/apt/*.bin \
       "$rootfs"/var/lib/apt/lists/* "$rootfs"/usr/share/man/* "$rootfs"/usr/share/info/* \
       "$rootfs"/usr/share/locale/*
find "$rootfs"/var/log -type f -delete
find "$rootfs"/usr/share/doc -mindepth 1 ! -type d ! -name copyright -delete
find "$rootfs"/usr/share/doc -mindepth 1 -type d -empty -delete

tar -C "$rootfs" --numeric-owner --xattrs -cf "$work/base.tar" .
mv "$work/base.tar" "$tarball"
echo "base-rootfs: cached $tarball ($(du -sh "$rootfs" | cut -f1)) in $((SECONDS - start)) s" >&2
echo "$tarball"
