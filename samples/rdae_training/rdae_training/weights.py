"""A model's weights file (what hush loads) and the golden input/output pair its C++
test compares against (tests/passes/test_rdae_network.cpp)."""
import torch

from . import safetensors_io
from .model import RDAE

FORMAT = "hush-rdae-1"


def metadata(model, **extra):
    m = {"format": FORMAT, "width": model.width, "levels": model.levels,
         "features": ",".join(str(f) for f in model.features)}
    m.update(extra)
    return m


def export(model, path, half=True, **extra):
    dtype = torch.float16 if half else torch.float32
    tensors = {k: v.detach().to(dtype).cpu().numpy() for k, v in model.state_dict().items()}
    safetensors_io.write(path, tensors, metadata(model, **extra))


def load(path):
    tensors, meta = safetensors_io.read(path)
    model = RDAE(int(meta["width"]), int(meta["levels"]))
    model.load_state_dict({k: torch.from_numpy(v.astype("float32")) for k, v in tensors.items()})
    return model, meta


def golden(model, inputs, path):
    """inputs [T, 7, H, W] (H, W multiples of model.multiple): writes the inputs and the
    unrolled outputs [T, 3, H, W] in float32, with the weights' own (fp16-rounded)
    values, so that C++ and PyTorch run the very same numbers."""
    with torch.no_grad():
        outputs = model.sequence(inputs.unsqueeze(0)).squeeze(0)
    safetensors_io.write(path, {"input": inputs.float().numpy(), "output": outputs.float().numpy()},
                         metadata(model, frames=inputs.shape[0]))
