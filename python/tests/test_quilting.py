"""quilt and constrained_quilt over arrays."""
import numpy as np
import pytest

import tessera
from conftest import noise


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32])
def test_quilt_formats_and_determinism(dtype):
    ex = noise((40, 40, 3), dtype)
    a = tessera.quilt(ex, 50, 30, patch_size=12, seed=3, threads=1)
    b = tessera.quilt(ex, 50, 30, patch_size=12, seed=3, threads=2)
    assert a.shape == (30, 50, 3) and a.dtype == np.dtype(dtype)
    np.testing.assert_array_equal(a, b)
    assert tessera.quilt(np.ascontiguousarray(ex[:, :, 0]), 20, 20, patch_size=10).shape == (20, 20, 1)


def test_constrained_quilt_keeps_the_unmasked_pixels():
    img = tessera.exemplar("bricks", 64, 64)
    mask = np.zeros((64, 64), dtype=bool)
    mask[20:40, 24:44] = True
    out = tessera.constrained_quilt(img, mask, patch_size=12, seed=2)
    np.testing.assert_array_equal(out[~mask], img[~mask])
    ex = tessera.exemplar("bricks", 64, 64, seed=9)
    out2 = tessera.constrained_quilt(img, mask.astype(np.uint8) * 255, ex, patch_size=12)
    np.testing.assert_array_equal(out2[~mask], img[~mask])


def test_quilt_errors():
    ex = noise((40, 40, 3), np.uint8)
    with pytest.raises(tessera.InvalidArgument):
        tessera.quilt(ex, 50, 30, patch_size=100)
    with pytest.raises(tessera.InvalidArgument):
        tessera.quilt(ex, 50, 30, tolerance=float("nan"))
    with pytest.raises(ValueError):
        tessera.constrained_quilt(ex, np.zeros((10, 10), bool))
    with pytest.raises(TypeError, match="mask"):
        tessera.constrained_quilt(ex, np.zeros((40, 40), np.float32))
    with pytest.raises(TypeError, match="dtype and channels"):
        tessera.constrained_quilt(ex, np.zeros((40, 40), bool), noise((40, 40, 4), np.uint8))
