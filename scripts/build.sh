#!/usr/bin/env bash
# Installs missing Debian packages, then configures and builds prism in Release
# into build/ (or $PRISM_BUILD_DIR). With --sanitize: everything under ASan and
# UBSan (RelWithDebInfo, no benchmarks) into build-sanitize/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PRISM_BUILD_DIR:-$root/build}"
config=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = --sanitize ]; then
  build="${PRISM_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
  config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRISM_SANITIZE=ON -DPRISM_BUILD_BENCHMARKS=OFF)
fi

bash "$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" "${config[@]}" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
