#!/usr/bin/env python3
"""Image quilting from Python: a quilted texture, and a hole filled by constrained quilting with a
mask. Usage: quilting.py [OUT_DIR]"""
import os
import sys

import numpy as np

import tessera


def main(out="."):
    os.makedirs(out, exist_ok=True)
    sand = tessera.exemplar("sand", 96, 96, seed=3)
    quilted = tessera.quilt(sand, 256, 256, patch_size=32, overlap=8, seed=1)
    tessera.write_png(os.path.join(out, "quilt_texture.png"), quilted)
    # punch a hole and fill it from the rest of the picture
    mask = np.zeros(quilted.shape[:2], dtype=bool)
    mask[96:160, 80:176] = True
    holed = quilted.copy()
    holed[mask] = 0
    filled = tessera.constrained_quilt(holed, mask, sand, patch_size=24, overlap=8, seed=2)
    assert np.array_equal(filled[~mask], holed[~mask])
    tessera.write_png(os.path.join(out, "quilt_hole_filled.png"), np.concatenate([holed, filled], axis=1))
    print("wrote quilt_texture.png, quilt_hole_filled.png to", out)


if __name__ == "__main__":
    main(*sys.argv[1:2])
