#!/usr/bin/env bash
# Every subcommand's success path and help, as a user first meets them: `hush`,
# `--help`, `--version`, `info` (the adapters and the self-checks), `render`,
# `denoise`, `dataset` and `demo` on tiny inputs, each exiting 0 with its output
# where it says; an unknown command or option exits 2 naming it.
# Usage: subcommands.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" --help | grep -q "usage: hush <command>" || fail "hush --help prints no usage"
"$hush" --version | grep -qE "^hush [0-9]+\.[0-9]+\.[0-9]+" || fail "hush --version prints no version"
# Into a file first: `grep -q` stops reading at its match, and a long usage text
# (denoise lists every node type) would then end hush with SIGPIPE under pipefail.
for command in demo denoise sweep render dataset info; do
    "$hush" "$command" --help > help.txt || fail "hush $command --help exited $?"
    grep -q "usage: hush $command" help.txt || fail "hush $command --help prints no usage"
done
expect_exit 2 "usage: hush <command>"
expect_exit 2 "unknown command 'frobnicate'" frobnicate
expect_exit 2 "unknown argument '--frobnicate' for hush render" render --frobnicate

"$hush" info > info.txt || fail "hush info failed: $(tail -5 info.txt)"
grep -q "llvmpipe" info.txt || fail "hush info lists no lavapipe adapter"
grep -q "^PASS" info.txt || fail "hush info's self-checks did not pass"

"$hush" render --scene cornell --size 16x16 --frames 2 --reference-spp 4 --out frames > /dev/null
[[ -f frames/frame_0000.exr && -f frames/frame_0001.exr && -f frames/hush-run.json ]] || fail "render wrote $(ls frames)"
"$hush" denoise --in frames --out denoised --chain eaw > /dev/null
[[ -f denoised/eaw/frame_0001.exr && -f denoised/eaw/frame_0001.png && -f denoised/report.json ]] ||
    fail "denoise wrote $(ls -R denoised)"
"$hush" dataset --out dataset --sequences 1 --frames 2 --size 16x16 --reference-spp 4 > /dev/null
[[ -n "$(ls dataset/*.npy 2>/dev/null)" ]] || fail "dataset wrote $(ls dataset)"
"$hush" demo --size 16x16 --frames 4 --reference-every 4 --reference-spp 4 --chain eaw,svgf --out demo > demo.txt
[[ -f demo/report.json && -f demo/side_by_side/frame_0003.png && -f demo/graph.svgf.dot ]] || fail "demo wrote $(ls demo)"
grep -q "^| svgf |" demo.txt || fail "demo printed no table row for svgf"
echo "subcommands: help, version, info, render, denoise, dataset and demo succeed; unknown names exit 2"
