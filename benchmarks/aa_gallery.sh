#!/usr/bin/env bash
# The anti-aliasing gallery: renders one scene (scenes/aa_test.json: thin wires and
# poles, a receding checkerboard, sphere silhouettes) under each --aa mode at a small
# size, cuts the same crop out of each, enlarges it with nearest-neighbour
# filtering so single pixels stay visible, labels it, and lays them side by side.
# Prints a Markdown table of primary rays per pixel and render time per mode.
#
#   benchmarks/aa_gallery.sh [BUILD_DIR] [OUT_DIR]
#
# BUILD_DIR holds the built `prism` (default: build); OUT_DIR receives the PNGs
# (default: docs/aa). Needs oiiotool (Debian: openimageio-tools). Times are the
# median of REPEAT runs (default 3) after one untimed run per mode; they include
# the whole render (sample positions, waves, filter) but not start-up or kernel
# builds. SPP (default 4) is the samples per pixel of grid, jitter, poisson and
# random; REF_SPP (default 256) that of the jittered reference.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
out="${2:-$here/docs/aa}"
prism="$build/prism"
scene="$here/scenes/aa_test.json"
repeat="${REPEAT:-3}"
spp="${SPP:-4}"
ref_spp="${REF_SPP:-256}"
width=320
height=240
# The crop (x, y, w, h) and its enlargement (--resample:interp=0: nearest pixel, no filtering).
crop_x=88 crop_y=30 crop_w=112 crop_h=84 zoom=3

command -v oiiotool >/dev/null || { echo "aa_gallery: oiiotool not found (apt-get install openimageio-tools)" >&2; exit 1; }
[ -x "$prism" ] || { echo "aa_gallery: $prism not found (build first, or pass BUILD_DIR)" >&2; exit 1; }
# Labels need a font file; without one the crops go unlabelled.
font="$(fc-match -f '%{file}' 'DejaVu Sans' 2>/dev/null || true)"
[ -f "$font" ] || font=""
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# name | prism options | label
modes=(
  "none|--aa none|none"
  "grid|--aa grid --spp $spp|grid $spp spp"
  "quincunx|--aa quincunx|quincunx"
  "adaptive|--aa adaptive|adaptive (0.1, level 2)"
  "jitter|--aa jitter --spp $spp|jitter $spp spp"
  "poisson|--aa poisson --spp $spp|poisson $spp spp"
  "random|--aa random --spp $spp|random $spp spp"
  "reference|--aa jitter --spp $ref_spp|reference: jitter $ref_spp spp"
)

# The render's own time from the summary line: its rays over its Mrays/s (the
# printed seconds have two decimals; this has three or four digits).
field() {
  sed -n 's/.*; \([0-9]*\) primary, \([0-9]*\) reflected, \([0-9]*\) refracted, \([0-9]*\) shadow rays, \([0-9.]*\) Mrays\/s.*/\1 \2 \3 \4 \5/p' |
    awk '{ printf "%.4f\n", ($1 + $2 + $3 + $4) / ($5 * 1e6) }'
}
rpp() { sed -n "s/.*, \([0-9.]*\) rays\/pixel.*/\1/p"; }

echo "| mode | options | primary rays per pixel | time (s) | relative time |"
echo "| --- | --- | ---: | ---: | ---: |"
panels=()
base_time=""
for entry in "${modes[@]}"; do
  IFS='|' read -r name opts label <<<"$entry"
  # shellcheck disable=SC2086
  "$prism" render "$scene" -o "$work/$name.png" --width $width --height $height $opts --quiet
  times=()
  line=""
  for _ in $(seq "$repeat"); do
    # shellcheck disable=SC2086
    line="$("$prism" render "$scene" -o "$work/$name.png" --width $width --height $height $opts)"
    times+=("$(field <<<"$line")")
  done
  t="$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(((repeat + 1) / 2))p")"
  r="$(rpp <<<"$line")"
  [ -n "$base_time" ] || base_time="$t"
  rel="$(awk -v a="$t" -v b="$base_time" 'BEGIN { printf "%.1f", a / b }')"
  printf '| %s | `%s` | %.3f | %.3f | %s× |\n' "$name" "$opts" "$r" "$t" "$rel"

  big_w=$((crop_w * zoom)) big_h=$((crop_h * zoom))
  # A white band above the crop carries the label.
  label_args=()
  [ -z "$font" ] || label_args=(--crop "${big_w}x$((big_h + 24))+0-24" --fill:color=1,1,1 "${big_w}x24+0-24"
    --text:x=6:y=-7:size=15:color=0,0,0:font="$font" "$label, $(printf '%.2f' "$r") rays/px"
    --origin +0+0 --fullpixels)
  oiiotool "$work/$name.png" --cut "${crop_w}x${crop_h}+${crop_x}+${crop_y}" \
    --resample:interp=0 "${big_w}x${big_h}" "${label_args[@]}" -o "$out/$name.png"
  panels+=("$out/$name.png")
done

# All crops side by side, four to a row; and the whole reference image with the
# crop outlined.
oiiotool "${panels[@]}" --mosaic:pad=4 4x2 -o "$out/aa_modes.png"
oiiotool "$work/reference.png" \
  --box:color=1,0,0 "$crop_x,$crop_y,$((crop_x + crop_w - 1)),$((crop_y + crop_h - 1))" \
  -o "$out/scene.png"
echo
echo "wrote $out/aa_modes.png, $out/scene.png and one crop per mode ($width x $height render, ${crop_w} x ${crop_h} crop at ${zoom}x)"
