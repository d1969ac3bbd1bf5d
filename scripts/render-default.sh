#!/usr/bin/env bash
# Sets everything up, builds, and renders the default scene (scenes/whitted.json)
# to whitted.png in the repository root.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PRISM_BUILD_DIR:-$root/build}"

bash "$root/scripts/build.sh"
"$build/prism" render "$root/scenes/whitted.json" -o "$root/whitted.png"
