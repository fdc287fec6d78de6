#!/usr/bin/python3
"""Weights and golden pairs for hush's C++ tests.

    # The golden pair of a weights file: PyTorch's unrolled forward on a sequence
    /usr/bin/python3 samples/rdae_training/export.py --weights W.safetensors --golden G.safetensors \\
        [--sequence DATASET.npy | --size 64x64] [--frames 3]
    # A small random (He-initialised, untrained) model, to test the network's structure
    /usr/bin/python3 samples/rdae_training/export.py --random --width 4 --levels 2 --weights W.safetensors ...
    # A training checkpoint to a weights file (fp16)
    /usr/bin/python3 samples/rdae_training/export.py --checkpoint OUT/checkpoint.pt --weights W.safetensors

The golden pair is computed from the weights as the file holds them (fp16 values
widened to fp32), so that hush and PyTorch multiply the very same numbers.
"""
import argparse
import os
import sys

import numpy as np
import torch

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rdae_training import weights as weights_file  # noqa: E402
from rdae_training.model import RDAE               # noqa: E402


def golden_input(args, multiple):
    if args.sequence:
        a = np.load(args.sequence, mmap_mode="r")
        x = torch.from_numpy(np.asarray(a[0, :args.frames], dtype=np.float32))
        h, w = (x.shape[-2] // multiple) * multiple, (x.shape[-1] // multiple) * multiple
        size = min(h, w, args.crop) if args.crop else None
        return x[..., :size or h, :size or w].contiguous()
    w, h = (int(v) for v in args.size.split("x"))
    g = torch.Generator().manual_seed(args.seed)
    x = torch.rand(args.frames, 7, h, w, generator=g)
    x[:, 3:5] = x[:, 3:5] * 2.0 - 1.0          # normals in [-1, 1]
    return x


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--weights", required=True, help="weights file to read (or write, with --random / --checkpoint)")
    p.add_argument("--random", action="store_true", help="write a random model's weights (fp32)")
    p.add_argument("--checkpoint", help="write this training checkpoint's weights (fp16)")
    p.add_argument("--width", type=int, default=4)
    p.add_argument("--levels", type=int, default=2)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--golden", help="write the golden input/output pair here")
    p.add_argument("--sequence", help="a `hush dataset` .npy whose first noise instance is the golden input")
    p.add_argument("--crop", type=int, default=64, help="square crop of --sequence (default 64)")
    p.add_argument("--size", default="32x32", help="random golden input's size, a multiple of 2^levels")
    p.add_argument("--frames", type=int, default=3)
    args = p.parse_args()
    if args.random:
        torch.manual_seed(args.seed)
        model = RDAE(args.width, args.levels)
        for name, value in model.named_parameters():      # non-zero biases, so that the test sees them
            if name.endswith("bias"):
                torch.nn.init.uniform_(value, -0.1, 0.1)
        weights_file.export(model, args.weights, half=False, random_seed=args.seed)
    elif args.checkpoint:
        state = torch.load(args.checkpoint, map_location="cpu")
        model = RDAE(state["width"], state["levels"])
        model.load_state_dict(state["model"])
        weights_file.export(model, args.weights, half=True, step=state["step"])
    if args.golden:
        model, _ = weights_file.load(args.weights)
        model.eval()
        weights_file.golden(model, golden_input(args, model.multiple), args.golden)
    written = [args.weights] if args.random or args.checkpoint else []
    print("wrote " + " and ".join(written + ([args.golden] if args.golden else [])))


if __name__ == "__main__":
    main()
