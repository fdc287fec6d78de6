#!/usr/bin/env bash
# README command 2: install dependencies, build everything (into build/) and run
# the whole test suite with CTest. With CI=true, compiler warnings are errors.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc)"
step() { printf '\n==> %s\n' "$*"; }

# Explicit ON/OFF (not just "ON in CI") so that a cached value from an earlier
# configure never silently decides.
werror=OFF
if [[ "${CI:-}" == "true" ]]; then
  werror=ON
fi

step "1/4 dependencies (scripts/setup.sh)"
"$root/scripts/setup.sh"

step "2/4 configure (build/, Ninja, Release, HUSH_WERROR=${werror})"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DHUSH_WERROR="$werror" -DHUSH_BUILD_TESTS=ON

step "3/4 build all (${jobs} jobs)"
cmake --build "$root/build" --parallel "$jobs"

# Two test processes: CI machines have two cores, and lavapipe uses threads of its own.
step "4/4 test: ctest --test-dir build --output-on-failure -j2"
start=$SECONDS
ctest --test-dir "$root/build" --output-on-failure -j2
printf '\n==> all tests passed in %ds\n' "$((SECONDS - start))"
