#!/bin/bash
# Runs on the lent GPU machine, in the carried repository (make-bundle.sh made
# build-gpu/): OpenCL's loader pointed at NVIDIA's library and the machine's PoCL,
# `prism devices`, then by PHASE (default check,bench):
#   check    renders of ten scenes on the GPU (PFM, packed as float16 into images.npz),
#            the same on the machine's CPU device (PoCL) compared byte for byte
#            ("same bits" or "DIFFER" in the summary: docs/devices.md, "Same bits on
#            every kind of device"), and every test binary at once, on the GPU
#            (PRISM_TEST_DEVICE)
#   bench    prism-bench devices, accel (69k and 1.1M bunny), firsthit
#   devices  prism-bench devices over the GPU and the CPU at 4, 16 and 32 spp
# Each step is cut to what is left of DEADLINE seconds. A summary goes to stdout
# and $OUT/summary.txt, every log to $OUT/logs.tar.gz.
set -u
T0=$(date +%s)
DEADLINE=${DEADLINE:-480}
PHASE=${PHASE:-check,bench}
R=$PWD
G=$R/build-gpu
W=/tmp/gpuwork
OUT=${OUT:-$W/out}  # set by the device tool
rm -rf $W
mkdir -p $W/logs $OUT
S=$W/logs/summary.txt
say() { echo "$*" | tee -a $S; }
step() {  # step NAME SECONDS command...
  local name=$1 limit=$2; shift 2
  local left=$(( DEADLINE - ($(date +%s) - T0) ))
  [ $left -lt 15 ] && { say "SKIP $name (deadline)"; return; }
  [ $limit -gt $left ] && limit=$left
  local t=$(date +%s%N)
  timeout $limit "$@" > $W/logs/$name.log 2>&1
  say "$(printf '%-24s rc=%-4s %7d ms' $name $? $(( ($(date +%s%N) - t) / 1000000 )))"
}
summary() { say "-- $1: $(grep -E '^(Passed|Failed|All tests|No tests)' $W/logs/$1.log | tail -1)"; grep -E 'FAILED|failed' $W/logs/$1.log | head -12 >> $S; }

# The binaries name the folders they were built with.
origin=$(cat $G/origin.txt)
[ -e "$origin" ] || { mkdir -p "$(dirname "$origin")" && ln -s $R "$origin"; }
[ -e /tmp/prism-device-src ] || ln -s $R /tmp/prism-device-src
[ -e $R/build-dev ] || ln -s $G $R/build-dev
B=$R/build-dev
(cd $G/devlib && tar xJf extra-libs.tar.xz)
say "== $(date -u)"
nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv | tee -a $S
OCL=$(ls /usr/local/nvidia/lib64/libnvidia-opencl.so.1 /usr/lib/x86_64-linux-gnu/libnvidia-opencl.so.1 2>/dev/null | head -1)
[ -z "$OCL" ] && OCL=$(find / -xdev -name 'libnvidia-opencl.so*' 2>/dev/null | head -1)
say "NVIDIA's OpenCL library: ${OCL:-none}"
mkdir -p $W/icd
[ -n "$OCL" ] && echo "$OCL" > $W/icd/nvidia.icd
for icd in /etc/OpenCL/vendors/*.icd; do  # the machine's other drivers (PoCL), NVIDIA's once
  [ -f "$icd" ] && ! grep -qi nvidia "$icd" && cp "$icd" $W/icd/
done
export OCL_ICD_VENDORS=$W/icd
L=$G/devlib
STD=$(ldconfig -p | awk '/libstdc\+\+\.so\.6 .*x86-64/{print $NF; exit}')
grep -q GLIBCXX_3.4.30 "${STD:-/dev/null}" || { L=$L:$G/devlib/std; say "the carried libstdc++"; }
export LD_LIBRARY_PATH=$L${OCL:+:$(dirname $OCL)}
export PRISM_CACHE_DIR=$W/cache XDG_CACHE_HOME=$W/xdg PRISM_BENCH_DATA=$G/data PRISM_PLUGIN_PATH=$G/plugins
cd $R
step devices 60 $B/prism devices
head -24 $W/logs/devices.log | tee -a $S
IDX=$(grep -E '^\[[0-9]+\]' $W/logs/devices.log | grep -iE 'nvidia' | head -1 | sed -E 's/^\[([0-9]+)\].*/\1/')
[ -z "$IDX" ] && { say "no NVIDIA device: the rest on device 0"; IDX=0; }
export PRISM_TEST_DEVICE=$IDX

if [[ $PHASE == *check* ]]; then
  SCENES="whitted cook cornell dof teapot glossy penumbra geometry quadrics motion"
  for sc in $SCENES; do
    step render_$sc 120 $B/prism render scenes/$sc.json -o $W/logs/$sc.pfm --device $IDX --stats
    head -1 $W/logs/render_$sc.log >> $S
  done
  CPU=$(grep -E '^\[[0-9]+\]' $W/logs/devices.log | grep -viE 'nvidia' | head -1 | sed -E 's/^\[([0-9]+)\].*/\1/')
  if [ -n "$CPU" ]; then
    mkdir -p $W/cpu
    for sc in $SCENES; do
      step cpu_$sc 120 $B/prism render scenes/$sc.json -o $W/cpu/$sc.pfm --device $CPU --quiet
      if [ ! -f $W/logs/$sc.pfm ] || [ ! -f $W/cpu/$sc.pfm ]; then say "not compared (a render is missing): $sc"
      elif cmp -s $W/logs/$sc.pfm $W/cpu/$sc.pfm; then say "same bits on the GPU and the CPU: $sc"
      else say "DIFFER on the GPU and the CPU: $sc, $(cmp -l $W/logs/$sc.pfm $W/cpu/$sc.pfm 2>&1 | wc -l) bytes"; fi
    done
  fi
  for t in kernel_tests render_tests accel_tests host_tests plugin_tests device_tests; do
    step $t 240 $B/tests/$t -r compact --order decl &
  done
  for t in c_api_test c_api_arguments_test c_api_scene_test c_api_threads_test; do step $t 120 $B/tests/$t $R/scenes & done
  wait
  for t in kernel_tests render_tests accel_tests host_tests plugin_tests device_tests; do summary $t; done
fi
if [[ $PHASE == *bench* ]]; then
  M11=$($B/benchmarks/prism-bench mesh --data $G/data bunny/bunny_loop2_1.1M.ply 2>>$S | tail -1)
  step bench_accel 200 $B/benchmarks/prism-bench accel --device $IDX --repeat 5 --out $W/logs/accel \
    $G/data/bunny/bun_zipper.ply $M11
  tail -12 $W/logs/bench_accel.log >> $S
  step bench_firsthit 120 $B/benchmarks/prism-bench firsthit --device $IDX --repeat 3 --out $W/logs/firsthit \
    $G/data/bunny/bun_zipper.ply $M11
  tail -6 $W/logs/bench_firsthit.log >> $S
fi
if [[ $PHASE == *devices* ]]; then
  for spp in 4 16 32; do
    step devices_${spp}spp 60 $B/benchmarks/prism-bench devices --devices all --repeat 5 --spp $spp
    grep -E '^\[|shared frame|^scene' $W/logs/devices_${spp}spp.log >> $S
  done
fi
say "== done after $(( $(date +%s) - T0 )) s"
cp $S $OUT/summary.txt
tar czf $OUT/logs.tar.gz --exclude='*.pfm' -C $W logs
ls $W/logs/*.pfm > /dev/null 2>&1 && python3 - $W/logs $OUT/images.npz <<'PY'
import glob, os, sys
import numpy as np
def pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip(); w, h = map(int, f.readline().split()); scale = float(f.readline())
        a = np.frombuffer(f.read(), dtype='<f4' if scale < 0 else '>f4')
    return a.reshape(h, w, 3 if kind == b'PF' else 1)[::-1]
np.savez_compressed(sys.argv[2], **{os.path.basename(p)[:-4]: pfm(p).astype(np.float16)
                                    for p in sorted(glob.glob(sys.argv[1] + '/*.pfm'))})
PY
cat $S
