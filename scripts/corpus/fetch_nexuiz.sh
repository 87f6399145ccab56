#!/usr/bin/env bash
# Fetches the real-map corpus: Debian's `nexuiz-data` package (GPL), downloaded with
# `apt-get download` (nothing is installed) and unpacked with `dpkg-deb -x` under
# build/corpus/nexuiz-data/. Cached: once the unpacked tree's stamp exists, a second run
# fetches nothing. Prints the folder holding the maps' pk3 on stdout.
#   scripts/corpus/fetch_nexuiz.sh [BUILD_DIR]
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(realpath -m "${1:-${PROBEPROXY_BUILD_DIR:-$here/build}}")
corpus="$build/corpus"
tree="$corpus/nexuiz-data"
stamp="$tree/.unpacked"

if [ ! -f "$stamp" ]; then
  mkdir -p "$corpus"
  # A fresh machine may have no package lists yet: apt-get download needs them.
  if ! apt-cache policy nexuiz-data 2>/dev/null | grep -q 'Candidate: [0-9]'; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update >&2
  fi
  # apt-get download writes into the current folder; a partial .deb from an interrupted run
  # is replaced, never unpacked.
  (cd "$corpus" && rm -f nexuiz-data_*.deb.partial && apt-get download nexuiz-data >&2)
  deb=$(ls "$corpus"/nexuiz-data_*.deb | head -n 1)
  rm -rf "$tree"
  dpkg-deb -x "$deb" "$tree"
  rm -f "$deb"  # the unpacked tree is what is kept; the archive would double the space
  touch "$stamp"
fi

# The maps live in the game's data pk3 (a zip), beside the other data archives.
echo "$tree/usr/share/games/nexuiz/data"
