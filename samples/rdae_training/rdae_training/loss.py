"""The training loss of Sec. 4.4, on colours already raised to 0.2 (the input node and
the dataset store them so): per frame, 0.8 * spatial L1 + 0.1 * gradient-domain L1
(HFEN: Laplacian of Gaussian, sigma 1.5) + 0.1 * temporal L1 (of the frame-to-frame
differences), frames weighted (0.011, 0.044, 0.135, 0.325, 0.607, 0.882, 1).
"""
import math

import torch
import torch.nn.functional as F

WEIGHTS = (0.8, 0.1, 0.1)
FRAME_WEIGHTS_7 = (0.011, 0.044, 0.135, 0.325, 0.607, 0.882, 1.0)


def frame_weights(frames):
    """The paper's Gaussian ramp for 7 frames; the same curve sampled for other lengths."""
    if frames == 7:
        return torch.tensor(FRAME_WEIGHTS_7)
    t = torch.linspace(0.0, 1.0, frames)
    return torch.exp(-((1.0 - t) ** 2) * 4.5)   # exp(-(1-t)^2 / (2 (1/3)^2)): the 7-frame values


def log_kernel(sigma=1.5):
    radius = int(math.ceil(3 * sigma))
    r = torch.arange(-radius, radius + 1, dtype=torch.float32)
    y, x = torch.meshgrid(r, r, indexing="ij")
    q = (x * x + y * y) / (2 * sigma * sigma)
    k = (q - 1.0) * torch.exp(-q)
    return k - k.mean()                    # no response to a constant image


class Loss:
    def __init__(self, frames):
        self.frame_weights = frame_weights(frames)
        self.kernel = log_kernel().view(1, 1, *log_kernel().shape)

    def hfen(self, images):
        n, c, h, w = images.shape
        return F.conv2d(images.reshape(n * c, 1, h, w), self.kernel, padding=self.kernel.shape[-1] // 2)

    def __call__(self, predicted, target):
        """predicted, target [N, T, 3, H, W]; returns (total, {term: value})."""
        n, t = predicted.shape[:2]
        w = self.frame_weights.to(predicted.device)
        spatial = (predicted - target).abs().mean(dim=(0, 2, 3, 4))
        flat_p, flat_t = predicted.reshape(n * t, *predicted.shape[2:]), target.reshape(n * t, *target.shape[2:])
        gradient = (self.hfen(flat_p) - self.hfen(flat_t)).abs().reshape(n, t, -1).mean(dim=(0, 2))
        temporal = torch.zeros_like(spatial)
        temporal[1:] = ((predicted[:, 1:] - predicted[:, :-1]) - (target[:, 1:] - target[:, :-1])).abs().mean(
            dim=(0, 2, 3, 4))
        terms = {"spatial": (w * spatial).sum() / w.sum(), "gradient": (w * gradient).sum() / w.sum(),
                 "temporal": (w * temporal).sum() / w.sum()}
        total = WEIGHTS[0] * terms["spatial"] + WEIGHTS[1] * terms["gradient"] + WEIGHTS[2] * terms["temporal"]
        return total, {k: float(v) for k, v in terms.items()}
