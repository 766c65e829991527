#!/usr/bin/env bash
# The format check: every tracked .h/.cpp is as clang-format-14 (with .clang-format) writes it.
#   bash scripts/check_format.sh          # lists the files that differ; exit 1 if any
#   bash scripts/check_format.sh --fix    # formats them in place
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(git ls-files '*.h' '*.cpp')
if [ "${1:-}" = "--fix" ]; then
  clang-format-14 --style=file -i "${files[@]}"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! clang-format-14 --style=file --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f  (bash scripts/check_format.sh --fix)"
    bad=1
  fi
done
[ $bad -eq 0 ] && echo "format: ${#files[@]} files as clang-format-14 writes them"
exit $bad
