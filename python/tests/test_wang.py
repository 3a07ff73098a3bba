"""Wang tile sets from Python: build, save/load, compose through colourings, atlas; bit-identity with
`tessera wang build` / `tessera wang tile`; bad input raises."""
import os
import subprocess

import numpy as np
import pytest

import tessera


@pytest.fixture(scope="module")
def tiles(grass):
    return tessera.build_wang_tiles(grass, tile_size=32, seed=3, threads=2)


def test_build_shapes_and_edges(tiles):
    assert tiles.tile_size == 32 and tiles.num_tiles == 16 and len(tiles) == 16
    assert tiles.horizontal_colors == 2 and tiles.vertical_colors == 2
    assert tiles.dtype == np.uint8 and tiles.channels == 3
    edges = tiles.edges
    assert edges.shape == (16, 4) and edges.dtype == np.int32
    assert len({tuple(e) for e in edges}) == 16  # the complete set: every edge combination once
    assert tiles.tile(0).shape == (32, 32, 3)
    assert tiles.shared_border >= 1 and tiles.exact_mip_levels >= 1


def test_same_seed_same_tiles_any_thread_count(grass, tiles):
    serial = tessera.build_wang_tiles(grass, tile_size=32, seed=3, threads=1)
    for i in range(tiles.num_tiles):
        assert np.array_equal(serial.tile(i), tiles.tile(i))


def test_hash_windows_agree_with_the_whole(tiles):
    whole = tiles.compose(160, 128, 0, 0, seed=7, threads=2)
    assert whole.shape == (128, 160, 3)
    part = tiles.compose(50, 40, 70, 33, seed=7, threads=1)
    assert np.array_equal(part, whole[33:73, 70:120])
    # the infinite plane: negative windows too, and they continue across the origin
    left = tiles.compose(64, 64, -32, -32, seed=7)
    assert np.array_equal(left[32:, 32:], whole[:32, :32])


def test_tiles_meet_without_seams(tiles):
    """Neighbouring cells share the colour of their common edge (checked through the explicit grid)."""
    edges = tiles.edges
    # a 2 x 2 grid: cell (0, 0) = tile 0; the others chosen so touching edges agree
    def find(north=None, west=None):
        for i, (n, e, s, w) in enumerate(edges):
            if (north is None or n == north) and (west is None or w == west):
                return i
        raise AssertionError
    t00 = 0
    t01 = find(west=edges[t00][1])
    t10 = find(north=edges[t00][2])
    t11 = find(north=edges[t01][2], west=edges[t10][1])
    grid = np.array([[edges[t00], edges[t01]], [edges[t10], edges[t11]]])
    img = tiles.compose(64, 64, coloring=grid)
    assert np.array_equal(img[:32, :32], tiles.tile(t00))
    assert np.array_equal(img[32:, 32:], tiles.tile(t11))


@pytest.mark.parametrize("kind", ["scanline", "periodic"])
def test_grid_colourings(tiles, kind):
    a = tiles.compose(96, 64, coloring=kind, seed=2)
    b = tiles.compose(96, 64, coloring=kind, seed=2, threads=1)
    assert a.shape == (64, 96, 3) and np.array_equal(a, b)
    with pytest.raises(ValueError, match="must not be negative"):
        tiles.compose(32, 32, -1, 0, coloring=kind)


def test_save_load_round_trip(tiles, tmp_path):
    tiles.save(str(tmp_path / "set"))
    back = tessera.WangTileSet.load(str(tmp_path / "set"))
    assert back.num_tiles == tiles.num_tiles and np.array_equal(back.edges, tiles.edges)
    for i in range(tiles.num_tiles):
        assert np.array_equal(back.tile(i), tiles.tile(i))
    as_float = tessera.WangTileSet.load(str(tmp_path / "set"), dtype="float32", channels=4)
    assert as_float.dtype == np.float32 and as_float.channels == 4


def test_atlas(tiles):
    a = tiles.atlas()
    assert a["layout"] == "edge_ordered" and a["tile_size"] == 32
    assert a["image"].shape == (4 * 32, 4 * 32, 3)  # 2 colours: 4 x 4 slots
    t = 5
    col, row = a["slot_col"][t], a["slot_row"][t]
    assert np.array_equal(a["image"][row * 32:(row + 1) * 32, col * 32:(col + 1) * 32], tiles.tile(t))
    padded = tiles.atlas("padded")
    assert padded["padding"] >= 1 and padded["slot_size"] == 32 + 2 * padded["padding"]


@pytest.mark.parametrize("dtype,channels", [(np.uint16, 1), (np.float32, 4)])
def test_other_formats(dtype, channels):
    from conftest import noise
    ex = noise((48, 48, channels), dtype, seed=4)
    s = tessera.build_wang_tiles(ex, tile_size=16, seed=1)
    assert s.dtype == dtype and s.channels == channels
    assert s.compose(40, 24).shape == (24, 40, channels)


def test_bad_input(grass, tiles, tmp_path):
    with pytest.raises(tessera.InvalidArgument):
        tessera.build_wang_tiles(grass, tile_size=2)
    with pytest.raises(tessera.InvalidArgument):
        tessera.build_wang_tiles(grass, horizontal_colors=0)
    with pytest.raises(ValueError, match="coloring must be"):
        tiles.compose(32, 32, coloring="nonsense")
    with pytest.raises(ValueError, match="outside"):
        tiles.compose(32, 32, coloring=np.full((1, 1, 4), 9))
    with pytest.raises(ValueError, match="rows x cols x 4"):
        tiles.compose(32, 32, coloring=np.zeros((2, 2), dtype=np.int32))
    with pytest.raises(TypeError):
        tiles.compose(32, 32, coloring=np.zeros((1, 1, 4), dtype=np.float32))
    with pytest.raises(IndexError):
        tiles.tile(99)
    with pytest.raises(tessera.Error):
        tiles.compose(1 << 40, 1 << 40)
    with pytest.raises(tessera.Error):
        tessera.WangTileSet.load(str(tmp_path / "missing"))
    with pytest.raises(ValueError, match="layout"):
        tiles.atlas("diagonal")


def test_equals_the_cli(cli, grass, tmp_path):
    """`tessera wang build` + `tessera wang tile` and the Python calls give the same tiles and pixels."""
    ex = tmp_path / "grass.png"
    tessera.write_png(str(ex), grass)
    subprocess.run([cli, "wang", "build", "--exemplar", str(ex), "--tile", "32", "--seed", "3", "--out",
                    str(tmp_path / "set")], check=True, capture_output=True)
    subprocess.run([cli, "wang", "tile", "--tiles", str(tmp_path / "set"), "--grid", "5x4", "--seed", "7", "--out",
                    str(tmp_path / "plane.png")], check=True, capture_output=True)
    built = tessera.build_wang_tiles(grass, tile_size=32, seed=3)
    loaded = tessera.WangTileSet.load(str(tmp_path / "set"))
    for i in range(built.num_tiles):
        assert np.array_equal(loaded.tile(i), built.tile(i))
    plane = tessera.read_png(str(tmp_path / "plane.png"))
    assert np.array_equal(plane, built.compose(160, 128, seed=7, variant_seed=7))
