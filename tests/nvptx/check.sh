#!/usr/bin/env bash
# Offline compile of every kernel program for an NVIDIA target (clang's
# nvptx64-nvidia-nvcl, OpenCL C 1.2, the build options prism uses), with each
# acceleration structure and every optional feature on and off, so a kernel
# that only PoCL accepts is caught without a GPU (issue 13). The 64-bit
# Z-buffer atomics are compiled with their extensions declared, as a device
# that advertises them (prism asks before it uses them) would; no other
# extension is assumed. Warnings fail the check too.
# Usage: tests/nvptx/check.sh KERNEL_DIR [CLANG]
set -euo pipefail
kernels="$1"
clang="${2:-clang}"
base=(-x cl -cl-std=CL1.2 -target nvptx64-nvidia-nvcl -Werror "-I$kernels" -S -o /dev/null)
features=(""
  "-DPRISM_MOTION -DPRISM_BVH_MOTION"
  "-DPRISM_BVH_KDOP -DPRISM_OBJECT_KDOP"
  "-DPRISM_AREA_LIGHTS -DPRISM_LOBES -DPRISM_LIGHT_BUFFER"
  "-DPRISM_KINDS=15"
  "-DPRISM_MOTION -DPRISM_BVH_MOTION -DPRISM_BVH_KDOP -DPRISM_OBJECT_KDOP -DPRISM_AREA_LIGHTS -DPRISM_LOBES -DPRISM_LIGHT_BUFFER")
count=0
for entry in "$kernels"/*.cl; do
  # Programs without a structure (the render loop's, scans) once per feature set.
  accels=(NONE)
  if "$clang" -x cl -cl-std=CL1.2 -target nvptx64-nvidia-nvcl "-I$kernels" -MM "$entry" 2>/dev/null |
      grep -q "accel/accel.h"; then
    accels=(NONE BVH OCTREE BSP)
  fi
  for accel in "${accels[@]}"; do
    for f in "${features[@]}"; do
      # shellcheck disable=SC2086
      if ! out=$("$clang" "${base[@]}" "-DPRISM_ACCEL_$accel" $f "$entry" 2>&1); then
        echo "nvptx: $(basename "$entry") with -DPRISM_ACCEL_$accel $f:" >&2
        echo "$out" >&2
        exit 1
      fi
      count=$((count + 1))
    done
  done
done
if ! out=$("$clang" "${base[@]}" -Xclang -cl-ext=+cl_khr_int64_base_atomics,+cl_khr_int64_extended_atomics \
    -DPRISM_ZBUFFER_WIDE "$kernels/firsthit.cl" 2>&1); then
  echo "nvptx: firsthit.cl with -DPRISM_ZBUFFER_WIDE:" >&2
  echo "$out" >&2
  exit 1
fi
count=$((count + 1))
echo "nvptx: $count kernel builds compiled for nvptx64-nvidia-nvcl"
