#!/usr/bin/env bash
# The benchmark command: installs what is missing, builds bench_fast_marching, runs it (ours and
# the competitors in one process), then prints the markdown table of times and ratios.
#   bash scripts/bench.sh                                   # everything (~3-4 min on 2 cores)
#   bash scripts/bench.sh --benchmark_filter='/bunny00'     # extra arguments go to the binary
# Output: $BUILD_DIR/bench_fast_marching.json (the run) and the table on stdout.
# Run it on an otherwise idle machine: the table compares times taken in this one run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" --target bench_fast_marching
json="$build/bench_fast_marching.json"
"$build/bench/bench_fast_marching" --benchmark_out="$json" --benchmark_out_format=json "$@"
echo
python3 "$root/scripts/bench_report.py" "$json"
