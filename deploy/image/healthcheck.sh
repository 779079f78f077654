#!/bin/bash
# slmp-sim-healthcheck [PATH] [PORT]: exit 0 when slmp-sim's HTTP API answers
# GET PATH (default /healthz) with 200 on 127.0.0.1:PORT (default
# $SLMP_SIM_HTTP_PORT, else 8080); exit 1 otherwise, the status line on stderr.
#
# The Dockerfile's HEALTHCHECK runs it. The image has no curl or wget, and
# installing one (with its TLS stack) for a loopback GET would grow the image
# and its patch surface; bash, which every Debian image has, can open the TCP
# connection itself. Set SLMP_SIM_HTTP_HOST when the API is bound to one
# address other than loopback. Kubernetes uses its own httpGet probes instead.
set -u
path="${1:-/healthz}"
port="${2:-${SLMP_SIM_HTTP_PORT:-8080}}"
host="${SLMP_SIM_HTTP_HOST:-127.0.0.1}"
exec 3<>"/dev/tcp/$host/$port" || exit 1
printf 'GET %s HTTP/1.0\r\nHost: %s\r\nConnection: close\r\n\r\n' "$path" "$host" >&3
if ! IFS= read -r -t 5 status <&3; then
  echo "slmp-sim-healthcheck: no answer from $host:$port$path within 5 s" >&2
  exit 1
fi
case "$status" in
  "HTTP/1."?" 200 "*) exit 0 ;;
esac
echo "slmp-sim-healthcheck: $host:$port$path answered '${status%$'\r'}'" >&2
exit 1
