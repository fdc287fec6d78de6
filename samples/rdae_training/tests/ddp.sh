#!/usr/bin/env bash
# Distributed training on one machine: torchrun starts 2 processes (gloo), each takes
# a few steps on its own sequences, and afterwards both must hold the very same
# weights (DistributedDataParallel averaged every gradient). Usage: ddp.sh <hush> <work>
set -euo pipefail
hush="$1"
work="$2"
toolkit="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
"$hush" dataset --out "$work/data" --sequences 2 --scenes room,thin --frames 3 --size 32x32 --noise 2 \
    --reference-spp 4
# --redirects 1 --tee 1: Debian's torch 1.13 on Python 3.11 cannot parse the default
# (its Std enum has no member for 0 there); stdout goes to a log and to the console.
torchrun --standalone --nproc_per_node=2 --redirects 1 --tee 1 \
    "$toolkit/train.py" --data "$work/data" --out "$work/train" --width 4 --levels 2 --frames 3 --batch 1 \
    --steps 4 --threads 1 --rank-weights
/usr/bin/python3 - "$toolkit" "$work/train" <<'PY'
import os, sys
sys.path.insert(0, sys.argv[1])
from rdae_training import safetensors_io
a, _ = safetensors_io.read(os.path.join(sys.argv[2], "rank0.safetensors"))
b, _ = safetensors_io.read(os.path.join(sys.argv[2], "rank1.safetensors"))
assert a.keys() == b.keys()
different = [k for k in a if not (a[k] == b[k]).all()]
assert not different, f"ranks disagree on {different}"
print(f"ddp: both ranks hold identical weights ({len(a)} tensors) after 4 steps")
PY
