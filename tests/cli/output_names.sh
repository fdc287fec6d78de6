#!/usr/bin/env bash
# A chain's name is a folder under --out: names that would write elsewhere, or over
# another chain's or the job's own outputs, are refused before anything is written.
# Usage: output_names.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" render --scene cornell --size 16x16 --frames 2 --out frames > /dev/null

# expect_refused <chain list> <message part>: exit 2, the message, nothing written.
expect_refused() {
    rm -rf out
    set +e
    "$hush" denoise --in frames --out out --chain "$1" > stdout.txt 2> stderr.txt
    local code=$?
    set -e
    [[ $code == 2 ]] || fail "--chain $1: exit $code, expected 2"
    grep -qF -- "$2" stderr.txt || fail "--chain $1: message '$(cat stderr.txt)' lacks '$2'"
    if [[ -d out ]] && [[ -n "$(ls -A out)" ]]; then fail "--chain $1: wrote $(ls -A out)"; fi
    echo "ok: --chain $1 refused: $(cat stderr.txt)"
}

echo '{"name": "../escape", "base": "eaw"}' > up.json
expect_refused up.json "name: '../escape' is not a valid chain name"
echo "{\"name\": \"$work/abs\", \"base\": \"eaw\"}" > absolute.json
expect_refused absolute.json "is not a valid chain name"
echo '{"name": "a/b", "base": "eaw"}' > slash.json
expect_refused slash.json "'a/b' is not a valid chain name"
echo '{"name": "..", "base": "eaw"}' > dots.json
expect_refused dots.json "'..' is not a valid chain name"
echo '{"name": "noisy", "base": "eaw"}' > noisy.json
expect_refused noisy.json "is named 'noisy', which the output folder uses for something else"
echo '{"name": "side_by_side", "base": "eaw"}' > sbs.json
expect_refused sbs.json "is named 'side_by_side'"
expect_refused svgf,svgf "two chains are named 'svgf'"
echo '{"name": "eaw", "base": "svgf"}' > clash.json
expect_refused eaw,clash.json "two chains are named 'eaw'"
echo '{"base": "eaw"}' > "my chain.json"
expect_refused "my chain.json" "it comes from the file name: give \"name\" in the file"

# Nothing escaped the work folder: only what this script made is beside it.
[[ ! -e ../escape && ! -e "$work/abs" && ! -e a ]] || fail "a chain wrote outside --out"

# A good name still works.
echo '{"name": "eaw-fewer.levels_2", "base": "eaw", "settings": {"atrous": {"iterations": 2}}}' > good.json
"$hush" denoise --in frames --out out --chain eaw,good.json > /dev/null
[[ -f out/eaw-fewer.levels_2/frame_0001.exr ]] || fail "the good chain wrote no output"
echo "PASS"
