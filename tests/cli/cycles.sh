#!/usr/bin/env bash
# Blender Cycles frames straight into hush: `hush check` reads the fixture's
# multilayer EXRs (tests/tracer/data/cycles), and `hush denoise --reference` scores
# SVGF against the 256-sample renders of the same frames. (docs/blender.md)
# Usage: cycles.sh <hush> <work folder> <fixture folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"; fixture="$3"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" check "$fixture/frames" > check.txt || fail "hush check on the Cycles fixture failed: $(cat check.txt)"
grep -qE "^  pass  motion .*sign, direction and units OK" check.txt || fail "motion: $(cat check.txt)"
echo "ok: hush check passes Blender's motion vectors as hush reads them"

"$hush" denoise --in "$fixture/frames" --reference "$fixture/reference" --chain svgf,eaw --out out --no-png > out.txt 2> err.txt ||
    fail "hush denoise on Cycles frames: $(cat err.txt)"
row() { grep -E "^\| $1 \|" out.txt | head -1; }
noisy=$(row noisy | awk -F'|' '{print $3}'); svgf=$(row svgf | awk -F'|' '{print $3}')
[[ -n "$noisy" && -n "$svgf" ]] || fail "no quality table: $(cat out.txt)"
awk -v a="$svgf" -v b="$noisy" 'BEGIN { exit !(a < b) }' || fail "svgf RMSE $svgf does not beat the input's $noisy"
[[ -f out/svgf/frame_0004.exr ]] || fail "no outputs: $(ls out)"
echo "ok: svgf on Cycles frames: RMSE $svgf against the input's $noisy"

mkdir -p badref; cp "$fixture/reference/frame_0001.exr" badref/
expect_exit 2 "frame_0002.exr" denoise --in "$fixture/frames" --reference badref --chain svgf --out out2
nothing_written out2
echo "all Cycles checks passed"
