#!/usr/bin/env bash
# Renders one scene on this machine's default OpenCL device (PoCL here, or a
# GPU where there is one) and on Oclgrind, another OpenCL implementation, and
# fails unless the two images are the same bits: the kernels use only math
# whose results OpenCL fixes (kernels/common/same_bits_math.h).
#   same_bits.sh PRISM SCENE [RENDER OPTIONS...]
# The image is a PFM, the film's floats as they are. Oclgrind builds the
# kernels unoptimised (-cl-opt-disable), so the test also holds an optimised
# build against an unoptimised one; and because Oclgrind 21.10's optimised
# builds mis-execute packet_intersect's lane mask (a comparison's true came out
# as 1 where OpenCL C makes it -1, so ~reject & in_range kept rejected lanes:
# docs/devices.md, "Same bits on every device"), which PoCL and NVIDIA's driver
# both get right.
set -euo pipefail
prism="$1"
scene="$2"
shift 2
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# Each side compiles its kernels afresh: a cache holds one device's binaries.
XDG_CACHE_HOME="$work/cache-device" "$prism" render "$scene" "$@" -o "$work/device.pfm" --quiet
XDG_CACHE_HOME="$work/cache-oclgrind" oclgrind --build-options "-cl-opt-disable -DPRISM_NO_FORCED_INLINE" \
  "$prism" render "$scene" "$@" -o "$work/oclgrind.pfm" --quiet
if ! cmp -s "$work/device.pfm" "$work/oclgrind.pfm"; then
  differing=$(cmp -l "$work/device.pfm" "$work/oclgrind.pfm" | wc -l || true)
  echo "same_bits.sh: $(basename "$scene") $*: the images differ in $differing of $(stat -c %s "$work/device.pfm") bytes" >&2
  exit 1
fi
echo "same_bits.sh: $(basename "$scene") $*: the same bits on both"
