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
