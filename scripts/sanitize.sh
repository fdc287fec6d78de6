#!/usr/bin/env bash
# The whole test suite under AddressSanitizer (leak checking on) and
# UndefinedBehaviorSanitizer, in build-sanitize/ (RelWithDebInfo). Any report fails
# the test that made it. Suppressions (tests/sanitize/) cover only the Vulkan
# loader, the lavapipe driver, LLVM (its JIT) and the validation layer.
#
#   scripts/sanitize.sh [ctest arguments, e.g. -R passes.svgf]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
build="$root/build-sanitize"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHUSH_SANITIZE=address,undefined \
    -DHUSH_WERROR="$([[ "${CI:-}" == true ]] && echo ON || echo OFF)"
cmake --build "$build"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitize/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$root/tests/sanitize/ubsan.supp"
ctest --test-dir "$build" --output-on-failure -j2 "$@"
echo "sanitize: all tests passed under ASan + UBSan"
