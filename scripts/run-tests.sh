#!/usr/bin/env bash
# Sets everything up, builds, and runs the whole test suite: each mesh-format
# fuzzer for a bounded time ($PRISM_FUZZ_SECONDS, default 60; 0 skips them)
# under AddressSanitizer and UndefinedBehaviorSanitizer, the Python package's
# tests (scripts/test-python.sh; PRISM_PYTHON_TESTS=0 skips them), then the
# CTest suite (last, so its summary closes the output).
#
# --sanitize (what CI runs, .ci/run): first the whole CTest suite again in a
# second build under AddressSanitizer and UndefinedBehaviorSanitizer
# (build-sanitize/; leaks too with PRISM_DETECT_LEAKS=1; the install,
# address-space-limit and Oclgrind tests are left out there, see
# tests/CMakeLists.txt), then all of the above.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PRISM_BUILD_DIR:-$root/build}"

if [ "${1:-}" = --sanitize ]; then
  bash "$root/scripts/build.sh" --sanitize
  # Leak detection only on request (PRISM_DETECT_LEAKS=1): LeakSanitizer's
  # stop-the-world tracer crashes now and then at exit among PoCL's worker threads
  # ("Tracer caught signal 11"), which would fail a sound run. PoCL's compiler
  # keeps some memory to the end (tests/sanitize/lsan.supp).
  (cd "${PRISM_SANITIZE_BUILD_DIR:-$root/build-sanitize}" &&
    ASAN_OPTIONS="detect_leaks=${PRISM_DETECT_LEAKS:-0}:abort_on_error=1" \
    LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0" \
    ctest --output-on-failure --parallel "$(nproc)" --timeout 900)
  echo "run-tests: the suite under ASan and UBSan passed; now the Release build"
elif [ $# -gt 0 ]; then
  echo "usage: scripts/run-tests.sh [--sanitize]" >&2
  exit 2
fi

bash "$root/scripts/build.sh"

if [ "${PRISM_FUZZ_SECONDS:-60}" != 0 ]; then
  bash "$root/scripts/run-fuzzers.sh"
fi

if [ "${PRISM_PYTHON_TESTS:-1}" != 0 ]; then
  bash "$root/scripts/test-python.sh"
fi

cd "$build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 600
