#!/usr/bin/env bash
# hush-bench-chains --quick on every built-in chain: it must finish, print a pass
# table with each pass's roofline fraction for every chain and size, and write a
# complete results file (checked by hush_bench_output_tests "[.bench-chains-output]").
# usage: bench_chains.sh <hush-bench-chains> <work folder> <hush_bench_output_tests>
set -euo pipefail
bench="$1"; work="$2"; checker="$3"
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"

chains=svgf,eaw,bmfr,mara,rdae
"$bench" --quick --chains "$chains" --output chains.json > stdout.txt 2> stderr.txt ||
    fail "hush-bench-chains --quick: $(tail -5 stderr.txt)"
tables=$(grep -c '^| pass | median ms | min | max | MiB read | MiB written | GB/s | of roofline |$' stdout.txt || true)
# Five chains at --quick's two sizes.
[[ "$tables" == 10 ]] || fail "expected 10 pass tables with a roofline column, found $tables"
HUSH_BENCH_OUTPUT="$work/chains.json" HUSH_BENCH_CHAINS="$chains" "$checker" "[.bench-chains-output]" ||
    fail "the results file failed its checks"
echo "ok: $tables pass tables, results file checked"
