#!/usr/bin/env bash
# The distributed ray tracing gallery: each effect's example scene (penumbra,
# glossy, dof, motion, and cook, which combines them all) rendered at 1, 4, 16 and
# 64 samples per pixel, labelled and laid side by side in docs/drt/SCENE.png, plus
# the combined scene alone at 64 spp in docs/drt/cook_64.png. Prints a Markdown
# table of render time and rays per primary sample for each scene and spp.
#
#   benchmarks/drt_gallery.sh [BUILD_DIR] [OUT_DIR]
#
# BUILD_DIR holds the built `prism` (default: build); OUT_DIR receives the PNGs
# (default: docs/drt). Needs oiiotool (Debian: openimageio-tools).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
out="${2:-$here/docs/drt}"
prism="$build/prism"
width="${WIDTH:-240}"
height="${HEIGHT:-180}"

command -v oiiotool >/dev/null || { echo "drt_gallery: oiiotool not found (apt-get install openimageio-tools)" >&2; exit 1; }
[ -x "$prism" ] || { echo "drt_gallery: $prism not found (build first, or pass BUILD_DIR)" >&2; exit 1; }
font="$(fc-match -f '%{file}' 'DejaVu Sans' 2>/dev/null || true)"
[ -f "$font" ] || font=""
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "| scene | spp | render s | rays per sample |"
echo "| --- | --- | --- | --- |"
for scene in penumbra glossy dof motion cook; do
  panels=()
  for spp in 1 4 16 64; do
    summary="$("$prism" render "$here/scenes/$scene.json" -o "$work/${scene}_$spp.png" \
      --width "$width" --height "$height" --spp "$spp" 2>&1 | tail -1)"
    seconds="$(sed -n 's/.* in \([0-9.]*\) s (kernels.*/\1/p' <<<"$summary")"
    rays="$(sed -n 's/.*; \([0-9]*\) primary, \([0-9]*\) reflected, \([0-9]*\) refracted, \([0-9]*\) shadow.*/\1 \2 \3 \4/p' <<<"$summary")"
    read -r p r t s <<<"$rays"
    echo "| $scene | $spp | $seconds | $(awk -v p="$p" -v r="$r" -v t="$t" -v s="$s" 'BEGIN { printf "%.2f", (p + r + t + s) / p }') |"
    panel="$work/${scene}_${spp}_panel.png"
    if [ -n "$font" ]; then
      oiiotool "$work/${scene}_$spp.png" --text:x=6:y=20:size=16:color=1,1,1:font="$font" "$spp spp" -o "$panel"
    else
      cp "$work/${scene}_$spp.png" "$panel"
    fi
    panels+=("$panel")
  done
  oiiotool "${panels[@]}" --mosaic:pad=4 4x1 -o "$out/$scene.png"
done
"$prism" render "$here/scenes/cook.json" -o "$out/cook_64.png" --spp 64 >/dev/null
