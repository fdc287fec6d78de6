#!/usr/bin/env bash
# The training toolkit end to end on tiny data, as CI runs it: `hush dataset` renders
# two 3-frame 32x32 sequences, train.py takes a few steps of a small network (resumes,
# and stops on SIGTERM with a checkpoint), export.py writes the weights' golden pair,
# and `hush denoise` runs the chain with the weights PyTorch wrote. Usage: smoke.sh <hush> <work folder>
set -euo pipefail
hush="$1"
work="$2"
toolkit="$(cd "$(dirname "$0")/.." && pwd)"
python=/usr/bin/python3
rm -rf "$work"
mkdir -p "$work"

"$hush" dataset --out "$work/data" --sequences 2 --scenes room,thin --frames 3 --size 32x32 --noise 2 \
    --reference-spp 4
test -f "$work/data/room_00000.npy" && test -f "$work/data/thin_00001.npy"

"$python" "$toolkit/train.py" --data "$work/data" --out "$work/train" --width 4 --levels 2 --frames 3 --batch 2 \
    --steps 3 --checkpoint-every 2
"$python" "$toolkit/train.py" --data "$work/data" --out "$work/train" --width 4 --levels 2 --frames 3 --batch 2 \
    --steps 5 --checkpoint-every 2 | tee "$work/resume.log"
grep -q "steps 3 -> 5" "$work/resume.log"          # resumed, not restarted
for f in checkpoint.pt losses.csv loss.png weights.safetensors; do test -s "$work/train/$f"; done
test "$(wc -l < "$work/train/losses.csv")" -eq 6    # header + 5 steps

# SIGTERM (or Ctrl-C) mid-run: the run stops after its step with a checkpoint.
"$python" "$toolkit/train.py" --data "$work/data" --out "$work/stopped" --width 4 --levels 2 --frames 3 --batch 2 \
    --steps 100000 --checkpoint-every 100000 > "$work/stop.log" &
trainer=$!
for _ in $(seq 120); do grep -q "^step 10/" "$work/stop.log" && break; sleep 0.5; done
kill -TERM "$trainer"
wait "$trainer"
grep -q "stopped at step [0-9]* on request" "$work/stop.log"
test -s "$work/stopped/checkpoint.pt"

"$python" "$toolkit/export.py" --weights "$work/train/weights.safetensors" --golden "$work/golden.safetensors" \
    --size 8x8 --frames 2

"$hush" render --scene cornell --frames 2 --size 32x32 --reference-spp 0 --channels all --out "$work/frames" > /dev/null
cat > "$work/chain.json" <<JSON
{"base": "rdae", "settings": {"width": 4, "levels": 2, "weights": "$work/train/weights.safetensors"}}
JSON
"$hush" denoise --in "$work/frames" --out "$work/denoised" --chain "$work/chain.json" > "$work/denoise.log"
test -f "$work/denoised/chain/frame_0001.exr"
echo "smoke: dataset, training (resumed), export and hush denoise with the trained weights all worked"
