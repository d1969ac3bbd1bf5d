#!/usr/bin/env bash
# Load time and peak memory per mesh format, prism's plugins next to
# OpenMesh's read_mesh, on the largest mesh of the benchmark ladder
# (bunny_loop2_1.1M.ply, found or made by `prism-bench mesh`: binary
# little-endian PLY, 1,111,216 triangles), converted to ASCII PLY, OBJ and OFF first. Each load
# runs in its own process (peak RSS is per process); the best time and the
# largest peak of $RUNS runs (default 3) are shown. Prints a Markdown table.
# Usage: benchmarks/mesh_load/run.sh [BUILD_DIR]   (needs mesh_load_bench built)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build}"
bench="${MESH_LOAD_BENCH:-$build/benchmarks/mesh_load/mesh_load_bench}"
runs="${RUNS:-3}"
src="$("$build/benchmarks/prism-bench" mesh bunny/bunny_loop2_1.1M.ply)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cp "$src" "$work/bunny_binary.ply"
for f in bunny_ascii.ply bunny.obj bunny.off; do "$bench" convert "$src" "$work/$f"; done

echo "| file | size (MB) | reader | vertices | triangles | load (s) | peak RSS (MiB) | RSS before load (MiB) |"
echo "|---|---:|---|---:|---:|---:|---:|---:|"
for f in bunny_binary.ply bunny_ascii.ply bunny.obj bunny.off; do
  size=$(awk -v b="$(stat -c %s "$work/$f")" 'BEGIN { printf "%.1f", b / 1e6 }')
  for reader in prism openmesh; do
    best="" peak=0 base=0 v="" t=""
    for _ in $(seq "$runs"); do
      if ! line=$("$bench" "$reader" "$work/$f" 2>&1); then best="failed: $line"; break; fi
      read -r _ _ v _ t _ s _ p _ b _ <<<"$line"
      best=$(awk -v a="${best:-1e9}" -v s="$s" 'BEGIN { print (s < a) ? s : a }')
      peak=$(awk -v a="$peak" -v p="$p" 'BEGIN { print (p > a) ? p : a }')
      base=$b
    done
    echo "| $f | $size | $reader | $v | $t | $best | $peak | $base |"
  done
done
