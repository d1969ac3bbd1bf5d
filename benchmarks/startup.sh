#!/usr/bin/env bash
# Cold and warm start of `prism render` on the default scene: cold with empty
# prism and PoCL kernel caches, warm with both filled by the cold run. Prints a
# Markdown table. Usage: benchmarks/startup.sh [WIDTH HEIGHT [DEVICE]]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prism="${PRISM:-$root/build/prism}"
width="${1:-1280}" height="${2:-720}" device="${3:-}"
caches="$(mktemp -d)"
trap 'rm -rf "$caches"' EXIT
export PRISM_CACHE_DIR="$caches/prism" POCL_CACHE_DIR="$caches/pocl"
out="$caches/out.png"

run() {
  local start end line
  start=$(date +%s.%N)
  line=$("$prism" render "$root/scenes/whitted.json" -o "$out" --width "$width" --height "$height" \
           ${device:+--device "$device"})
  end=$(date +%s.%N)
  # The summary line: "... in R s (kernels K s, first launches F s): ... M Mrays/s -> ..."
  local render kernels launches mrays
  render=$(sed -E 's/.* in ([0-9.]+) s \(kernels.*/\1/' <<<"$line")
  kernels=$(sed -E 's/.*\(kernels ([0-9.]+) s,.*/\1/' <<<"$line")
  launches=$(sed -E 's/.*first launches ([0-9.]+) s\).*/\1/' <<<"$line")
  mrays=$(sed -E 's/.* ([0-9.]+) Mrays\/s.*/\1/' <<<"$line")
  printf '| %s | %.2f | %s | %s | %s | %s |\n' "$1" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" \
    "$kernels" "$launches" "$render" "$mrays"
}

echo "default scene (scenes/whitted.json) at ${width}x${height}, device: $("$prism" devices | head -1)"
echo
echo "| start | process wall time (s) | kernel build/load (s) | first launches (s) | render (s) | Mrays/s |"
echo "| --- | --- | --- | --- | --- | --- |"
run cold
run warm
run warm
