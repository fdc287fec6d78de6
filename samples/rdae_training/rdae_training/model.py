"""The recurrent denoising autoencoder (Chaitanya et al. 2017, Sec. 4.1-4.2, Figs. 2, 4).

Mirrors passes/include/hush/passes/rdae/architecture.hpp: the module names below are
the tensor names of the weights file and the pass names of the hush graph
("encoders.0.rcnn.mix" is pass "rdae.encoders.0.rcnn.mix").

    encoders.<k>  conv to f_k, RCNN block h = C(C(C(x) ++ h_prev)), 2x2 max pool
    bottleneck    conv f_{L-1} -> f_L at 1/2^L
    decoders.<k>  nearest 2x upsample, ++ encoder k's output, conv1, conv2 (k = L-1 .. 1)
    final         upsample, ++ encoder 0's output, conv to RGB, linear

f_k = round(width * (4/3)^k); leaky ReLU 0.1 everywhere but the final layer.
"""
import math

import torch
from torch import nn
import torch.nn.functional as F

INPUT_CHANNELS = 7    # colour^0.2 (3), view-space normal xy (2), depth, roughness
OUTPUT_CHANNELS = 3
LEAKY_SLOPE = 0.1


def features(width, level):
    """Rounded half up, as RdaeArchitecture::features."""
    return int(math.floor(width * (4.0 / 3.0) ** level + 0.5))


def conv3x3(inputs, outputs):
    conv = nn.Conv2d(inputs, outputs, 3, padding=1)
    # He et al. 2015 initialisation for leaky ReLU (Sec. 5.3).
    nn.init.kaiming_normal_(conv.weight, a=LEAKY_SLOPE, nonlinearity="leaky_relu")
    nn.init.zeros_(conv.bias)
    return conv


def act(x):
    return F.leaky_relu(x, LEAKY_SLOPE)


class RecurrentBlock(nn.Module):
    """h_i = O_i = C(C(C(I_i) ++ h_{i-1})) (Sec. 4.2)."""

    def __init__(self, channels):
        super().__init__()
        self.input = conv3x3(channels, channels)
        self.mix = conv3x3(2 * channels, channels)
        self.output = conv3x3(channels, channels)

    def forward(self, x, hidden):
        x = act(self.input(x))
        if hidden is None:            # first frame, or after a reset: h = 0
            hidden = torch.zeros_like(x)
        x = act(self.mix(torch.cat([x, hidden], dim=1)))
        return act(self.output(x))


class Encoder(nn.Module):
    def __init__(self, inputs, channels):
        super().__init__()
        self.conv = conv3x3(inputs, channels)
        self.rcnn = RecurrentBlock(channels)


class Decoder(nn.Module):
    def __init__(self, inputs, skip, channels):
        super().__init__()
        self.conv1 = conv3x3(inputs + skip, channels)
        self.conv2 = conv3x3(channels, channels)


class RDAE(nn.Module):
    def __init__(self, width=32, levels=6):
        super().__init__()
        self.width, self.levels = width, levels
        f = [features(width, k) for k in range(levels + 1)]
        self.features = f
        previous = INPUT_CHANNELS
        self.encoders = nn.ModuleList()
        for k in range(levels):
            self.encoders.append(Encoder(previous, f[k]))
            previous = f[k]
        self.bottleneck = conv3x3(f[levels - 1], f[levels])
        # Keyed by level, so that "decoders.3.conv1" is the decoder at 1/8.
        self.decoders = nn.ModuleDict()
        previous = f[levels]
        for k in range(levels - 1, 0, -1):
            self.decoders[str(k)] = Decoder(previous, f[k], f[k])
            previous = f[k]
        self.final = conv3x3(previous + f[0], OUTPUT_CHANNELS)

    @property
    def multiple(self):
        """Frame sizes must be multiples of this (hush pads to it)."""
        return 2 ** self.levels

    def forward(self, x, hidden=None):
        """One frame: x [N, 7, H, W] -> (y [N, 3, H, W], new hidden states)."""
        hidden = hidden or [None] * self.levels
        skips, state = [], []
        for k, encoder in enumerate(self.encoders):
            x = act(encoder.conv(x))
            x = encoder.rcnn(x, hidden[k])
            state.append(x)
            skips.append(x)
            x = F.max_pool2d(x, 2)
        x = act(self.bottleneck(x))
        for k in range(self.levels - 1, 0, -1):
            decoder = self.decoders[str(k)]
            x = F.interpolate(x, scale_factor=2, mode="nearest")
            x = act(decoder.conv1(torch.cat([x, skips[k]], dim=1)))
            x = act(decoder.conv2(x))
        x = F.interpolate(x, scale_factor=2, mode="nearest")
        return self.final(torch.cat([x, skips[0]], dim=1)), state

    def sequence(self, frames):
        """Unrolled over time (back-propagation through time, Sec. 5.3): frames
        [N, T, 7, H, W] -> [N, T, 3, H, W], the hidden state zero at frame 0."""
        hidden, outputs = None, []
        for t in range(frames.shape[1]):
            y, hidden = self(frames[:, t], hidden)
            outputs.append(y)
        return torch.stack(outputs, dim=1)


class Unrolled(nn.Module):
    """The network over a whole sequence as one forward call, which is what
    DistributedDataParallel synchronises around."""

    def __init__(self, model):
        super().__init__()
        self.model = model

    def forward(self, frames):
        return self.model.sequence(frames)


def parameter_count(model):
    return sum(p.numel() for p in model.parameters())


def multiply_adds_per_pixel(model):
    total = 0.0
    for name, module in model.named_modules():
        if isinstance(module, nn.Conv2d):
            level = level_of(name, model.levels)
            total += 9 * module.in_channels * module.out_channels / 4 ** level
    return total


def level_of(name, levels):
    parts = name.split(".")
    if parts[0] == "encoders" or parts[0] == "decoders":
        return int(parts[1])
    return levels if parts[0] == "bottleneck" else 0
