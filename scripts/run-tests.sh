#!/usr/bin/env bash
# Sets everything up, builds, and runs the whole test suite: each mesh-format
# fuzzer for a bounded time ($PRISM_FUZZ_SECONDS, default 60; 0 skips them)
# under AddressSanitizer and UndefinedBehaviorSanitizer, the Python package's
# tests (scripts/test-python.sh; PRISM_PYTHON_TESTS=0 skips them), then the
# CTest suite (last, so its summary closes the output).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PRISM_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh"

if [ "${PRISM_FUZZ_SECONDS:-60}" != 0 ]; then
  bash "$root/scripts/run-fuzzers.sh"
fi

if [ "${PRISM_PYTHON_TESTS:-1}" != 0 ]; then
  bash "$root/scripts/test-python.sh"
fi

cd "$build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 600
