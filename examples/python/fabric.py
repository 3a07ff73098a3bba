#!/usr/bin/env python3
"""Fabric textures (paper 001) from Python: the four presets, a cat map and its period, and a fabric
from an image of your own. Usage: fabric.py [OUT_DIR]"""
import os
import sys

import numpy as np

import tessera


def main(out="."):
    os.makedirs(out, exist_ok=True)
    # the paper's presets, side by side
    tiles = [tessera.make_fabric(p, 192, 192, tile_size=96, seed=1) for p in tessera.fabric_presets()]
    gap = np.full((192, 8, 3), 255, np.uint8)
    strip = np.concatenate([t if i == 0 else np.concatenate([gap, t], axis=1) for i, t in enumerate(tiles)], axis=1)
    tessera.write_png(os.path.join(out, "fabric_presets.png"), strip)

    # the cat map scrambles a picture and brings it back after its period
    img = tessera.exemplar("bricks", 128, 128, seed=2)
    period = tessera.cat_map_period(128)
    steps = [0, 1, 3, period // 2, period]
    row = np.concatenate([tessera.cat_map(img, s) for s in steps], axis=1)
    tessera.write_png(os.path.join(out, "fabric_cat_map.png"), row)
    print(f"cat map period for 128 x 128: {period} steps")

    # a tweed-like fabric from any image: cat map, then a game-of-life perturbation
    fabric = tessera.fabric_from_image(img, 256, 256, tile_size=128, iterations=45, generations=3, seed=5)
    tessera.write_png(os.path.join(out, "fabric_from_image.png"), fabric)
    print("wrote", ", ".join(f"fabric_{n}.png" for n in ("presets", "cat_map", "from_image")), "to", out)


if __name__ == "__main__":
    main(*sys.argv[1:2])
