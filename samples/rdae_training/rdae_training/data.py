"""Training sequences written by `hush dataset` (samples/cli/command_dataset.cpp).

Each file <scene>_<index>.npy holds float16 [K + 1, T, 7, H, W]: the network's input
tensor for K independent 1-spp noise instances of every frame, and last the reference
through the same input node (its colour channels are the target). Channels: colour^0.2
(3), view-space normal xy (2), depth d/(1+d), roughness.

Augmentation as Sec. 4.3: a random 90/180/270-degree rotation, a per-channel colour
scale in [0, 2] (applied as scale^0.2, the colour being stored ^0.2), forward or
backward playback, and camera stops (a frame repeated with another noise instance).
"""
import glob
import os
import random

import numpy as np
import torch

COLOR_POWER = 0.2


def sequence_files(folder, exclude_scenes=()):
    files = sorted(glob.glob(os.path.join(folder, "*.npy")))
    return [f for f in files if scene_of(f) not in exclude_scenes]


def scene_of(path):
    return os.path.basename(path).rsplit("_", 1)[0]


def rotate_normals(x, k):
    """x [..., 7, H, W] rotated k quarter turns (torch.rot90 on H, W, anticlockwise as
    displayed): view-space normal (nx, ny) turns with the image, (nx, ny) -> (-ny, nx)
    per turn (image y points down, view y up)."""
    x = torch.rot90(x, k, dims=(-2, -1))
    for _ in range(k % 4):
        nx, ny = x[..., 3, :, :].clone(), x[..., 4, :, :].clone()
        x[..., 3, :, :], x[..., 4, :, :] = -ny, nx
    return x


class SequenceSampler:
    """Random training sequences, augmented, as (inputs [T, 7, H, W], target [T, 3, H, W])."""

    def __init__(self, files, frames=7, crop=None, seed=0, augment=True):
        if not files:
            raise ValueError("no training sequences (.npy files written by `hush dataset`)")
        self.frames, self.crop, self.augment = frames, crop, augment
        self.rng = random.Random(seed)
        self.files, self.arrays = [], []
        self.update(files)

    def update(self, files):
        """Adds the files not seen yet (training may start while `hush dataset` still
        writes sequences); returns how many were added."""
        new = [f for f in files if f not in set(self.files)]
        for f in new:
            a = np.load(f, mmap_mode="r")
            if a.ndim != 5 or a.shape[2] != 7 or a.shape[0] < 2:
                raise ValueError(f"{f}: shape {a.shape}, expected [K + 1, T, 7, H, W] with K >= 1")
            if a.shape[1] < self.frames:
                raise ValueError(f"{f}: {a.shape[1]} frames, training asks for {self.frames}")
            self.files.append(f)
            self.arrays.append(a)
        return len(new)

    def sample(self):
        a = self.arrays[self.rng.randrange(len(self.arrays))]
        noise, length = a.shape[0] - 1, a.shape[1]
        start = self.rng.randrange(length - self.frames + 1)
        order = list(range(start, start + self.frames))
        if self.augment and self.rng.random() < 0.5:
            order.reverse()                                  # backward playback
        inputs, targets, frame = [], [], order[0]
        for t in range(self.frames):
            stop = self.augment and t > 0 and self.rng.random() < 0.1
            if not stop:
                frame = order[t]
            instance = self.rng.randrange(noise)            # a stop keeps the frame, not the noise
            inputs.append(np.asarray(a[instance, frame], dtype=np.float32))
            targets.append(np.asarray(a[noise, frame, :3], dtype=np.float32))
        x, y = torch.from_numpy(np.stack(inputs)), torch.from_numpy(np.stack(targets))
        x, y = self._crop(x, y)
        if self.augment:
            k = self.rng.randrange(4)
            x, y = rotate_normals(x, k), torch.rot90(y, k, dims=(-2, -1))
            scale = torch.tensor([self.rng.uniform(0.0, 2.0) for _ in range(3)]) ** COLOR_POWER
            x[:, :3] *= scale.view(1, 3, 1, 1)
            y *= scale.view(1, 3, 1, 1)
        return x.contiguous(), y.contiguous()

    def batch(self, size):
        pairs = [self.sample() for _ in range(size)]
        return torch.stack([p[0] for p in pairs]), torch.stack([p[1] for p in pairs])

    def _crop(self, x, y):
        if not self.crop:
            return x, y
        h, w = x.shape[-2:]
        if self.crop > min(h, w):
            raise ValueError(f"crop {self.crop} is larger than the frames ({w}x{h})")
        top, left = self.rng.randrange(h - self.crop + 1), self.rng.randrange(w - self.crop + 1)
        s = (..., slice(top, top + self.crop), slice(left, left + self.crop))
        return x[s], y[s]
