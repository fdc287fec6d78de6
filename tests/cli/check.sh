#!/usr/bin/env bash
# `hush check`: the tracer's frames pass every convention (exit 0, one line each);
# bad arguments and folders are errors naming what is wrong (exit 2). The broken
# conventions themselves are tested in tests/tracer/test_frame_check.cpp.
# Usage: check.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" render --scene room --size 48x48 --frames 3 --reference-spp 0 --out frames > /dev/null
"$hush" check frames > out.txt || fail "hush check on the tracer's frames failed: $(cat out.txt)"
for convention in motion camera normal depth meshid albedo radiance; do
    grep -qE "^  pass  $convention " out.txt || fail "$convention did not pass: $(cat out.txt)"
done
grep -qF "7 passed, 0 failed, 0 skipped" out.txt || fail "summary: $(cat out.txt)"
echo "ok: the tracer's frames pass every check"

"$hush" check frames --frames 1 > one.txt
grep -qE "^  skip  motion .*two consecutive frames" one.txt || fail "one frame: $(cat one.txt)"
echo "ok: one frame skips the motion check, saying why"

"$hush" render --scene room --size 48x48 --frames 2 --reference-spp 0 --channels color,albedo --out bare > /dev/null
"$hush" check bare > bare.txt
grep -qE "^  skip  normal .*'normal'" bare.txt || fail "missing layer not named: $(cat bare.txt)"
echo "ok: a missing layer is named"

expect_exit 2 "no-such-folder" check no-such-folder
expect_exit 2 "--first" check frames --first 9
expect_exit 2 "name the folder" check
