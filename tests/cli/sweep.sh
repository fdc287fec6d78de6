#!/usr/bin/env bash
# hush sweep on the default scene at a tiny size, two chains with one knob each: the
# output is checked by the hidden Catch2 case of hush_sweep_tests (complete results,
# fronts non-dominated, plots, report images exist); a second run resumes (nothing is
# measured again) and a bad knob fails before anything is written.
# usage: sweep.sh <hush> <work folder> <hush_sweep_tests>
set -euo pipefail
hush="$1"; work="$2"; checker="$3"
source "$(dirname "$0")/cli_lib.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

args=(sweep --scene cornell --size 32x32 --frames 6 --reference-every 3 --reference-spp 8 --reference-pairs --lag
      --chain svgf,eaw --vary svgf.atrous.iterations=1,3 --vary eaw.atrous.iterations=2,4 --out out)
"$hush" "${args[@]}" > first.txt 2> first.err || fail "hush sweep: $(cat first.err)"
grep -q "svgf atrous.iterations=3" first.txt || fail "table lacks a configuration: $(cat first.txt)"
HUSH_SWEEP_OUTPUT="$work/out" "$checker" "[.sweep-output]" || fail "the sweep's output failed its checks"
echo "ok: sweep output checked"

# Resume: the same command reuses the frames and every measurement.
cp out/sweep.json first.json
"$hush" "${args[@]}" > second.txt 2> second.err || fail "second hush sweep: $(cat second.err)"
grep -q "reusing the frames" second.txt || fail "frames were rendered again: $(cat second.txt)"
cmp -s <(grep -v '"date"' first.json) <(grep -v '"date"' out/sweep.json) || fail "the resumed sweep measured again"
HUSH_SWEEP_OUTPUT="$work/out" "$checker" "[.sweep-output]" || fail "the resumed sweep's output failed its checks"
echo "ok: resumed without measuring again"

# A knob that names no setting fails before any work, naming it.
expect_exit 2 "unknown field 'iterashuns'" sweep --chain svgf --vary svgf.atrous.iterashuns=1,2 --out bad
nothing_written bad

# Budget mode picks from the sweep and says which and why.
frames_dir=$(ls -d out/frames/*/)
"$hush" denoise --in "$frames_dir" --out budget --budget-ms 1000 --sweep out/sweep.json > budget.txt 2> budget.err ||
    fail "hush denoise --budget-ms: $(cat budget.err)"
grep -q "budget 1e+03 ms: '.*' (.*): the best mean SSIM" budget.txt || fail "budget mode did not say why: $(cat budget.txt)"
expect_exit 2 "no configuration of the sweep runs within 1e-06 ms" denoise --in "$frames_dir" --out budget2 \
    --budget-ms 0.000001 --sweep out/sweep.json
nothing_written budget2
echo "ok: budget mode"

# Interrupted part way (the device lost at its 1500th submission: two of four configurations done), a sweep keeps what it
# finished: sweep.json says "complete": false, and the same command, rerun without
# --overwrite, measures only what is missing.
args[${#args[@]}-1]=int
set +e
HUSH_INJECT_FAULT=device-lost:1500 "$hush" "${args[@]}" > int1.txt 2> int1.err
code=$?
set -e
[[ $code == 2 ]] && grep -q "device-lost" int1.err || fail "interrupted sweep: exit $code: $(cat int1.err)"
grep -q '"complete": false' int/sweep.json || fail "no partial sweep.json after the interruption"
"$hush" "${args[@]}" > int2.txt 2> int2.err || fail "resumed sweep: $(cat int2.err)"
grep -q "resuming: an earlier run" int2.txt || fail "the rerun did not resume: $(cat int2.txt)"
grep -qE "sweep done: [1-3] run\(s\) measured, [1-3] reused" int2.err || fail "the rerun measured everything again: $(cat int2.err)"
HUSH_SWEEP_OUTPUT="$work/int" "$checker" "[.sweep-output]" || fail "the resumed sweep's output failed its checks"
echo "ok: an interrupted sweep resumes"

# Exposure sweep: SVGF, BMFR, Mara et al. and EAW (its scale-free default colour weight)
# are scale-equivariant (docs/sweep.md): with radiance and reference times 1e-6 and 1e6
# (the tonemap scaled back) their RMSE stays within 0.1 % of exposure 1's. (The RDAE's
# network is not; the table shows by how much.)
"$hush" sweep --scene cornell --size 32x32 --frames 6 --reference-every 3 --reference-spp 8 \
    --chain svgf,bmfr,mara,eaw --exposure 1e-6,1,1e6 --out exposure > exposure.txt 2> exposure.err ||
    fail "exposure sweep: $(cat exposure.err)"
grep -q "^exposure stability" exposure.txt || fail "no exposure table: $(cat exposure.txt)"
rows=$(grep -E "^\| cornell-32x32 \| (svgf|bmfr|mara|eaw) \(its settings\)" exposure.txt)
[[ $(wc -l <<< "$rows") == 4 ]] || fail "exposure table rows missing: $(cat exposure.txt)"
awk -F'|' '{ for (i = 4; i < NF; ++i) if ($i + 0 < 0.999 || $i + 0 > 1.001) { print "out of bounds: " $0; exit 1 } }' \
    <<< "$rows" || fail "a scale-equivariant chain changed with exposure: $rows"
echo "ok: svgf, bmfr, mara and eaw are exposure-invariant within 0.1 %"

# Budget mode without a sweep measures the built-in chains on the frames first; frames
# without a reference cannot be measured, which it says before writing anything.
"$hush" denoise --in "$frames_dir" --out budget3 --budget-ms 1000 > budget3.txt 2> budget3.err ||
    fail "hush denoise --budget-ms without --sweep: $(cat budget3.err)"
grep -q "without --sweep: measuring the built-in chains" budget3.txt || fail "no quick sweep: $(cat budget3.txt)"
grep -q "budget 1e+03 ms: '.*' (.* (its defaults)): the best mean SSIM" budget3.txt ||
    fail "budget mode without a sweep did not say why: $(cat budget3.txt)"
"$hush" render --scene cornell --size 16x16 --frames 2 --reference-spp 0 --out unscored \
    --channels color,direct,indirect,matte,glossy,albedo,specular,normal,position,depth,motion,roughness,meshid,virtualpos,emission > /dev/null
expect_exit 2 "some frames must carry a 'reference' layer" denoise --in unscored --out budget4 --budget-ms 10
nothing_written budget4
echo "ok: budget mode without a sweep"
