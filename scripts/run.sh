#!/usr/bin/env bash
# README command 1: install dependencies, build hush (Release, Ninja, into build/)
# and run the main job, `hush demo`: render the default scene (cornell, 256x256,
# 32 frames, a 512-spp reference on every 8th), denoise it with EAW and SVGF, and
# write images, a side-by-side strip per scored frame, tables and out/report.json.
# Arguments go to `hush demo` (e.g. --out other/ --scene room); see `hush demo --help`.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc)"
step() { printf '\n==> %s\n' "$*"; }

step "1/4 dependencies (scripts/setup.sh)"
"$root/scripts/setup.sh"

step "2/4 configure (build/, Ninja, Release)"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release

# Only what the main job needs; scripts/test.sh builds everything.
step "3/4 build the hush CLI (${jobs} jobs)"
cmake --build "$root/build" --parallel "$jobs" --target hush

step "4/4 run: build/samples/cli/hush demo --out out $*"
"$root/build/samples/cli/hush" demo --out "$root/out" "$@"
