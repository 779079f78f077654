#!/usr/bin/env bash
# debian-mirror.sh [SUITE]: prints the Debian mirror this machine's apt uses for
# SUITE (default bookworm), e.g. http://deb.debian.org/debian.
#
# The image is built from whatever mirror the build machine is allowed to reach
# (a CI network may only see a local mirror or a proxy), so the URL is read from
# apt's own sources at run time and never written into the repository. Both
# formats are read: deb822 (*.sources) and one-line (sources.list, *.list).
# Exit 1 with a message when no enabled "deb" entry serves SUITE with "main".
set -euo pipefail
suite="${1:-bookworm}"
dir="${APT_SOURCES_DIR:-/etc/apt}"   # a test may point this at its own tree

files=()
[ -f "$dir/sources.list" ] && files+=("$dir/sources.list")
for f in "$dir"/sources.list.d/*.list "$dir"/sources.list.d/*.sources; do
  [ -f "$f" ] && files+=("$f")
done

mirror=""
for f in ${files[@]+"${files[@]}"}; do
  case "$f" in
    *.sources)
      # deb822: paragraphs of "Key: value" separated by blank lines.
      mirror=$(awk -v suite="$suite" '
        function flush() {
          if (types ~ /(^| )deb( |$)/ && (" " suites " ") ~ (" " suite " ") &&
              (" " comps " ") ~ / main / && tolower(enabled) != "no" && uris != "" && found == "") {
            split(uris, u, " "); found = u[1]
          }
          types = suites = comps = uris = enabled = ""
        }
        /^[ \t]*#/ { next }
        /^[ \t]*$/ { flush(); next }
        {
          key = tolower($1); sub(/:$/, "", key)
          value = $0; sub(/^[^:]*:[ \t]*/, "", value)
          if (key == "types") types = value
          else if (key == "uris") uris = value
          else if (key == "suites") suites = value
          else if (key == "components") comps = value
          else if (key == "enabled") enabled = value
        }
        END { flush(); print found }' "$f")
      ;;
    *)
      # One-line: deb [options] URI SUITE COMPONENT...
      mirror=$(awk -v suite="$suite" '
        $1 != "deb" { next }
        {
          i = 2
          if ($i ~ /^\[/) { while ($i !~ /\]$/) i++; i++ }
          uri = $i; s = $(i + 1); main = 0
          for (j = i + 2; j <= NF; j++) if ($j == "main") main = 1
          if (s == suite && main) { print uri; exit }
        }' "$f")
      ;;
  esac
  [ -n "$mirror" ] && break
done

if [ -z "$mirror" ]; then
  echo "debian-mirror.sh: no enabled 'deb' source for '$suite' with component 'main' in $dir/sources.list{,.d}; pass --mirror URL" >&2
  exit 1
fi
echo "${mirror%/}"
