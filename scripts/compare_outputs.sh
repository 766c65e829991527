#!/usr/bin/env bash
# "No change of behaviour" oracle: runs every resources/*.mlx on every test mesh through a staged
# meshlabserver and fingerprints the outputs, so that two builds of the plugin can be compared.
#   compare_outputs.sh record <stage-dir> <out-dir>   # stage-dir from scripts/stage_meshlab.sh
#   compare_outputs.sh compare <dir-a> <dir-b>        # exit 1 if any pair differs
# record writes <out-dir>/fingerprints.tsv, one sorted line per (script, mesh) pair:
#   script <TAB> mesh <TAB> exit code <TAB> sha256 of the output PLY or - <TAB> failure line(s) or -
# plus <out-dir>/logs/<script>__<mesh>.log (whole stdout+stderr) and <out-dir>/ply/<script>__<mesh>.ply
# (binary PLY with vertex quality and colour, -m vq vc; it holds no time). The failure column is
# our filter's "... failed (Code): message" log line(s); timing lines ("Time: ...") are never compared.
# Environment: MESH_DIR (default $GEODESIC_REMESH_CACHE/meshes or ~/.cache/geodesic-remesh/meshes,
# searched recursively for off/ply/stl/obj), RESOURCES (default <repo>/resources, top level only),
# ONLY / EXCLUDE (extended regexes on the mesh path relative to MESH_DIR), JOBS (2), TIMEOUT (300 s).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage() { sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }

run_one() {  # run_one <script.mlx> <mesh-relpath>   (called by xargs, reads STAGE OUT MESH_DIR TIMEOUT)
  local script=$1 mesh=$2
  local name; name="$(basename "$script" .mlx)__${mesh//\//_}"
  local ply="$OUT/ply/$name.ply" log="$OUT/logs/$name.log" slot lockfd
  rm -f "$ply"
  # Two slots (one per parallel job): each looks for a free X display from its own base number, so
  # the two concurrent xvfb-run -a never race for the same display.
  for slot in $(seq 0 15); do
    exec {lockfd}>"$OUT/.slot$slot.lock"
    flock -n "$lockfd" && break
    exec {lockfd}>&-
  done
  local rc=0 t0=$SECONDS
  (cd "$OUT/ply" && timeout -k 10 "$TIMEOUT" xvfb-run -a -n $((300 + 50 * slot)) \
      "$STAGE/bin/meshlabserver" -i "$MESH_DIR/$mesh" -o "$ply" -m vq vc -s "$script") >"$log" 2>&1 || rc=$?
  exec {lockfd}>&-
  echo "compare_outputs.sh: exit code $rc, wall time $((SECONDS - t0)) s" >>"$log"
  local hash=- fail
  [ -s "$ply" ] && hash=$(sha256sum "$ply" | cut -d' ' -f1)
  # Our filter logs failures as "LOG: <level> <filter name> failed (<Code>): <message>"; the same
  # text is echoed without the prefix (sometimes glued to progress labels), so take the LOG lines.
  fail=$(sed -nE 's/^.*LOG: [0-9]+ (.*failed \(.*)$/\1/p' "$log" | sort -u | paste -sd'|' -)
  [ -n "$fail" ] || fail=$(grep -F 'failed (' "$log" | sort -u | paste -sd'|' - || true)
  printf '%s\t%s\t%s\t%s\t%s\n' "$(basename "$script")" "$mesh" "$rc" "$hash" "${fail:--}" \
    >"$OUT/rows/$name.tsv"
}

record() {
  [ $# -eq 2 ] || usage
  export STAGE; STAGE=$(cd "$1" && pwd)
  [ -x "$STAGE/bin/meshlabserver" ] || { echo "compare_outputs.sh: no $STAGE/bin/meshlabserver" >&2; exit 1; }
  mkdir -p "$2"; export OUT; OUT=$(cd "$2" && pwd)
  export MESH_DIR=${MESH_DIR:-${GEODESIC_REMESH_CACHE:-$HOME/.cache/geodesic-remesh}/meshes}
  export TIMEOUT=${TIMEOUT:-300}
  local resources=${RESOURCES:-$root/resources}
  rm -rf "$OUT/logs" "$OUT/ply" "$OUT/rows" "$OUT/fingerprints.tsv"
  mkdir -p "$OUT/logs" "$OUT/ply" "$OUT/rows"
  local meshes
  meshes=$(cd "$MESH_DIR" && find . -type f \( -iname '*.off' -o -iname '*.ply' -o -iname '*.stl' \
             -o -iname '*.obj' \) | sed 's|^\./||' | LC_ALL=C sort |
           grep -E "${ONLY:-.}" | { if [ -n "${EXCLUDE:-}" ]; then grep -vE "$EXCLUDE"; else cat; fi; } || true)
  local n_m n_s; n_m=$(printf '%s\n' "$meshes" | grep -c . || true)
  n_s=$(find "$resources" -maxdepth 1 -name '*.mlx' | wc -l)
  echo "record: $n_s scripts x $n_m meshes from $MESH_DIR, ${JOBS:-2} jobs, stage $STAGE" >&2
  export -f run_one
  local s m start=$SECONDS
  for s in "$resources"/*.mlx; do
    while IFS= read -r m; do [ -n "$m" ] && printf '%s\0%s\0' "$s" "$m"; done <<<"$meshes"
  done | xargs -0 -n 2 -P "${JOBS:-2}" bash -c 'run_one "$1" "$2"' _
  cat "$OUT"/rows/*.tsv 2>/dev/null | LC_ALL=C sort -t$'\t' -k1,1 -k2,2 >"$OUT/fingerprints.tsv"
  rm -rf "$OUT/rows" "$OUT"/.slot*.lock
  awk -F'\t' -v t=$((SECONDS - start)) '{ n++; if ($3 != 0) f++ }
    END { printf "record: %d pairs, %d failed, %d s\n", n, f, t }' "$OUT/fingerprints.tsv" >&2
}

compare() {
  [ $# -eq 2 ] || usage
  local a=$1/fingerprints.tsv b=$2/fingerprints.tsv
  [ -f "$a" ] && [ -f "$b" ] || { echo "compare_outputs.sh: missing $a or $b" >&2; exit 2; }
  # Fields 3-5 (exit code, hash, failure line) must match; a pair missing on one side differs.
  awk -F'\t' '
    FNR == NR { A[$1 FS $2] = $3 FS $4 FS $5; next }
    { k = $1 FS $2; B[k] = $3 FS $4 FS $5 }
    END {
      for (k in A) K[k]; for (k in B) K[k]
      for (k in K) {
        n++
        if ((k in A) && (k in B) && A[k] == B[k]) { same++; continue }
        va = (k in A) ? A[k] : "(missing)"; vb = (k in B) ? B[k] : "(missing)"
        gsub(FS, " ", k); gsub(FS, " ", va); gsub(FS, " ", vb)
        printf "DIFF %s  a: %s  b: %s\n", k, va, vb | "LC_ALL=C sort"
      }
      close("LC_ALL=C sort")
      printf "%d pairs, %d identical, %d differ\n", n, same, n - same
      exit (n != same)
    }' "$a" "$b"
}

case "${1:-}" in
  record) shift; record "$@" ;;
  compare) shift; compare "$@" ;;
  *) usage ;;
esac
