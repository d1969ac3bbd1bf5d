#!/usr/bin/env bash
# The Python package's tests: a virtual environment in build/venv (numpy and
# pytest from PyPI), `pip install .` (scikit-build-core builds libprism into
# build/python/, incrementally after the first time), then pytest over
# python/tests and the Python examples.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="${PRISM_VENV:-$root/build/venv}"

[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
# The build backend, NumPy and pytest come from PyPI. A machine that cannot
# reach it cannot run these tests: say so plainly rather than fail the C++ suite.
probe="$(mktemp -d)"
if ! "$venv/bin/python" -m pip download --quiet --no-deps --dest "$probe" "scikit-build-core>=0.10" >/dev/null 2>&1; then
  rm -rf "$probe"
  echo "test-python: SKIPPED: no Python package index reachable (pip could not fetch scikit-build-core)" >&2
  exit 0
fi
rm -rf "$probe"
"$venv/bin/python" -m pip install --quiet "$root[test]"
# Not from python/, whose prism/ folder would shadow the installed package.
cd "$root"
# The kernels' compile cache beside the C++ tests' (a fresh one costs a few seconds).
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$root/build/pocl-cache}" XDG_CACHE_HOME="${XDG_CACHE_HOME:-$root/build/test-cache}"
"$venv/bin/pytest" -q "$root/python/tests" "$@"
for example in "$root"/examples/python/*.py; do
  "$venv/bin/python" "$example" --check
done
