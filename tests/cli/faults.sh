#!/usr/bin/env bash
# The driver's failures, injected (HUSH_INJECT_FAULT, rhi/fault_injection.hpp): out
# of device memory and a device lost mid-run give exit 2 and the error kind, leave
# no partial output (no frame of the failed run, no temporary), and the same command
# without the fault then runs in the same folder without --overwrite.
# Usage: faults.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" render --scene glossy --size 32x32 --frames 4 --reference-spp 4 --out frames > /dev/null

# no_partial_output <folder>: no image and no temporary of the failed run is left.
no_partial_output() {
    local left
    left="$(find "$1" -type f \( -name '*.exr' -o -name '*.png' -o -name '*.tmp-*' -o -name report.json \) | head -5)"
    [[ -z "$left" ]] || fail "the failed run left: $left"
}

# A late device loss: frames 0 and 1 were already written when it fails.
HUSH_INJECT_FAULT=device-lost:6 expect_exit 2 "error (device-lost)" denoise --in frames --out lost --chain svgf
no_partial_output lost
"$hush" denoise --in frames --out lost --chain svgf > /dev/null || fail "the rerun after a device loss failed"
[[ -f lost/svgf/frame_0003.exr && -f lost/report.json ]] || fail "the rerun after a device loss wrote no outputs"

HUSH_INJECT_FAULT=out-of-device-memory:4 expect_exit 2 "error (out-of-memory)" denoise --in frames --out oom --chain eaw,bmfr
grep -qF "out of device memory" stderr.txt || fail "the out-of-memory message does not say which memory"
no_partial_output oom

# A failed rerun over a complete earlier run removes only what it wrote itself.
"$hush" denoise --in frames --out keep --chain eaw > /dev/null
HUSH_INJECT_FAULT=device-lost:6 expect_exit 2 "error (device-lost)" denoise --in frames --out keep --chain svgf
[[ -f keep/eaw/frame_0003.exr ]] || fail "a failed run removed an earlier run's output"
[[ ! -e keep/svgf ]] || fail "a failed run left its own outputs"
"$hush" denoise --in frames --out keep --chain svgf > /dev/null || fail "the rerun over a failed run failed"

HUSH_INJECT_FAULT=oops expect_exit 2 "unknown fault 'oops'" denoise --in frames --out bad --chain eaw
echo "faults: device loss and out-of-memory give exit 2, no partial output, and a clean rerun"
