"""tessera geometry bindings: mesh exemplars, mesh arrays' validation, geometric Wang tiles."""
import numpy as np
import pytest

import tessera


@pytest.mark.parametrize("kind", ["rings", "chain_mail", "stones", "weave"])
def test_exemplars(kind):
    v, f = tessera.mesh_exemplar(kind, seed=2)
    assert v.dtype == np.float64 and v.ndim == 2 and v.shape[1] == 3 and len(v) > 0
    assert f.dtype == np.int64 and f.shape[1] == 3 and f.min() >= 0 and f.max() < len(v)
    v2, f2 = tessera.mesh_exemplar(kind, seed=2)
    np.testing.assert_array_equal(v, v2)
    np.testing.assert_array_equal(f, f2)
    with pytest.raises(ValueError, match="kind"):
        tessera.mesh_exemplar("cubes")


def test_bad_meshes_raise_clearly():
    v, f = tessera.mesh_exemplar("rings", size=4)
    with pytest.raises(TypeError, match="float64"):
        tessera.mesh_quilt(v.astype(np.float32), f, 4, 4)
    with pytest.raises(TypeError, match="int32 or int64"):
        tessera.mesh_quilt(v, f.astype(np.float64), 4, 4)
    with pytest.raises(ValueError, match="n x 3"):
        tessera.mesh_quilt(v[:, :2], f, 4, 4)
    with pytest.raises(ValueError, match="m x 3"):
        tessera.mesh_quilt(v, f.reshape(-1), 4, 4)
    bad = v.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match="row 3 is not finite"):
        tessera.mesh_quilt(bad, f, 4, 4)
    oob = f.copy()
    oob[5, 2] = len(v)
    with pytest.raises(ValueError, match="row 5 refers to vertex"):
        tessera.mesh_quilt(v, oob, 4, 4)
    neg = f.astype(np.int32)
    neg[0, 0] = -1
    with pytest.raises(ValueError, match="row 0"):
        tessera.mesh_quilt(v, neg, 4, 4)
    with pytest.raises(ValueError):
        tessera.mesh_quilt(v, f, -1, 4)


@pytest.fixture(scope="module")
def tiles():
    v, f = tessera.mesh_exemplar("rings")
    return tessera.GeometricTileSet.build(v, f, tile_size=6.4, seed=3)


def test_tile_set_and_plane(tiles, tmp_path):
    assert tiles.num_tiles == 16 and tiles.edges.shape == (16, 4) and tiles.edges.dtype == np.int32
    v, f = tiles.tile(0)
    assert v.shape[1] == 3 and f.shape[1] == 3
    assert v[:, :2].min() >= 0 and v[:, :2].max() <= tiles.tile_size
    with pytest.raises(IndexError):
        tiles.tile(16)
    pv, pf = tiles.tile_plane(3, 2, seed=5)
    assert pv[:, 0].max() <= 3 * tiles.tile_size + 1e-9 and pv[:, 1].max() <= 2 * tiles.tile_size + 1e-9
    pv2, pf2 = tiles.tile_plane(3, 2, seed=5, threads=1)
    np.testing.assert_array_equal(pv, pv2)
    np.testing.assert_array_equal(pf, pf2)
    with pytest.raises((ValueError, OverflowError)):
        tiles.tile_plane(1 << 20, 1 << 20)
    with pytest.raises(ValueError):
        tiles.tile_plane(0, 2)
    tiles.save(str(tmp_path / "set"))
    back = tessera.GeometricTileSet.load(str(tmp_path / "set"))
    assert back.num_tiles == tiles.num_tiles
    np.testing.assert_array_equal(back.edges, tiles.edges)
    with pytest.raises(OSError):
        tessera.GeometricTileSet.load(str(tmp_path / "missing"))
