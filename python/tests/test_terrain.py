"""tessera terrain bindings: make_terrain and one synthesized frame."""
import numpy as np
import pytest

import tessera


@pytest.fixture(scope="module")
def terrain():
    return tessera.make_terrain(cells_x=24, cells_y=24, seed=3)


def test_make_terrain(terrain):
    v, f = terrain
    assert v.shape == (25 * 25, 3) and v.dtype == np.float64
    assert f.shape[1] == 3 and f.dtype == np.int64 and f.max() < len(v)
    v2, _ = tessera.make_terrain(cells_x=24, cells_y=24, seed=3, threads=1)
    np.testing.assert_array_equal(v, v2)
    assert not np.array_equal(v, tessera.make_terrain(cells_x=24, cells_y=24, seed=4)[0])
    with pytest.raises(ValueError, match="cells"):
        tessera.make_terrain(cells_x=0)
    with pytest.raises(tessera.Error, match="2\\^28"):
        tessera.make_terrain(cells_x=1 << 14, cells_y=1 << 14)


def test_frame(terrain):
    v, f = terrain
    ex = tessera.exemplar("grass", 64, 64, seed=1)
    r = tessera.render_terrain_frame(v, f, ex, width=96, height=64, camera="oblique", seed=2)
    img = r["image"]
    assert img.shape == (64, 96, 3) and img.dtype == np.uint8
    assert r["level"].shape == (len(f),) and r["scale"].shape == (len(f),) and r["visible_faces"] > 0
    again = tessera.render_terrain_frame(v, f, ex, width=96, height=64, camera="oblique", seed=2, threads=1)
    np.testing.assert_array_equal(img, again["image"])
    field = tessera.render_terrain_frame(v, f, ex, width=96, height=64, camera="oblique", shading="scale_field")
    assert not np.array_equal(field["image"], img)
    look = tessera.render_terrain_frame(v, f, ex, width=32, height=32, eye=(0, -70, 25), target=(0, 0, 0))
    assert look["image"].shape == (32, 32, 3)


def test_frame_errors(terrain):
    v, f = terrain
    ex = tessera.exemplar("grass", 32, 32)
    with pytest.raises(ValueError, match="camera|grazing"):
        tessera.render_terrain_frame(v, f, ex, camera="fisheye")
    with pytest.raises(ValueError, match="eye|target"):
        tessera.render_terrain_frame(v, f, ex, eye=(0, 0, 0), target=(0, 0, 0))
    with pytest.raises(ValueError):
        tessera.render_terrain_frame(v, f, ex, width=100000, height=10)
    with pytest.raises(ValueError, match="shading"):
        tessera.render_terrain_frame(v, f, ex, shading="phong")
    bad = v.copy()
    bad[0, 2] = np.inf
    with pytest.raises(ValueError, match="not finite"):
        tessera.render_terrain_frame(bad, f, ex)
    with pytest.raises(TypeError):
        tessera.render_terrain_frame(v, f, ex.astype(np.int16))
