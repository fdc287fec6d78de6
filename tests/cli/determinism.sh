#!/usr/bin/env bash
# The same chains on the same frames in two processes write bit-identical EXR
# outputs and the same metrics (fixed reduction orders; no timing in the images).
# Usage: determinism.sh <hush> <work folder>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"
hush="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work"; cd "$work"

"$hush" render --scene glossy --size 32x32 --frames 4 --reference-spp 4 --channels all --out frames > /dev/null
chains=eaw,svgf,bmfr,mara,rdae
"$hush" denoise --in frames --out a --chain "$chains" --no-png > /dev/null
"$hush" denoise --in frames --out b --chain "$chains" --no-png > /dev/null

count=0
for file in a/*/frame_*.exr; do
    cmp -s "$file" "b/${file#a/}" || fail "${file#a/} differs between two runs"
    count=$((count + 1))
done
[[ $count == 24 ]] || fail "expected 24 EXR files (noisy and 5 chains x 4 frames), found $count"

# The metrics in the reports agree to the last digit (GPU times are left out).
metrics() { /usr/bin/python3 - "$1" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
def strip(node):
    if isinstance(node, dict):
        return {k: strip(v) for k, v in node.items() if "ms" not in k.lower() and "time" not in k.lower() and k != "environment"}
    if isinstance(node, list):
        return [strip(v) for v in node]
    return node
print(json.dumps(strip(report.get("chains", report)), sort_keys=True))
PY
}
[[ "$(metrics a/report.json)" == "$(metrics b/report.json)" ]] || fail "report metrics differ between two runs"

# `hush demo` twice prints the same quality table: every column but the GPU time
# (the last), in two processes that each render their own frames.
quality_table() {
    sed -n '/^quality:/,/^$/p' "$1" | grep '^| ' | awk -F'|' 'BEGIN { OFS = "|" } { $(NF-1) = ""; print }'
}
demo=(demo --size 32x32 --frames 8 --reference-every 4 --reference-spp 8 --chain eaw,svgf,bmfr,mara,rdae)
"$hush" "${demo[@]}" --out demo1 > demo1.txt
"$hush" "${demo[@]}" --out demo2 > demo2.txt
rows="$(quality_table demo1.txt | wc -l)"
[[ $rows == 8 ]] || fail "expected a quality table of 8 rows (header, rule, noisy, 5 chains) in hush demo's output, found $rows"
diff <(quality_table demo1.txt) <(quality_table demo2.txt) > /dev/null ||
    fail "hush demo printed different quality tables: $(diff <(quality_table demo1.txt) <(quality_table demo2.txt))"
echo "determinism: $count EXR outputs and the report metrics identical across two processes; hush demo's table too"
