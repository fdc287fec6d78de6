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
echo "determinism: $count EXR outputs and the report metrics identical across two processes"
