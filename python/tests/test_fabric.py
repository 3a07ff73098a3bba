"""tessera fabric bindings: cat map, its period, the game-of-life perturbation, make_fabric."""
import numpy as np
import pytest

import tessera
from conftest import noise


@pytest.mark.parametrize("dtype", [np.uint8, np.uint16, np.float32])
@pytest.mark.parametrize("channels", [1, 3, 4])
def test_cat_map_is_a_permutation_with_its_period(dtype, channels):
    img = noise((24, 24, channels), dtype, seed=channels)
    out = tessera.cat_map(img, 5)
    assert out.shape == img.shape and out.dtype == img.dtype
    assert not np.array_equal(out, img)
    assert sorted(out.reshape(-1, channels).tolist()) == sorted(img.reshape(-1, channels).tolist())
    np.testing.assert_array_equal(tessera.cat_map(out, -5), img)
    np.testing.assert_array_equal(tessera.cat_map(img, tessera.cat_map_period(24)), img)


def test_cat_map_period_values():
    assert tessera.cat_map_period(1) == 1
    assert tessera.cat_map_period(5) == 10  # Arnold's map mod 5
    assert tessera.cat_map_period(101, a=2, b=3) > 0
    with pytest.raises(tessera.InvalidArgument, match="2\\^62|n"):
        tessera.cat_map_period(0)


def test_cat_map_threads_and_errors():
    img = noise((64, 64, 3), np.uint8)
    np.testing.assert_array_equal(tessera.cat_map(img, 7, threads=1), tessera.cat_map(img, 7, threads=2))
    with pytest.raises(ValueError, match="square|non_square"):
        tessera.cat_map(noise((20, 30, 3), np.uint8), 1)
    assert tessera.cat_map(noise((20, 30, 3), np.uint8), 1, non_square="centered_square").shape == (20, 30, 3)
    with pytest.raises(ValueError, match="non_square"):
        tessera.cat_map(img, 1, non_square="nope")
    with pytest.raises(TypeError, match="float64"):
        tessera.cat_map(img.astype(np.float64), 1)
    with pytest.raises(ValueError, match="shape"):
        tessera.cat_map(np.zeros((4, 4, 5), np.uint8), 1)
    bad = noise((8, 8, 3), np.float32)
    bad[2, 2, 1] = np.nan
    with pytest.raises(ValueError):
        tessera.cat_map(bad, 1)


def test_life_perturbation_is_deterministic_and_checks_options():
    img = noise((32, 32, 3), np.uint8, seed=4)
    a = tessera.life_perturbation(img, generations=2, seed=3)
    assert a.shape == img.shape and a.dtype == img.dtype
    np.testing.assert_array_equal(a, tessera.life_perturbation(img, generations=2, seed=3, threads=1))
    assert not np.array_equal(a, img)
    np.testing.assert_array_equal(tessera.life_perturbation(img, generations=0), img)
    with pytest.raises(ValueError, match="live_count"):
        tessera.life_perturbation(img, live_count=9)
    calls = []
    tessera.life_perturbation(img, generations=3, progress=calls.append)
    assert calls
    with pytest.raises(tessera.Cancelled):
        tessera.life_perturbation(img, generations=3, progress=lambda f: False)


@pytest.mark.parametrize("preset", ["flannel", "twill", "linen", "tweed"])
def test_presets(preset):
    assert preset in tessera.fabric_presets()
    a = tessera.make_fabric(preset, 48, 32, seed=2)
    assert a.shape == (32, 48, 3) and a.dtype == np.uint8
    np.testing.assert_array_equal(a, tessera.make_fabric(preset, 48, 32, seed=2, threads=1))
    # periodic with side max(width, height): the first 32 columns repeat after 48? no: tile_size=16 repeats
    t = tessera.make_fabric(preset, 40, 40, tile_size=20, seed=2)
    np.testing.assert_array_equal(t[:20, :20], t[20:, 20:])


def test_fabric_errors_and_from_image():
    with pytest.raises(ValueError, match="unknown fabric preset 'silk'"):
        tessera.make_fabric("silk")
    with pytest.raises(ValueError):
        tessera.make_fabric("flannel", 0, 10)
    with pytest.raises((ValueError, OverflowError, MemoryError)):
        tessera.make_fabric("flannel", 1 << 40, 1 << 40)
    src = noise((32, 32, 3), np.uint8)
    f = tessera.fabric_from_image(src, 64, 48, tile_size=32, iterations=10)
    assert f.shape == (48, 64, 3)
    np.testing.assert_array_equal(f[:32, :32], tessera.cat_map(src, 10))
    with pytest.raises(ValueError, match="fit"):
        tessera.fabric_from_image(noise((30, 20, 3), np.uint8), 32, 32)
    assert tessera.fabric_from_image(noise((30, 20, 3), np.uint8), 32, 32, fit="centered_square").shape == (32, 32, 3)
