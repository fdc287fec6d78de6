"""Unit tests of the training toolkit (CPU, seconds): the network's shape as the paper
and hush's C++ count it, the loss, augmentation, and the weights file round trip."""
import os
import sys
import tempfile
import unittest

import numpy as np
import torch

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from rdae_training import safetensors_io, weights                # noqa: E402
from rdae_training.data import SequenceSampler, rotate_normals   # noqa: E402
from rdae_training.loss import FRAME_WEIGHTS_7, Loss, frame_weights  # noqa: E402
from rdae_training.model import RDAE, multiply_adds_per_pixel, parameter_count  # noqa: E402


class Model(unittest.TestCase):
    def test_paper_network_has_36_convolutions_and_3_12_million_parameters(self):
        m = RDAE(32, 6)
        convs = [x for x in m.modules() if isinstance(x, torch.nn.Conv2d)]
        self.assertEqual(len(convs), 36)
        self.assertEqual(parameter_count(m), 3121364)      # RdaeArchitecture::parameterCount
        self.assertEqual(m.features, [32, 43, 57, 76, 101, 135, 180])
        self.assertEqual(parameter_count(RDAE(16, 6)), 777286)
        self.assertLess(multiply_adds_per_pixel(RDAE(16, 6)), multiply_adds_per_pixel(m) / 3.5)

    def test_recurrence_carries_state(self):
        torch.manual_seed(0)
        m = RDAE(4, 2)
        x = torch.rand(1, 3, 7, 16, 16)
        unrolled = m.sequence(x)
        alone, _ = m(x[:, 2])
        self.assertGreater((unrolled[:, 2] - alone).abs().max().item(), 1e-4)
        first, _ = m(x[:, 0])
        self.assertTrue(torch.equal(unrolled[:, 0], first))


class LossTerms(unittest.TestCase):
    def test_zero_for_a_perfect_prediction_and_the_papers_frame_weights(self):
        y = torch.rand(2, 7, 3, 16, 16)
        total, _ = Loss(7)(y, y)
        self.assertEqual(total.item(), 0.0)
        self.assertTrue(np.allclose(frame_weights(7).numpy(), FRAME_WEIGHTS_7))
        self.assertTrue(np.allclose(frame_weights(4).numpy()[[0, -1]], [0.011, 1.0], atol=1e-3))

    def test_temporal_term_sees_flicker_the_spatial_term_forgives(self):
        target = torch.full((1, 7, 3, 16, 16), 0.5)
        flicker = target + 0.1 * torch.tensor([1, -1, 1, -1, 1, -1, 1.0]).view(1, 7, 1, 1, 1)
        steady = target + 0.1
        _, a = Loss(7)(flicker, target)
        _, b = Loss(7)(steady, target)
        self.assertAlmostEqual(a["spatial"], b["spatial"], places=5)
        self.assertGreater(a["temporal"], 0.1)
        self.assertAlmostEqual(b["temporal"], 0.0, places=6)


class Augmentation(unittest.TestCase):
    def test_rotating_the_image_turns_view_space_normals_with_it(self):
        # A normal pointing right (view +x) at the right edge: after a quarter turn
        # anticlockwise, that edge is the top, and the normal points up (view +y).
        x = torch.zeros(1, 7, 4, 4)
        x[0, 3, :, 3] = 1.0
        r = rotate_normals(x, 1)
        self.assertTrue(torch.allclose(r[0, 4, 0, :], torch.ones(4)))     # top row, ny = 1
        self.assertTrue(torch.allclose(r[0, 3], torch.zeros(4, 4)))
        self.assertTrue(torch.equal(rotate_normals(r, 3), x))

    def test_sampler_reads_hush_dataset_files(self):
        with tempfile.TemporaryDirectory() as d:
            a = np.random.rand(3, 5, 7, 8, 8).astype(np.float16)
            np.save(os.path.join(d, "room_00000.npy"), a)
            s = SequenceSampler([os.path.join(d, "room_00000.npy")], frames=4, seed=1)
            x, y = s.batch(2)
            self.assertEqual(tuple(x.shape), (2, 4, 7, 8, 8))
            self.assertEqual(tuple(y.shape), (2, 4, 3, 8, 8))
            with self.assertRaises(ValueError):
                SequenceSampler([os.path.join(d, "room_00000.npy")], frames=6)


class WeightsFile(unittest.TestCase):
    def test_round_trip_through_safetensors(self):
        torch.manual_seed(3)
        m = RDAE(4, 2)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "w.safetensors")
            weights.export(m, path, half=False)
            back, meta = weights.load(path)
            self.assertEqual(meta["features"], "4,5,7")
            for k, v in m.state_dict().items():
                self.assertTrue(torch.equal(v, back.state_dict()[k]), k)
            tensors, _ = safetensors_io.read(path)
            self.assertEqual(tensors["final.weight"].shape, (3, 9, 3, 3))   # 5 upsampled + 4 skip


if __name__ == "__main__":
    unittest.main()
