#!/usr/bin/python3
"""Trains hush's recurrent denoising autoencoder on sequences from `hush dataset`.

    /usr/bin/python3 samples/rdae_training/train.py --data DIR --out DIR [--width 32] ...

Adam (lr 0.001, betas 0.9 / 0.99), minibatches of 4 sequences of 7 frames, the loss of
Sec. 4.4, the learning rate ramped up tenfold over the warm-up, then 1/sqrt(t) (Sec. 5.3).
Writes to --out: checkpoint.pt (resumed from when present), losses.csv, loss.png and
weights.safetensors (fp16, what hush loads). Several processes (torchrun, one machine
or many) train one model with DistributedDataParallel: gloo on CPUs, NCCL on GPUs.
"""
import argparse
import csv
import math
import os
import signal
import sys
import time

import torch
import torch.distributed as dist
from torch.nn.parallel import DistributedDataParallel

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rdae_training import weights as weights_file            # noqa: E402
from rdae_training.data import SequenceSampler, sequence_files  # noqa: E402
from rdae_training.loss import Loss                          # noqa: E402
from rdae_training.model import RDAE, Unrolled, parameter_count  # noqa: E402


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--data", required=True, help="folder of .npy sequences (hush dataset)")
    p.add_argument("--out", required=True, help="folder for checkpoint, losses, plot and weights")
    p.add_argument("--width", type=int, default=32, help="features of the first stage (paper: 32)")
    p.add_argument("--levels", type=int, default=6, help="encoder stages / poolings (paper: 6)")
    p.add_argument("--steps", type=int, default=1000, help="optimiser steps in all (a resumed run continues)")
    p.add_argument("--batch", type=int, default=4, help="sequences per step and process (paper: 4)")
    p.add_argument("--frames", type=int, default=7, help="frames per sequence (paper: 7)")
    p.add_argument("--crop", type=int, default=0, help="random square crop of the frames (0: whole frames)")
    p.add_argument("--lr", type=float, default=1e-3, help="learning rate after the warm-up (paper: 0.001)")
    p.add_argument("--warmup", type=int, default=0, help="warm-up steps (default: 2%% of --steps, as 10 of 500 epochs)")
    p.add_argument("--exclude-scenes", default="cornell", help="scenes held out of training (comma-separated)")
    p.add_argument("--checkpoint-every", type=int, default=50, help="steps between checkpoints")
    p.add_argument("--time-limit", type=float, default=0, help="stop (with a checkpoint) after this many minutes")
    p.add_argument("--threads", type=int, default=0, help="CPU threads per process (0: PyTorch's choice)")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--rank-weights", action="store_true", help="every process writes rank<k>.safetensors at the end")
    return p.parse_args(argv)


def learning_rate(args, step, warmup):
    if step < warmup:
        return args.lr * 10.0 ** (step / warmup - 1.0)     # lr/10 -> lr, geometric
    return args.lr * math.sqrt(warmup / max(step, 1)) if warmup else args.lr


def format_seconds(s):
    s = int(s)
    return f"{s // 3600}h{s // 60 % 60:02d}m" if s >= 3600 else f"{s // 60}m{s % 60:02d}s"


class Run:
    """Distributed set-up: one process, or torchrun's WORLD_SIZE processes."""

    def __init__(self):
        self.world = int(os.environ.get("WORLD_SIZE", "1"))
        self.rank = int(os.environ.get("RANK", "0"))
        self.device = torch.device("cuda", int(os.environ.get("LOCAL_RANK", "0"))) if torch.cuda.is_available() \
            else torch.device("cpu")
        if self.world > 1:
            dist.init_process_group("nccl" if self.device.type == "cuda" else "gloo")

    @property
    def main(self):
        return self.rank == 0

    def close(self):
        if self.world > 1:
            dist.destroy_process_group()


def save_checkpoint(path, model, optimizer, step, history):
    temporary = f"{path}.tmp-{os.getpid()}"
    torch.save({"model": model.state_dict(), "optimizer": optimizer.state_dict(), "step": step,
                "history": history, "width": model.width, "levels": model.levels}, temporary)
    os.replace(temporary, path)


def plot(history, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    steps = [h["step"] for h in history]
    fig, ax = plt.subplots(figsize=(7, 4))
    for key in ("loss", "spatial", "gradient", "temporal"):
        values = [h[key] for h in history]
        window = max(1, len(values) // 50)
        smooth = [sum(values[max(0, i - window + 1):i + 1]) / len(values[max(0, i - window + 1):i + 1])
                  for i in range(len(values))]
        ax.plot(steps, smooth, label=key)
    ax.set_xlabel("step")
    ax.set_ylabel("L1 (colour^0.2)")
    ax.set_yscale("log")
    ax.set_title(title)
    ax.legend()
    fig.tight_layout()
    temporary = f"{path}.tmp-{os.getpid()}.png"
    fig.savefig(temporary, dpi=100)
    plt.close(fig)
    os.replace(temporary, path)


def write_outputs(args, model, optimizer, step, history, run):
    if not run.main:
        return
    save_checkpoint(os.path.join(args.out, "checkpoint.pt"), model, optimizer, step, history)
    recent = history[-20:]
    mean = sum(h["loss"] for h in recent) / max(len(recent), 1)
    weights_file.export(model, os.path.join(args.out, "weights.safetensors"), half=True, step=step,
                        loss=f"{mean:.5f}", sequences_seen=step * args.batch * run.world)
    with open(os.path.join(args.out, "losses.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["step", "loss", "spatial", "gradient", "temporal", "lr", "seconds"])
        w.writeheader()
        w.writerows(history)
    plot(history, os.path.join(args.out, "loss.png"), f"rdae width {model.width}, {model.levels} levels")


class StopRequest:
    """Ctrl-C or SIGTERM ends the run after the current step, with a checkpoint, so
    that no minutes of training are lost (a second Ctrl-C stops at once)."""

    def __init__(self):
        self.requested = False
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, self._on_signal)

    def _on_signal(self, sig, frame):
        if self.requested:
            raise KeyboardInterrupt
        self.requested = True
        print(f"train: {signal.Signals(sig).name}: stopping after this step, with a checkpoint "
              "(again to stop at once)", flush=True)


def train(args):
    run = Run()
    stop = StopRequest()
    if args.threads:
        torch.set_num_threads(args.threads)
    torch.manual_seed(args.seed)     # the same initial weights on every rank
    os.makedirs(args.out, exist_ok=True)
    held_out = [s for s in args.exclude_scenes.split(",") if s]
    files = sequence_files(args.data, held_out)
    sampler = SequenceSampler(files, frames=args.frames, crop=args.crop or None, seed=args.seed * 1000 + run.rank)
    model = RDAE(args.width, args.levels).to(run.device)
    optimizer = torch.optim.Adam(model.parameters(), lr=args.lr, betas=(0.9, 0.99))
    step, history = 0, []
    checkpoint = os.path.join(args.out, "checkpoint.pt")
    if os.path.exists(checkpoint):
        state = torch.load(checkpoint, map_location=run.device)
        if (state["width"], state["levels"]) != (args.width, args.levels):
            sys.exit(f"{checkpoint}: a width {state['width']}, {state['levels']}-level network; "
                     f"asked for {args.width}, {args.levels} (use another --out)")
        model.load_state_dict(state["model"])
        optimizer.load_state_dict(state["optimizer"])
        step, history = state["step"], state["history"]
        sampler.rng.seed(args.seed * 1000 + run.rank + step)
    net = DistributedDataParallel(Unrolled(model)) if run.world > 1 else Unrolled(model)
    loss_fn = Loss(args.frames)
    warmup = args.warmup or max(1, args.steps // 50)
    if run.main:
        print(f"train: {len(files)} sequences from {args.data} (held out: {args.exclude_scenes or 'none'}), "
              f"width {args.width}, {args.levels} levels, {parameter_count(model) / 1e6:.2f} M parameters, "
              f"{run.world} process(es) x batch {args.batch} on {run.device}, steps {step} -> {args.steps}",
              flush=True)
    start, first = time.time(), step
    while step < args.steps:
        for group in optimizer.param_groups:
            group["lr"] = learning_rate(args, step, warmup)
        x, y = sampler.batch(args.batch)
        predicted = net(x.to(run.device))
        loss, terms = loss_fn(predicted, y.to(run.device))
        optimizer.zero_grad(set_to_none=True)
        loss.backward()
        optimizer.step()
        step += 1
        history.append({"step": step, "loss": float(loss), **terms, "lr": optimizer.param_groups[0]["lr"],
                        "seconds": round(time.time() - start, 2)})
        elapsed = time.time() - start
        per_step = elapsed / (step - first)
        if run.main and (step % 10 == 0 or step == args.steps):
            recent = history[-10:]
            print(f"step {step}/{args.steps}  loss {sum(h['loss'] for h in recent) / len(recent):.4f}  "
                  f"(spatial {terms['spatial']:.4f}, gradient {terms['gradient']:.4f}, temporal {terms['temporal']:.4f})"
                  f"  lr {history[-1]['lr']:.2e}  {per_step:.2f} s/step  "
                  f"left {format_seconds(per_step * (args.steps - step))}", flush=True)
        out_of_time = (args.time_limit and elapsed > args.time_limit * 60) or stop.requested
        if step % args.checkpoint_every == 0 or step == args.steps or out_of_time:
            write_outputs(args, model, optimizer, step, history, run)
            added = sampler.update(sequence_files(args.data, held_out))
            if added and run.main:
                print(f"train: {added} new sequence(s) in {args.data}, {len(sampler.files)} in all", flush=True)
        if out_of_time:
            if run.main:
                why = "on request" if stop.requested else f"after --time-limit {args.time_limit} min"
                print(f"train: stopped at step {step} {why}", flush=True)
            break
    if args.rank_weights:
        weights_file.export(model, os.path.join(args.out, f"rank{run.rank}.safetensors"), half=False)
    run.close()


if __name__ == "__main__":
    train(parse_args())
