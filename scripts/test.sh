#!/usr/bin/env bash
# README command 2: install dependencies, build everything and run the whole test
# suite with CTest. Arguments are passed to ctest (e.g. -R passes.svgf).
#
# With CI=true (what .ci/run sets), compiler warnings are errors. HUSH_SANITIZE=address,undefined
# builds into build-sanitize/ instead and runs the suite under those sanitizers with
# leak checking on (scripts/sanitize.sh; docs/reliability.md, "Sanitizers").
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
sanitize="${HUSH_SANITIZE:-}"
build="$root/build"
if [[ -n "$sanitize" ]]; then
  build="$root/build-sanitize"
fi

step "1/4 dependencies (scripts/setup.sh)"
"$root/scripts/setup.sh"

step "2/4 configure (${build#"$root/"}/, Ninja, Release, HUSH_WERROR=${werror}, HUSH_SANITIZE=${sanitize:-none})"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DHUSH_WERROR="$werror" -DHUSH_BUILD_TESTS=ON -DHUSH_SANITIZE="$sanitize"

step "3/4 build all (${jobs} jobs)"
cmake --build "$build" --parallel "$jobs"

# Two test processes: CI machines have two cores, and lavapipe uses threads of its own.
# A sanitized binary carries its own sanitizer options (tests/sanitize/runtime_defaults.c).
step "4/4 test: ctest --test-dir ${build#"$root/"} --output-on-failure -j2 $*"
start=$SECONDS
ctest --test-dir "$build" --output-on-failure -j2 "$@"
printf '\n==> all tests passed in %ds%s\n' "$((SECONDS - start))" "${sanitize:+ (under -fsanitize=$sanitize)}"
