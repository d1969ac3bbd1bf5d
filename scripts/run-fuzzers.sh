#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang with ASan + UBSan) into
# build-fuzz/ and runs each for $PRISM_FUZZ_SECONDS seconds (default 60),
# seeded with the corpus in tests/data (the scene loader: with scenes/). Fails if
# any target finds a crash, a sanitizer error, a leak, a timeout (a hang) or an
# out-of-memory.
# $PRISM_FUZZ_RUNS, if set, also stops each target after that many executions
# (the long budget of docs/reliability.md: PRISM_FUZZ_RUNS=10000000 with a
# PRISM_FUZZ_SECONDS large enough not to stop it first).
# Usage: scripts/run-fuzzers.sh [obj|ply|off|scene|api ...]   (default: all five)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PRISM_FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${PRISM_FUZZ_SECONDS:-60}"
runs="${PRISM_FUZZ_RUNS:+-runs=$PRISM_FUZZ_RUNS}"
data="$root/tests/data"
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj ply off scene api)

if ! command -v clang++ >/dev/null; then
  echo "run-fuzzers: clang++ not found (Debian: clang libclang-rt-14-dev)" >&2
  exit 1
fi
CC=clang CXX=clang++ cmake -S "$root/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --parallel "$(nproc)" >/dev/null

failed=()
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"        # new inputs go here; kept between runs
  artifacts="$build/artifacts/$t/" # crashing inputs land here
  mkdir -p "$corpus" "$artifacts"
  # Seeds: every file of the format from the corpus, good and bad,
  # plus the test meshes (inputs over -max_len are cut).
  seed_dir="$build/seeds/$t"
  rm -rf "$seed_dir" && mkdir -p "$seed_dir"
  if [ "$t" = scene ] || [ "$t" = api ]; then
    # The API target reads JSON text for its scene calls (and the rest as calls).
    cp "$root"/scenes/*.json "$seed_dir/"
  else
    seeds=()
    for d in "$data/formats/$t" "$data/formats/bad/$t"; do [ -d "$d" ] && seeds+=("$d"); done
    find "${seeds[@]}" "$data/meshes" -type f -iname "*.$t" -size -2M -exec cp -t "$seed_dir" {} + 2>/dev/null || true
    [ "$t" = off ] && cp "$data/formats/off/assimp/formatDetection" "$seed_dir/" 2>/dev/null || true
  fi
  dict="$root/fuzz/$t.dict"
  [ "$t" = api ] && dict="$root/fuzz/scene.dict"  # JSON's tokens, for the scene text among the calls
  echo "fuzzing $t for ${seconds}s (seeds: $(ls "$seed_dir" | wc -l) files)"
  if ! "$build/${t}_fuzzer" "$corpus" "$seed_dir" \
      -max_total_time="$seconds" $runs -max_len=65536 -rss_limit_mb=2048 -timeout=10 \
      -dict="$dict" -artifact_prefix="$artifacts" -print_final_stats=1 \
      >"$build/$t.log" 2>&1; then
    echo "  FAILED: see $build/$t.log and $artifacts" >&2
    tail -30 "$build/$t.log" >&2
    failed+=("$t")
  else
    grep -E "stat::number_executed_units|cov:" "$build/$t.log" | tail -2 | sed 's/^/  /'
  fi
done

if [ ${#failed[@]} -gt 0 ]; then
  echo "run-fuzzers: failures in: ${failed[*]}" >&2
  exit 1
fi
echo "run-fuzzers: no findings"
