#!/usr/bin/env bash
# Fuzzes every reader of user files with libFuzzer, ASan and UBSan: the scene
# parsers (obj, mtl, scene), the EXR frame reader (exr_frame), the BMFR dataset
# reader (bmfr_dataset), chain files (chain_file) and the RDAE weights reader
# (rdae_weights). Not part of the normal build: it needs clang (Debian 12: clang-14
# and libclang-rt-14-dev) and builds tests/fuzz/ into build-fuzz/ with
# -DHUSH_BUILD_FUZZERS=ON.
#
#   scripts/fuzz.sh [--seconds N | --runs N] [--update-corpus] [target ...]
#
# Each target runs N seconds (default 90), or N executions, from its kept corpus
# (tests/tracer/data/fuzz_corpus/<target>/ or tests/passes/data/fuzz_corpus/<target>/),
# writing new inputs to build-fuzz/corpus/. A crash, hang or sanitizer report stops
# the run and leaves the input in build-fuzz/artifacts/<target>/; add it to the kept
# corpus as regress_<what>, once fixed, so that the Catch2 "fuzz corpus" tests replay
# it in every build. Each run's final statistics go to build-fuzz/stats/<target>.txt.
# --update-corpus minimizes (-merge=1) the kept corpus plus what was found and keeps
# at most 100 of the result per target, besides the seeds and crash reproducers.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
all=(obj mtl scene exr_frame bmfr_dataset chain_file rdae_weights)
limit=(-max_total_time=90)
update=0
max_kept=100
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) limit=(-max_total_time="$2"); shift 2 ;;
    --runs) limit=(-runs="$2"); shift 2 ;;
    --update-corpus) update=1; shift ;;
    obj|mtl|scene|exr_frame|bmfr_dataset|chain_file|rdae_weights) targets+=("$1"); shift ;;
    *) echo "usage: $0 [--seconds N | --runs N] [--update-corpus] [${all[*]}]" >&2; exit 2 ;;
  esac
done
[[ ${#targets[@]} -gt 0 ]] || targets=("${all[@]}")

if ! "${CXX:-clang++}" --version 2>/dev/null | grep -q clang; then
  echo "fuzz.sh needs clang with libFuzzer: apt-get install -y clang-14 libclang-rt-14-dev (or set CXX)" >&2
  exit 1
fi

build="$root/build-fuzz"
# Every library is instrumented for coverage (fuzzer-no-link); each harness links
# libFuzzer's main. All harnesses are built before any runs, so that a header edited
# during a long run cannot give a harness and a library two layouts of one struct.
CC="${CC:-clang}" CXX="${CXX:-clang++}" cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DHUSH_BUILD_TESTS=OFF -DHUSH_BUILD_SAMPLES=OFF -DHUSH_BUILD_FUZZERS=ON \
    -DHUSH_SANITIZE=fuzzer-no-link,address,undefined > /dev/null
cmake --build "$build" --target "${targets[@]/#/fuzz_}"

kept_corpus() {
  case "$1" in
    chain_file|rdae_weights) echo "$root/tests/passes/data/fuzz_corpus/$1" ;;
    *) echo "$root/tests/tracer/data/fuzz_corpus/$1" ;;
  esac
}

export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in "${targets[@]}"; do
  kept="$(kept_corpus "$t")"
  work="$build/corpus/$t"
  mkdir -p "$work" "$build/artifacts/$t" "$build/stats" "$kept"
  echo "==> fuzz $t (${limit[*]}; new inputs in $work)"
  dict=()
  [[ -f "$root/tests/fuzz/$t.dict" ]] && dict=(-dict="$root/tests/fuzz/$t.dict")
  # Binary formats need room for a whole small file (the seeds are 2-16 KB).
  max_len=4096
  [[ $t == exr_frame || $t == bmfr_dataset || $t == rdae_weights ]] && max_len=20000
  "$build/tests/fuzz/fuzz_$t" "$work" "$kept" "${dict[@]}" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
      "${limit[@]}" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" 2>&1 | tee "$build/stats/$t.log" |
      grep -E "^(#[0-9]+ *(DONE|INITED)|stat::|==[0-9]+==ERROR|SUMMARY)" || true
  grep -E "^stat::" "$build/stats/$t.log" > "$build/stats/$t.txt" || true
  if grep -qE "ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer)|runtime error|deadly signal" "$build/stats/$t.log"; then
    echo "==> fuzz $t found a problem: see $build/stats/$t.log and $build/artifacts/$t/" >&2
    exit 1
  fi
  if [[ $update == 1 ]]; then
    # Minimize what was found plus the kept corpus, then cap it: the kept corpus is
    # a regression test in the repository, not the fuzzer's working set. Hand-written
    # seeds (seed_*) and fixed crash reproducers (regress_*) always stay; of the rest,
    # at most $max_kept files spread evenly over the size range (small ones hit single
    # statements, large ones whole valid files).
    merged="$build/merged/$t"
    rm -rf "$merged" && mkdir -p "$merged"
    "$build/tests/fuzz/fuzz_$t" -merge=1 -max_len="$max_len" "$merged" "$kept" "$work" 2>&1 | grep -E "MERGE-OUTER: [0-9]+ new files" || true
    find "$kept" -type f ! -name 'seed_*' ! -name 'regress_*' -delete
    (cd "$merged" && ls -S -r | grep -v -E '^(seed|regress)_' || true) |
      awk -v n="$max_kept" '{ f[NR] = $0 } END { k = (NR < n) ? NR : n; for (i = 0; i < k; i++) print f[1 + int(i * NR / k)] }' |
      while read -r f; do cp "$merged/$f" "$kept/"; done
    echo "==> kept corpus for $t: $(ls "$kept" | wc -l) files"
  fi
done
