"""tessera surface bindings: PolycubeMap build, arrays, save/load."""
import numpy as np
import pytest

import tessera
from meshes import uv_sphere


@pytest.fixture(scope="module")
def sphere_map():
    v, f = uv_sphere()
    return tessera.PolycubeMap.build(v, f, tiles_across=4)


def test_polycube_of_a_sphere(sphere_map):
    m = sphere_map
    v, f = uv_sphere()
    np.testing.assert_array_equal(m.vertices, v)
    np.testing.assert_array_equal(m.faces, f)
    assert m.polycube_positions.shape == v.shape
    assert m.labels.dtype == np.uint8 and m.labels.shape == (len(f),) and set(m.labels) == set(range(6))
    assert m.face_chart.shape == (len(f),)
    assert len(m.charts) >= 6 and m.num_corners >= 8 and m.num_edges >= 12
    assert m.quad_corners.shape == (m.num_quads, 4, 3)
    assert m.quad_neighbors.shape == (m.num_quads, 4) and m.quad_neighbors.min() >= 0
    assert m.quad_chart.max() < len(m.charts)
    # deterministic for any thread count
    again = tessera.PolycubeMap.build(v, f, tiles_across=4, threads=1)
    np.testing.assert_array_equal(again.polycube_positions, m.polycube_positions)


def test_save_load_round_trip(sphere_map, tmp_path):
    path = str(tmp_path / "sphere.polycube")
    sphere_map.save(path)
    back = tessera.PolycubeMap.load(path)
    np.testing.assert_array_equal(back.polycube_positions, sphere_map.polycube_positions)
    np.testing.assert_array_equal(back.quad_corners, sphere_map.quad_corners)
    assert back.tile_size == sphere_map.tile_size
    with pytest.raises(OSError):
        tessera.PolycubeMap.load(str(tmp_path / "missing.polycube"))
    (tmp_path / "junk.polycube").write_text("not a polycube")
    with pytest.raises(tessera.Error):
        tessera.PolycubeMap.load(str(tmp_path / "junk.polycube"))


def test_distortion_retries(sphere_map):
    v, f = uv_sphere()
    best = tessera.PolycubeMap.build(v, f, tiles_across=4, distortion_retries=2)
    assert best.num_quads > 0 and best.labels.shape == (len(f),)
    with pytest.raises(tessera.Error, match="distortion_retries"):
        tessera.PolycubeMap.build(v, f, tiles_across=4, distortion_retries=-1)


def test_bad_input():
    v, f = uv_sphere()
    with pytest.raises(tessera.Error):
        tessera.PolycubeMap.build(v, f[:-3])  # open mesh
    with pytest.raises(TypeError):
        tessera.PolycubeMap.build(v.astype(np.float32), f)
    with pytest.raises(ValueError):
        tessera.PolycubeMap.build(v, f + len(v))


def test_remesh_keeps_the_surface_and_evens_the_triangles():
    v, f = uv_sphere()  # slivers at the poles
    v2, f2, stats = tessera.remesh(v, f, edges_across=12, feature_angle=180)
    assert v2.dtype == np.float64 and f2.shape[1] == 3 and len(f2) > 0
    assert stats["min_angle"] > stats["min_angle_input"] and stats["min_angle"] > 20
    assert stats["feature_edges"] == 0 and stats["max_deviation"] < 1e-6
    # closed: every edge used twice, and a polycube map can be built on it
    e = np.sort(np.concatenate([f2[:, [0, 1]], f2[:, [1, 2]], f2[:, [2, 0]]]), axis=1)
    _, counts = np.unique(e, axis=0, return_counts=True)
    assert (counts == 2).all()
    assert tessera.PolycubeMap.build(v2, f2, tiles_across=4).num_quads > 0
    again = tessera.remesh(v, f, edges_across=12, feature_angle=180)
    np.testing.assert_array_equal(again[0], v2)
    with pytest.raises(tessera.Error, match="edges_across"):
        tessera.remesh(v, f, edges_across=0)
    with pytest.raises(tessera.Error):
        tessera.remesh(v, f[:-3])  # open
