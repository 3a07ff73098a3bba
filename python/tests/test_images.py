"""PNG files and exemplars: dtypes, shapes, zero-copy outputs."""
import numpy as np
import pytest

import tessera
from conftest import noise


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("channels", [1, 2, 3, 4])
def test_png_round_trip(tmp_path, dtype, channels):
    img = noise((13, 17, channels), dtype)
    path = str(tmp_path / "x.png")
    tessera.write_png(path, img)
    back = tessera.read_png(path)
    assert back.dtype == np.dtype(dtype) and back.shape == img.shape
    np.testing.assert_array_equal(back, img)


def test_two_dimensional_and_float(tmp_path):
    path = str(tmp_path / "g.png")
    grey = noise((9, 11), np.uint8)
    tessera.write_png(path, grey)
    np.testing.assert_array_equal(tessera.read_png(path)[:, :, 0], grey)
    f = np.linspace(0, 1, 30, dtype=np.float32).reshape(5, 6)
    tessera.write_png(path, f)
    back = tessera.read_png(path)
    assert back.dtype == np.uint16
    np.testing.assert_array_equal(back[:, :, 0], np.round(f * 65535).astype(np.uint16))


def test_padded_rows_are_read_in_place(tmp_path):
    big = noise((10, 20, 3), np.uint8)
    path = str(tmp_path / "p.png")
    tessera.write_png(path, big[:, 5:12])
    np.testing.assert_array_equal(tessera.read_png(path), big[:, 5:12])


def test_outputs_own_their_memory_without_copies(model):
    out = model.synthesize(32, 16, seed=1)  # synthesized in place into the returned array
    assert out.flags.c_contiguous and out.flags.writeable and out.flags.owndata
    ex = model.exemplar  # a C++ buffer moved into the array (no second copy)
    assert ex.flags.c_contiguous and ex.base is not None


def test_exemplar_kinds():
    for kind in ("grass", "sand", "rock", "bricks", "cells", "weave", "dots"):
        e = tessera.exemplar(kind, 32, 24, seed=2)
        assert e.shape == (24, 32, 3) and e.dtype == np.uint8
    with pytest.raises(tessera.InvalidArgument):
        tessera.exemplar("lava")
