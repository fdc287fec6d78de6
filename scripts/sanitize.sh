#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer, in
# build-sanitize/ (RelWithDebInfo, -DHUSH_SANITIZE=address,undefined). Any report
# aborts the test that made it.
#
#   scripts/sanitize.sh [ctest arguments, e.g. -R passes.svgf]
#
# Leak checking is off: the Vulkan loader unloads lavapipe and the validation layer
# (dlclose) before LeakSanitizer runs, so their per-process allocations are
# reported from "<unknown module>" and no suppression by library name can match
# them (docs/reliability.md). install_consumer is left out: it builds an outside
# project, without sanitizer flags, against the sanitized static libraries.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
build="$root/build-sanitize"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHUSH_SANITIZE=address,undefined \
    -DHUSH_WERROR="$([[ "${CI:-}" == true ]] && echo ON || echo OFF)"
cmake --build "$build"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$root/tests/sanitize/ubsan.supp"
ctest --test-dir "$build" --output-on-failure -j2 -E '^install_consumer$' "$@"
echo "sanitize: all tests passed under ASan + UBSan"
