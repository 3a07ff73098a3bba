"""examples/python/dask_render.py on a small size: the Zarr store equals rendering any window alone
and `tessera synth --window 0,0,N,N` of the CLI (same exemplar, options and seed)."""
import os
import subprocess
import sys

import numpy as np
import pytest

import tessera

zarr = pytest.importorskip("zarr")
pytest.importorskip("dask.distributed")

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python", "dask_render.py")


def run_script(*args):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in [env.get("PYTHONPATH"), os.path.dirname(SCRIPT)] if p)
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], check=True, capture_output=True, text=True,
                          env=env, timeout=600)


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    d = tmp_path_factory.mktemp("dask")
    ex = str(d / "ex.png")
    tessera.write_png(ex, tessera.exemplar("rock", 64, 64, seed=4))
    store = str(d / "t.zarr")
    out = run_script("--exemplar", ex, "--size", 200, "--chunk", 64, "--seed", 9, "--out", store,
                     "--workers", 2, "--patch", 24, "--overlap", 6)
    assert "megapixels/s" in out.stdout
    return ex, store


def test_store_layout_and_windows(rendered):
    ex, store = rendered
    z = zarr.open(store, mode="r")
    assert z.shape == (200, 200, 3) and z.chunks == (64, 64, 3) and z.dtype == np.uint8
    model = tessera.PatchModel(tessera.read_png(ex), patch_width=24, patch_height=24, overlap=6)
    whole = z[:]
    np.testing.assert_array_equal(whole, model.synthesize(200, 200, seed=9))
    for x, y, w, h in ((0, 0, 17, 13), (50, 61, 90, 70), (150, 190, 50, 10)):
        np.testing.assert_array_equal(z[y:y + h, x:x + w], model.synthesize(w, h, x=x, y=y, seed=9))


def test_equals_the_cli(rendered, cli, tmp_path):
    ex, store = rendered
    png = str(tmp_path / "cli.png")
    subprocess.run([cli, "synth", "--exemplar", ex, "--out", png, "--seed", "9", "--window", "0,0,200,200",
                    "--patch", "24", "--overlap", "6"], check=True, capture_output=True)
    np.testing.assert_array_equal(zarr.open(store, mode="r")[:], tessera.read_png(png))


def test_origin_and_threads_in_process(tmp_path, rendered):
    ex, _ = rendered
    store = str(tmp_path / "o.zarr")
    run_script("--exemplar", ex, "--size", 96, "--chunk", 40, "--seed", 9, "--out", store, "--workers", 1,
               "--no-processes", "--origin=-30,70", "--patch", "24", "--overlap", "6", "--compressor", "none",
               "--chunks-per-task", 2)  # rows of 3 chunks: tasks of 2 and of 1
    model = tessera.PatchModel(tessera.read_png(ex), patch_width=24, patch_height=24, overlap=6)
    np.testing.assert_array_equal(zarr.open(store, mode="r")[:], model.synthesize(96, 96, x=-30, y=70, seed=9))


def test_gray16_chunks_reuse_one_buffer(tmp_path):
    # one channel, 16 bits, chunks of a task of different sizes (edge chunks): each task renders into
    # one reused buffer, so a stale pixel from the previous chunk would show here
    ex = str(tmp_path / "g.png")
    rock = tessera.exemplar("rock", 48, 48, seed=2).astype(np.uint16) * 257
    tessera.write_png(ex, np.ascontiguousarray(rock[:, :, 1]))
    store = str(tmp_path / "g.zarr")
    run_script("--exemplar", ex, "--size", 70, "--chunk", 32, "--seed", 3, "--out", store, "--workers", 1,
               "--no-processes", "--patch", "16", "--overlap", "4", "--chunks-per-task", 3)
    z = zarr.open(store, mode="r")
    assert z.shape == (70, 70, 1) and z.dtype == np.uint16
    model = tessera.PatchModel(tessera.read_png(ex), patch_width=16, patch_height=16, overlap=4)
    np.testing.assert_array_equal(z[:], model.synthesize(70, 70, seed=3).reshape(70, 70, 1))
