#!/usr/bin/env bash
# Bad input frames are found before any work, all problems in one message naming
# each file; a gap in the frame indices resets the history with a warning; an image
# too large is refused before allocating (docs/reliability.md).
# Usage: input_frames.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" render --scene cornell --size 16x16 --frames 4 --reference-spp 4 --out frames > /dev/null
"$hush" render --scene cornell --size 8x8 --frames 1 --first 2 --reference-spp 0 --out small > /dev/null

# A frame of another size and a truncated frame: one message names both files.
mkdir -p mixed; cp frames/frame_000{0,1,3}.exr mixed/
cp small/frame_0002.exr mixed/frame_0002.exr
head -c 300 frames/frame_0003.exr > mixed/frame_0003.exr
expect_exit 2 "frame_0002.exr" denoise --in mixed --out out --chain eaw
grep -qF "frame_0003.exr" stderr.txt || fail "the truncated frame is not named: $(cat stderr.txt)"
grep -qF "8x8" stderr.txt || fail "the odd size is not given: $(cat stderr.txt)"
nothing_written out

# A chain whose layers the frames lack: named before any work.
"$hush" render --scene cornell --size 16x16 --frames 2 --reference-spp 0 --channels color,albedo --out bare > /dev/null
expect_exit 2 "normal" denoise --in bare --out out --chain svgf
nothing_written out

# A gap in the indices: the run goes on, warns, and resets the history there.
mkdir -p gap; cp frames/frame_000{0,1,3}.exr gap/
"$hush" denoise --in gap --out gapout --chain svgf --no-png > stdout.txt 2> stderr.txt || fail "gap run failed: $(cat stderr.txt)"
grep -qiF "gap" stderr.txt || grep -qiF "gap" stdout.txt || fail "no warning for the gap: $(cat stderr.txt)"
[[ -f gapout/svgf/frame_0003.exr ]] || fail "the frame after the gap was not written"
grep -qF "warnings" gapout/report.json || fail "report.json lacks the warnings"
echo "ok: a gap warns and resets the history"

# A size beyond what any GPU texture holds is refused before allocating. (Sizes under
# that limit that exceed the host's memory are refused by a check against the memory
# available, which depends on the machine, so it is not scripted here.)
expect_exit 2 "1 to 16384" render --scene cornell --size 60000x60000 --frames 1 --out huge
nothing_written huge

# --side-by-side on frames without a reference still writes the strip (noisy | chains).
"$hush" render --scene cornell --size 16x16 --frames 2 --reference-spp 0 --out unscored > /dev/null
"$hush" denoise --in unscored --out sbs --chain eaw --side-by-side --no-exr > /dev/null 2>&1 || fail "side-by-side run failed"
[[ -f sbs/side_by_side/frame_0001.png ]] || fail "no side-by-side strip for a frame without a reference: $(ls sbs)"
echo "ok: side-by-side strips for frames without a reference"
echo "all input-frame checks passed"
