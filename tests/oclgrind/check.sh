#!/usr/bin/env bash
# Runs one prism command under Oclgrind, the OpenCL device simulator that checks
# every memory access of every kernel, and fails on any report.
#   check.sh memory PRISM ARGS...  out-of-bounds accesses, data races and API misuse
#                                  (kernels built as the driver builds them)
#   check.sh uninit PRISM ARGS...  reads of uninitialised values, kernels built with
#                                  -cl-opt-disable: Oclgrind 21.10's checker stops at
#                                  the `freeze` instruction optimised builds contain
#                                  (and at the noalias scopes forced inlining leaves,
#                                  hence PRISM_NO_FORCED_INLINE); fills, copies and
#                                  partial writes go through a copy kernel and no
#                                  buffer is released (PRISM_HOST_TRANSFERS: the
#                                  checker's blind spots, host/device/checked_transfers.h).
# Each run has its own kernel cache, so the kernels are built under the options
# given here and not taken from a PoCL build.
set -euo pipefail
mode="$1"
shift
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
case "$mode" in
  memory) checks=(--check-api --data-races) ;;
  uninit) checks=(--uninitialized --build-options "-cl-opt-disable -DPRISM_NO_FORCED_INLINE")
          export PRISM_HOST_TRANSFERS=1 ;;
  *) echo "check.sh: unknown mode '$mode' (memory or uninit)" >&2; exit 2 ;;
esac
export XDG_CACHE_HOME="$work/cache"
cd "$work"
status=0
oclgrind "${checks[@]}" --max-errors 20 --log "$work/oclgrind.log" "$@" >"$work/out.txt" 2>&1 || status=$?
cat "$work/out.txt"
if [ "$status" -ne 0 ]; then
  echo "check.sh: the command failed under Oclgrind (exit $status)" >&2
  exit 1
fi
if [ -s "$work/oclgrind.log" ]; then
  echo "check.sh: Oclgrind reported ($mode):" >&2
  head -80 "$work/oclgrind.log" >&2
  exit 1
fi
echo "check.sh: Oclgrind ($mode): no reports"
