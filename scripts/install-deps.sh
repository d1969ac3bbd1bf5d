#!/usr/bin/env bash
# Installs prism's build and run-time dependencies from Debian 12 packages, only
# those that are missing, so a second run costs nothing. Needs root (or sudo) when
# something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
  libcgal-dev libopenmesh-dev libopenimageio-dev openimageio-tools
  catch2 nlohmann-json3-dev
  libtinyobjloader-dev libgmp-dev libmpfr-dev libboost-dev
  libembree-dev            # benchmarks only: the reference column of prism-bench
  povray                   # benchmarks only: prism-bench povray
  clang libclang-rt-14-dev # fuzz targets (libFuzzer with ASan/UBSan)
  bc
  python3 python3-venv     # the Python package and its tests (scripts/test-python.sh)
  oclgrind                 # the kernels under a checking simulator (tests/oclgrind/)
  libopenmpi-dev openmpi-bin  # mpirun prism render: ranks share each frame (tests/mpi/)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "prism: installing missing Debian packages: ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
