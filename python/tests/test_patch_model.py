"""tessera.PatchModel: formats, windows, options, bit-identity with `tessera synth`, serialization."""
import os
import pickle
import subprocess

import numpy as np
import pytest

import tessera
from conftest import noise


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32])
@pytest.mark.parametrize("channels", [None, 1, 2, 3, 4])
def test_every_format_round_trips(dtype, channels):
    shape = (40, 40) if channels is None else (40, 40, channels)
    ex = noise(shape, dtype)
    m = tessera.PatchModel(ex, patch_width=8, patch_height=8, overlap=3, threads=1)
    out = m.synthesize(33, 21, seed=3)
    assert out.dtype == np.dtype(dtype)
    assert out.shape == (21, 33, channels or 1)
    assert m.channels == (channels or 1)
    assert m.dtype == np.dtype(dtype)
    # synthesized pixels are exemplar pixels (or blends of them in the overlaps): the range holds
    assert out.min() >= ex.min() and out.max() <= ex.max()


def test_windows_tile_the_texture(model):
    whole = model.synthesize(80, 60, x=-20, y=7, seed=11)
    part = model.synthesize(30, 25, x=-20 + 17, y=7 + 9, seed=11)
    np.testing.assert_array_equal(whole[9:34, 17:47], part)
    assert not np.array_equal(model.synthesize(30, 25, seed=12), model.synthesize(30, 25, seed=11))


def test_threads_do_not_change_the_output(model):
    a = model.synthesize(100, 70, seed=5, threads=1)
    b = model.synthesize(100, 70, seed=5, threads=2)
    np.testing.assert_array_equal(a, b)


def test_options_and_properties(grass):
    m = tessera.PatchModel(grass, patch_width=16, patch_height=12, overlap=5, candidates=4, seams=True)
    assert (m.patch_width, m.patch_height, m.overlap, m.candidates, m.seams) == (16, 12, 5, 4, True)
    assert (m.exact_sets, m.pca_dims, m.pca_samples, m.search_pool, m.refine_iterations) == (False, 8, 384, 16, 4)
    assert m.num_patches > 0 and m.memory_bytes > 0
    np.testing.assert_array_equal(m.exemplar, grass)
    assert "PatchModel(64 x 64 x 3 uint8" in repr(m)
    auto = tessera.PatchModel(grass)
    assert auto.patch_width >= 2 and auto.overlap >= 1


def test_save_load_and_pickle(grass):
    m = tessera.PatchModel(grass, patch_width=16, patch_height=16, overlap=4, seams=True)
    data = m.save()
    assert isinstance(data, bytes) and data[:8] == b"TSPMODEL"
    for back in (tessera.PatchModel.load(data), pickle.loads(pickle.dumps(m))):
        assert (back.patch_width, back.overlap, back.seams) == (16, 4, True)
        np.testing.assert_array_equal(back.synthesize(50, 40, x=3, seed=9), m.synthesize(50, 40, x=3, seed=9))
    f = noise((30, 30, 2), np.float32)
    mf = tessera.PatchModel(f, patch_width=6, patch_height=6, overlap=2)
    np.testing.assert_array_equal(tessera.PatchModel.load(mf.save()).synthesize(20, 20), mf.synthesize(20, 20))


def test_bad_model_bytes_are_clear_errors(model):
    data = model.save()
    with pytest.raises(tessera.ParseError, match="not a tessera patch model"):
        tessera.PatchModel.load(b"hello world, this is not a model")
    with pytest.raises(ValueError, match="too short"):
        tessera.PatchModel.load(b"")
    with pytest.raises(tessera.ParseError, match="checksum|truncated"):
        tessera.PatchModel.load(data[:-100])
    corrupted = bytearray(data)
    corrupted[200] ^= 0xFF
    with pytest.raises(tessera.ParseError, match="checksum"):
        tessera.PatchModel.load(bytes(corrupted))
    other = bytearray(data)
    other[8] = 2  # format version 2
    with pytest.raises(tessera.Unsupported, match="version 2.*reads version 1"):
        tessera.PatchModel.load(bytes(other))
    with pytest.raises(NotImplementedError):
        tessera.PatchModel.load(bytes(other))
    with pytest.raises(TypeError):
        tessera.PatchModel.load("a string")


def test_bit_identical_to_the_cli(tmp_path, cli):
    ex = tessera.exemplar("rock", 96, 96, seed=4)
    path = str(tmp_path / "ex.png")
    tessera.write_png(path, ex)
    for seams, window in (("feather", (0, 0, 120, 90)), ("cut", (-37, 1000, 64, 50))):
        out = str(tmp_path / f"out_{seams}.png")
        subprocess.run([cli, "synth", "--exemplar", path, "--out", out, "--seed", "42", "--seams", seams,
                        "--window", ",".join(map(str, window)), "--threads", "2"],
                       check=True, capture_output=True)
        m = tessera.PatchModel(tessera.read_png(path), seams=(seams == "cut"))
        x, y, w, h = window
        mine = m.synthesize(w, h, x=x, y=y, seed=42)
        np.testing.assert_array_equal(mine, tessera.read_png(out))


def rock_model_and_cli(tmp_path, cli, *options):
    """The model of a 96 x 96 rock exemplar and `tessera synth` of it (seed 9, 150 x 110) with options."""
    path = str(tmp_path / "ex.png")
    tessera.write_png(path, tessera.exemplar("rock", 96, 96, seed=4))
    out = str(tmp_path / "o.png")
    subprocess.run([cli, "synth", "--exemplar", path, "--out", out, "--seed", "9", "--size", "150x110", *options],
                   check=True, capture_output=True)
    return tessera.PatchModel(tessera.read_png(path)), tessera.read_png(out)


def test_overlap_fallback_matches_the_cli(tmp_path, cli):
    """fallback="overlap" (quality mode) equals `tessera synth --fallback overlap`, and differs from the
    paper's fallback (the photographs' case: vacant cells whose four sets share no patch)."""
    m, cli_out = rock_model_and_cli(tmp_path, cli, "--fallback", "overlap")
    mine = m.synthesize(150, 110, seed=9, fallback="overlap")
    np.testing.assert_array_equal(mine, cli_out)
    assert not np.array_equal(mine, m.synthesize(150, 110, seed=9))
    np.testing.assert_array_equal(mine, m.synthesize(150, 110, seed=9, fallback="overlap", threads=1))
    with pytest.raises(ValueError, match="fallback must be"):
        m.synthesize(8, 8, fallback="best")
    with pytest.raises(ValueError, match="fallback_budget"):
        m.synthesize(8, 8, fallback="overlap", fallback_budget=0)


def test_fallback_rules_and_patch_fraction_match_the_cli(tmp_path, cli):
    """fallback="sets" (the paper's rule) is the default of both (equal to the CLI's default output), "estimate"
    equals `--fallback estimate`; min_patch_fraction=0.25 (the paper's size range) equals `--min-patch-fraction 0.25`."""
    m, cli_default = rock_model_and_cli(tmp_path, cli)
    mine = m.synthesize(150, 110, seed=9)
    np.testing.assert_array_equal(mine, cli_default)
    np.testing.assert_array_equal(mine, m.synthesize(150, 110, seed=9, fallback="sets", threads=1))
    _, cli_estimate = rock_model_and_cli(tmp_path, cli, "--fallback", "estimate")
    np.testing.assert_array_equal(m.synthesize(150, 110, seed=9, fallback="estimate"), cli_estimate)
    _, cli_paper = rock_model_and_cli(tmp_path, cli, "--min-patch-fraction", "0.25")
    paper = tessera.PatchModel(tessera.read_png(str(tmp_path / "ex.png")), min_patch_fraction=0.25)
    np.testing.assert_array_equal(paper.synthesize(150, 110, seed=9), cli_paper)
    assert paper.patch_width <= m.patch_width
    for bad in (0.0, 0.6, float("nan")):
        with pytest.raises(ValueError, match="min_patch_fraction"):
            tessera.PatchModel(tessera.exemplar("rock", 32, 32), min_patch_fraction=bad)


def test_feather_width_matches_the_cli(tmp_path, cli):
    """feather_width equals `tessera synth --feather W`; 5 is the default; a band narrower than the
    overlap (the model's, resolved from the exemplar) gives another texture than 0 (the paper's
    whole-overlap blend), a band as wide as it the same; a negative width is refused."""
    m, cli_out = rock_model_and_cli(tmp_path, cli, "--feather", "0")
    paper = m.synthesize(150, 110, seed=9, feather_width=0)
    np.testing.assert_array_equal(paper, cli_out)
    np.testing.assert_array_equal(m.synthesize(150, 110, seed=9), m.synthesize(150, 110, seed=9, feather_width=5))
    assert m.overlap > 2
    np.testing.assert_array_equal(paper, m.synthesize(150, 110, seed=9, feather_width=m.overlap))
    assert not np.array_equal(paper, m.synthesize(150, 110, seed=9, feather_width=2))
    with pytest.raises(ValueError, match="feather_width"):
        m.synthesize(8, 8, feather_width=-1)


def test_cli_bit_identity_16_bit_grey(tmp_path, cli):
    ex = (noise((48, 48, 1), np.uint16, seed=3) // 3 + 1000).astype(np.uint16)
    path = str(tmp_path / "ex16.png")
    tessera.write_png(path, ex)
    out = str(tmp_path / "o.png")
    subprocess.run([cli, "synth", "--exemplar", path, "--out", out, "--seed", "7", "--size", "70x50",
                    "--patch", "12", "--overlap", "4"], check=True, capture_output=True)
    m = tessera.PatchModel(tessera.read_png(path), patch_width=12, patch_height=12, overlap=4)
    np.testing.assert_array_equal(m.synthesize(70, 50, seed=7), tessera.read_png(out))


def test_synthesize_into_out(model):
    """out=: rendered in place into the caller's array (returned as is), equal to a new array's pixels."""
    fresh = model.synthesize(48, 40, 5, 9, seed=3)
    buf = np.zeros((40, 48, 3), dtype=np.uint8)
    got = model.synthesize(48, 40, 5, 9, seed=3, out=buf)
    assert got is buf and np.array_equal(buf, fresh)
    # row padding is fine: a view of a wider array
    wide = np.zeros((40, 64, 3), dtype=np.uint8)
    model.synthesize(48, 40, 5, 9, seed=3, out=wide[:, :48])
    assert np.array_equal(wide[:, :48], fresh) and not wide[:, 48:].any()


def test_synthesize_stats(model):
    """stats=: filled with the figures of `tessera synth --stats` and the C++ call's time."""
    st = {}
    img = model.synthesize(96, 80, 3, 4, seed=2, stats=st)
    assert np.array_equal(img, model.synthesize(96, 80, 3, 4, seed=2))  # stats change nothing
    assert st["cells"] > 0 and st["placed"] + st["filled"] <= st["cells"]
    assert 0 <= st["empty_intersections"] <= st["filled"]
    assert st["synthesis_ms"] > 0 and st["fill_overlap_rms"] >= 0
    with pytest.raises(TypeError, match="dict"):
        model.synthesize(8, 8, stats=[])


def test_synthesize_out_refused(model):
    with pytest.raises(TypeError, match="dtype"):
        model.synthesize(8, 8, out=np.zeros((8, 8, 3), dtype=np.float32))
    with pytest.raises(ValueError, match="shape"):
        model.synthesize(8, 8, out=np.zeros((8, 9, 3), dtype=np.uint8))
    ro = np.zeros((8, 8, 3), dtype=np.uint8)
    ro.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        model.synthesize(8, 8, out=ro)
    with pytest.raises(ValueError, match="layout"):
        model.synthesize(8, 8, out=np.zeros((8, 16, 3), dtype=np.uint8)[:, ::2])
    with pytest.raises(TypeError):
        model.synthesize(8, 8, out=[1, 2, 3])
