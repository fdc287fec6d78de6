"""The safetensors layout, written and read by hand (Debian 12 has no python3-safetensors):
8 bytes little-endian header length N, N bytes of JSON {name: {dtype, shape,
data_offsets}, "__metadata__": {str: str}}, then the data. hush reads it in
passes/src/rdae/weights.cpp.
"""
import json
import os
import struct

import numpy as np

DTYPES = {"F16": np.float16, "F32": np.float32}
NAMES = {np.dtype(np.float16): "F16", np.dtype(np.float32): "F32"}


def write(path, tensors, metadata=None):
    """tensors: {name: numpy array (float16 or float32)}; written atomically."""
    header, blobs, offset = {}, [], 0
    for name in sorted(tensors):
        a = np.ascontiguousarray(tensors[name])
        if a.dtype not in NAMES:
            raise ValueError(f"tensor '{name}': dtype {a.dtype}, expected float16 or float32")
        data = a.astype(a.dtype.newbyteorder("<"), copy=False).tobytes()
        header[name] = {"dtype": NAMES[a.dtype], "shape": list(a.shape), "data_offsets": [offset, offset + len(data)]}
        blobs.append(data)
        offset += len(data)
    if metadata:
        header["__metadata__"] = {str(k): str(v) for k, v in metadata.items()}
    text = json.dumps(header, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 8)      # keeps the data 8-byte aligned
    temporary = f"{path}.tmp-{os.getpid()}"
    with open(temporary, "wb") as f:
        f.write(struct.pack("<Q", len(text)))
        f.write(text)
        for blob in blobs:
            f.write(blob)
    os.replace(temporary, path)


def read(path):
    """Returns ({name: numpy array}, metadata)."""
    with open(path, "rb") as f:
        raw = f.read()
    (n,) = struct.unpack("<Q", raw[:8])
    header = json.loads(raw[8:8 + n])
    metadata = header.pop("__metadata__", {})
    data = raw[8 + n:]
    tensors = {}
    for name, e in header.items():
        begin, end = e["data_offsets"]
        tensors[name] = np.frombuffer(data[begin:end], dtype=np.dtype(DTYPES[e["dtype"]]).newbyteorder("<")).reshape(
            e["shape"])
    return tensors, metadata
