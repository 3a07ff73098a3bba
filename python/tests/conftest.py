"""Shared fixtures of tessera's Python tests (run by ctest with PYTHONPATH=<build>/python)."""
import os
import shutil

import numpy as np
import pytest

import tessera


@pytest.fixture(scope="session")
def grass():
    """A small procedural RGB uint8 exemplar (what `tessera synth --exemplar grass` renders)."""
    return tessera.exemplar("grass", 64, 64, seed=1)


@pytest.fixture(scope="session")
def cli():
    """Path of the `tessera` command of the same build tree (TESSERA_CLI), or skip."""
    path = os.environ.get("TESSERA_CLI") or shutil.which("tessera")
    if not path or not os.path.exists(path):
        pytest.skip("the tessera command is not built (set TESSERA_CLI)")
    return path


@pytest.fixture(scope="session")
def model(grass):
    return tessera.PatchModel(grass, patch_width=16, patch_height=16, overlap=4)


def noise(shape, dtype, seed=0):
    rng = np.random.default_rng(seed)
    if np.dtype(dtype) == np.float32:
        return rng.random(shape, dtype=np.float32)
    return rng.integers(0, np.iinfo(dtype).max, size=shape, dtype=dtype)
