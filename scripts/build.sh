#!/usr/bin/env bash
# Configures and builds the project into $BUILD_DIR (default: build). Used by main.sh and test.sh.
# Arguments are passed to `cmake --build` (e.g. --target filter_geodesic_remesh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo ${CMAKE_ARGS:-} >/dev/null
cmake --build "$build" -j "$(nproc)" "$@"
