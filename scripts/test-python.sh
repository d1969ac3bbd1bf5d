#!/usr/bin/env bash
# The Python package's tests: a virtual environment in build/venv (numpy and
# pytest from PyPI), `pip install .` (scikit-build-core builds libprism into
# build/python/, incrementally after the first time), then pytest over
# python/tests and the Python examples.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="${PRISM_VENV:-$root/build/venv}"

[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --upgrade pip >/dev/null
"$venv/bin/python" -m pip install --quiet "$root[test]"
# Not from python/, whose prism/ folder would shadow the installed package.
cd "$root"
# The kernels' compile cache beside the C++ tests' (a fresh one costs a few seconds).
export POCL_CACHE_DIR="${POCL_CACHE_DIR:-$root/build/pocl-cache}" XDG_CACHE_HOME="${XDG_CACHE_HOME:-$root/build/test-cache}"
"$venv/bin/pytest" -q "$root/python/tests" "$@"
for example in "$root"/examples/python/*.py; do
  "$venv/bin/python" "$example" --check
done
