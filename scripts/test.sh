#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs every test (ctest prints the summary).
#   bash scripts/test.sh            # from a fresh clone on Debian 12; safe to run again
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
start=$(date +%s)
# Warnings of our own code are errors here (and so in CI): GR_STRICT=ON.
CMAKE_ARGS="-DGR_STRICT=ON ${CMAKE_ARGS:-}" bash "$root/scripts/build.sh"
echo "[test] build took $(( $(date +%s) - start )) s"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)"
