#!/usr/bin/env bash
# --out loses no one's data: a folder of unknown files is refused (unless
# --overwrite, which still leaves files hush did not write alone), a file given for
# a folder is refused, and a rerun into an earlier run's folder removes that run's
# stale outputs and nothing else (docs/reliability.md).
# Usage: output_folder.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" render --scene cornell --size 16x16 --frames 2 --reference-spp 4 --out frames > /dev/null
[[ -f frames/hush-run.json ]] || fail "render wrote no manifest"

# A rerun with fewer chains removes the first run's outputs of the chain it dropped.
"$hush" denoise --in frames --out out --chain eaw,svgf --no-png > /dev/null
[[ -f out/eaw/frame_0001.exr && -f out/svgf/frame_0001.exr ]] || fail "first run's outputs missing"
"$hush" denoise --in frames --out out --chain svgf --no-png > /dev/null
[[ ! -e out/eaw/frame_0001.exr ]] || fail "stale out/eaw/frame_0001.exr left behind"
[[ -f out/svgf/frame_0001.exr ]] || fail "rerun's output missing"
echo "ok: a rerun removed the stale eaw outputs"

# A user's own file in the earlier run's folder is not an output: it stays.
echo "mine" > out/notes.txt
"$hush" denoise --in frames --out out --chain eaw --no-png > /dev/null
[[ "$(cat out/notes.txt)" == mine ]] || fail "a user's file in a hush folder was touched"
echo "ok: a user's file in a run folder survives a rerun"

# A folder hush did not make is refused before any work, and left as it was.
mkdir -p theirs; echo "precious" > theirs/data.txt
expect_exit 2 "--overwrite" denoise --in frames --out theirs --chain eaw
[[ "$(ls theirs)" == data.txt ]] || fail "refused run wrote into theirs/: $(ls theirs)"
expect_exit 2 "--overwrite" render --scene cornell --size 8x8 --frames 1 --out theirs
[[ "$(ls theirs)" == data.txt ]] || fail "refused render wrote into theirs/"
"$hush" denoise --in frames --out theirs --chain eaw --no-png --overwrite > /dev/null
[[ "$(cat theirs/data.txt)" == precious && -f theirs/eaw/frame_0000.exr ]] || fail "--overwrite run"
echo "ok: --overwrite writes beside the user's files and keeps them"

# A file given for --out: refused, and the file is unchanged.
echo "a file" > plain.txt
expect_exit 2 "exists and is not a folder" denoise --in frames --out plain.txt --chain eaw
[[ "$(cat plain.txt)" == "a file" ]] || fail "plain.txt changed"

# A folder that cannot be written: found before any work (skipped as root, who can write anywhere).
if [[ $(id -u) != 0 ]]; then
    mkdir -p locked; chmod a-w locked
    expect_exit 2 "not writable" denoise --in frames --out locked/out --chain eaw
    chmod u+w locked
fi
echo "all output-folder checks passed"
