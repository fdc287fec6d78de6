#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer with leak
# checking, in build-sanitize/ (scripts/test.sh with HUSH_SANITIZE set).
# Any report fails the test that made it. Options and suppressions:
# tests/sanitize/ (docs/reliability.md, "Sanitizers").
#
#   scripts/sanitize.sh [ctest arguments, e.g. -R passes.svgf]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
HUSH_SANITIZE="${HUSH_SANITIZE:-address,undefined}" exec "$root/scripts/test.sh" "$@"
