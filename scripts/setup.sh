#!/usr/bin/env bash
# Installs everything the project needs on Debian 12 (bookworm). Safe to run again.
#   1. Debian packages (MeshLab 2020.09, Qt5, GLEW, Eigen, GoogleTest, Google Benchmark, CGAL, Xvfb, matplotlib for docs/adaptive_error.png, clang-format-14 for the format check).
#   2. MeshLab 2020.09's sources (plugin headers + the matching vcglib) from Debian's source package,
#      pinned to the version of the installed binary, into $CACHE/meshlab-2020.09+dfsg1.
#   3. The real test meshes of libcgal-demo into $CACHE/meshes.
# $CACHE is $GEODESIC_REMESH_CACHE, or ~/.cache/geodesic-remesh; CMakeLists.txt uses the same default.
set -euo pipefail

MESHLAB_VERSION=2020.09+dfsg1-2
CACHE=${GEODESIC_REMESH_CACHE:-$HOME/.cache/geodesic-remesh}
PACKAGES=(meshlab qtbase5-dev libqt5opengl5-dev libglew-dev libeigen3-dev libgtest-dev
          libbenchmark-dev libcgal-dev xvfb xauth imagemagick x11-utils dpkg-dev cmake g++ make
          python3-matplotlib clang-format-14)

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
log() { printf '[setup] %s\n' "$*"; }

# --- 1. packages ------------------------------------------------------------------------------
SRC_LIST=/etc/apt/sources.list.d/geodesic-remesh-src.sources
need_update=0
if [ ! -f "$SRC_LIST" ]; then
  log "adding a deb-src entry for bookworm main ($SRC_LIST)"
  $SUDO tee "$SRC_LIST" >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  need_update=1
fi
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ] || [ $need_update -eq 1 ]; then
  log "apt-get update"
  $SUDO apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  log "installing: ${missing[*]}"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
installed=$(dpkg-query -W -f='${Version}' meshlab)
if [ "$installed" != "$MESHLAB_VERSION" ]; then
  log "WARNING: installed meshlab is $installed, the plugin is built against $MESHLAB_VERSION headers"
fi

# --- 2. MeshLab sources -----------------------------------------------------------------------
mkdir -p "$CACHE"
MESHLAB_SRC="$CACHE/meshlab-2020.09+dfsg1"
if [ ! -f "$MESHLAB_SRC/src/common/interfaces.h" ] || [ ! -d "$MESHLAB_SRC/vcglib/vcg" ]; then
  log "fetching MeshLab $MESHLAB_VERSION sources into $CACHE"
  rm -rf "$MESHLAB_SRC"
  # apt-get source refuses to run as root into a dir '_apt' cannot write; a temp dir avoids that warning.
  (cd "$CACHE" && apt-get source -qq "meshlab=$MESHLAB_VERSION" >/dev/null 2>&1 || \
   { cd "$CACHE" && apt-get source "meshlab=$MESHLAB_VERSION"; })
  rm -f "$CACHE"/meshlab_2020.09*.tar.* "$CACHE"/meshlab_2020.09*.dsc
fi
test -f "$MESHLAB_SRC/src/common/interfaces.h"
log "MeshLab sources: $MESHLAB_SRC"

# --- 3. test meshes ---------------------------------------------------------------------------
MESHES="$CACHE/meshes"
if [ ! -f "$MESHES/fandisk.off" ] || [ ! -f "$MESHES/bunny00.off" ]; then
  log "fetching libcgal-demo meshes into $MESHES"
  tmp=$(mktemp -d)
  (cd "$tmp" && apt-get download -qq libcgal-demo >/dev/null 2>&1 || { cd "$tmp" && apt-get download libcgal-demo; })
  dpkg-deb -x "$tmp"/libcgal-demo_*.deb "$tmp/x"
  mkdir -p "$tmp/data"
  tar -xzf "$tmp/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$tmp/data"
  src=$(find "$tmp/data" -type d -path '*data/meshes' | head -n1)
  rm -rf "$MESHES"; mkdir -p "$MESHES"
  cp -r "$src"/. "$MESHES"/
  rm -rf "$tmp"
fi
test -f "$MESHES/fandisk.off"
log "test meshes: $MESHES ($(ls "$MESHES" | wc -l) files)"
