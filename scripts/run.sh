#!/usr/bin/env bash
# README command 1: install dependencies, build hush (Release, Ninja, into build/)
# and run the main job. For now the main job is `hush info`: it lists the Vulkan
# adapters with their limits and runs a compute self-check on the default one.
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

step "4/4 run: build/samples/cli/hush info"
"$root/build/samples/cli/hush" info "$@"
