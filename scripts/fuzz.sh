#!/usr/bin/env bash
# Fuzzes the scene parsers (OBJ, MTL, JSON scene) with libFuzzer, ASan and UBSan.
# Not part of the normal build: it needs clang (Debian 12: clang-14 and
# libclang-rt-14-dev) and builds the harnesses of tests/fuzz/ into build-fuzz/.
#
#   scripts/fuzz.sh [--seconds N] [--update-corpus] [obj|mtl|scene ...]
#
# Each parser runs N seconds (default 90) from its kept corpus in
# tests/tracer/data/fuzz_corpus/<parser>/, writing new inputs to build-fuzz/corpus/.
# A crash, hang or sanitizer report stops the run and leaves the input in
# build-fuzz/artifacts/<parser>/; add it to the kept corpus once fixed, so the
# Catch2 test "fuzz corpus" replays it in every build.
# --update-corpus minimizes (-merge=1) the kept corpus plus what was found and keeps
# at most 100 of the result per parser, besides the seeds and crash reproducers.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds=90
update=0
max_kept=100
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --update-corpus) update=1; shift ;;
    obj|mtl|scene) targets+=("$1"); shift ;;
    *) echo "usage: $0 [--seconds N] [--update-corpus] [obj|mtl|scene ...]" >&2; exit 2 ;;
  esac
done
[[ ${#targets[@]} -gt 0 ]] || targets=(obj mtl scene)

cxx="${CXX:-clang++}"
if ! "$cxx" --version 2>/dev/null | grep -q clang; then
  echo "fuzz.sh needs clang with libFuzzer: apt-get install -y clang-14 libclang-rt-14-dev (or set CXX)" >&2
  exit 1
fi

build="$root/build-fuzz"
mkdir -p "$build/obj"
flags=(-std=c++20 -g -O1 -fno-omit-frame-pointer -fno-sanitize-recover=undefined
       -I"$root/tracer/include" -I"$root/tracer/src" -I"$root/rhi/include")
# The parsers are instrumented for coverage (fuzzer-no-link); each harness links
# libFuzzer's main (fuzzer).
sources=(text_parse obj_loader mtl_loader json_fields scene_file scene)
objects=()
for s in "${sources[@]}"; do
  o="$build/obj/$s.o"
  if [[ ! -f "$o" || "$root/tracer/src/$s.cpp" -nt "$o" || -n "$(find "$root/tracer/src" "$root/tracer/include" -newer "$o" -name '*.hpp' -print -quit)" ]]; then
    echo "==> compile $s.cpp"
    "$cxx" "${flags[@]}" -fsanitize=fuzzer-no-link,address,undefined -c "$root/tracer/src/$s.cpp" -o "$o"
  fi
  objects+=("$o")
done

# Link every harness before fuzzing any: a header edited during a long run must not
# give a harness and the parser objects two layouts of the same struct.
for t in "${targets[@]}"; do
  echo "==> build fuzz_$t"
  "$cxx" "${flags[@]}" -fsanitize=fuzzer,address,undefined "$root/tests/fuzz/fuzz_$t.cpp" "${objects[@]}" -o "$build/fuzz_$t"
done

export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in "${targets[@]}"; do
  kept="$root/tests/tracer/data/fuzz_corpus/$t"
  work="$build/corpus/$t"
  mkdir -p "$work" "$build/artifacts/$t" "$kept"
  echo "==> fuzz $t for ${seconds}s (new inputs in $work)"
  dict=()
  [[ -f "$root/tests/fuzz/$t.dict" ]] && dict=(-dict="$root/tests/fuzz/$t.dict")
  "$build/fuzz_$t" "$work" "$kept" "${dict[@]}" -max_len=4096 -timeout=5 -rss_limit_mb=2048 \
      -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/"
  if [[ $update == 1 ]]; then
    # Minimize what was found plus the kept corpus, then cap it: the kept corpus is
    # a regression test in the repository, not the fuzzer's working set. Hand-written
    # seeds (seed_*) and fixed crash reproducers (regress_*) always stay; of the rest,
    # at most $max_kept files spread evenly over the size range (small ones hit single
    # statements, large ones whole valid files).
    merged="$build/merged/$t"
    rm -rf "$merged" && mkdir -p "$merged"
    "$build/fuzz_$t" -merge=1 "$merged" "$kept" "$work" 2>&1 | grep -E "MERGE-OUTER: [0-9]+ new files" || true
    find "$kept" -type f ! -name 'seed_*' ! -name 'regress_*' -delete
    (cd "$merged" && ls -S -r | grep -v -E '^(seed|regress)_' || true) |
      awk -v n="$max_kept" '{ f[NR] = $0 } END { k = (NR < n) ? NR : n; for (i = 0; i < k; i++) print f[1 + int(i * NR / k)] }' |
      while read -r f; do cp "$merged/$f" "$kept/"; done
    echo "==> kept corpus for $t: $(ls "$kept" | wc -l) files"
  fi
done
