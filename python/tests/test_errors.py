"""Bad input is a clear Python exception, never a crash."""
import numpy as np
import pytest

import tessera
from conftest import noise


def test_exception_hierarchy():
    assert issubclass(tessera.Error, RuntimeError)
    pairs = {tessera.InvalidArgument: ValueError, tessera.OutOfRange: IndexError,
             tessera.SizeOverflow: OverflowError, tessera.IOError: OSError, tessera.ParseError: ValueError,
             tessera.Unsupported: NotImplementedError}
    for cls, base in pairs.items():
        assert issubclass(cls, tessera.Error) and issubclass(cls, base)
    for cls in (tessera.Cancelled, tessera.NotConverged, tessera.InternalError):
        assert issubclass(cls, tessera.Error)
    assert tessera.InvalidArgument.code == "invalid_argument"
    assert tessera.ParseError.code == "parse_error"


def test_wrong_dtype():
    with pytest.raises(TypeError, match="uint8, uint16 or float32.*float64"):
        tessera.PatchModel(np.zeros((32, 32, 3)))
    with pytest.raises(TypeError, match="int32"):
        tessera.write_png("/tmp/never.png", np.zeros((4, 4), dtype=np.int32))
    with pytest.raises(TypeError, match="byte order|>u2"):
        tessera.PatchModel(noise((32, 32), np.uint16).astype(">u2"))


def test_wrong_shapes():
    for shape in [(32,), (32, 32, 5), (32, 32, 0), (2, 32, 32, 3)]:
        with pytest.raises(ValueError, match="H x W or H x W x C"):
            tessera.PatchModel(np.zeros(shape, dtype=np.uint8))
    with pytest.raises(ValueError, match="empty"):
        tessera.PatchModel(np.zeros((0, 32, 3), dtype=np.uint8))


def test_non_contiguous_and_negative_strides():
    ex = noise((64, 64, 4), np.uint8)
    with pytest.raises(ValueError, match="ascontiguousarray"):
        tessera.PatchModel(ex[::-1])
    with pytest.raises(ValueError, match="ascontiguousarray"):
        tessera.PatchModel(ex[:, ::2])
    with pytest.raises(ValueError, match="ascontiguousarray"):
        tessera.PatchModel(ex[:, :, :3])
    with pytest.raises(ValueError, match="ascontiguousarray"):
        tessera.PatchModel(np.asfortranarray(ex))
    # padded rows are fine (row stride larger than a row), and read without a copy
    m = tessera.PatchModel(ex[:, :48], patch_width=8, patch_height=8, overlap=2)
    assert m.synthesize(10, 10).shape == (10, 10, 4)


def test_nan_and_infinity():
    ex = noise((32, 32, 3), np.float32)
    ex[5, 7, 1] = np.nan
    with pytest.raises(tessera.InvalidArgument, match="finite"):
        tessera.PatchModel(ex)
    ex[5, 7, 1] = np.inf
    with pytest.raises(ValueError, match="finite"):
        tessera.write_png("/tmp/never.png", ex)


def test_bad_options_and_sizes(model):
    ex = noise((32, 32, 3), np.uint8)
    with pytest.raises(tessera.InvalidArgument, match="candidates must be in \\[1, 64\\], got 0"):
        tessera.PatchModel(ex, candidates=0)
    with pytest.raises(tessera.InvalidArgument, match="do not fit"):
        tessera.PatchModel(ex, patch_width=40, patch_height=40, overlap=4)
    with pytest.raises(TypeError):
        tessera.PatchModel(ex, no_such_option=3)
    with pytest.raises(tessera.InvalidArgument):
        model.synthesize(0, 10)
    with pytest.raises(tessera.InvalidArgument):
        model.synthesize(-5, 10)
    with pytest.raises(tessera.SizeOverflow):
        model.synthesize(10**9, 10**9)
    with pytest.raises(tessera.OutOfRange, match="texture plane"):
        model.synthesize(10, 10, x=2**60)
    with pytest.raises(TypeError, match="incompatible function arguments"):
        model.synthesize(10, 10, x=2**70)  # beyond int64: pybind11's conversion refuses it
    with pytest.raises(tessera.InvalidArgument, match="threads"):
        model.synthesize(10, 10, threads=-1)
    with pytest.raises(ValueError, match="seams"):
        model.synthesize(10, 10, seams="zigzag")


def test_png_errors(tmp_path):
    with pytest.raises(tessera.IOError):
        tessera.read_png(str(tmp_path / "missing.png"))
    bad = tmp_path / "bad.png"
    bad.write_bytes(b"\x89PNG\r\n\x1a\nnot really")
    with pytest.raises(tessera.ParseError):
        tessera.read_png(str(bad))
    with pytest.raises(OSError):
        tessera.write_png(str(tmp_path / "no" / "such" / "dir.png"), np.zeros((4, 4), np.uint8))
