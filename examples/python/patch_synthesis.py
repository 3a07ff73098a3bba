#!/usr/bin/env python3
"""Patch synthesis from Python: a PatchModel built once, windows of the unbounded texture rendered
independently, and the model saved to bytes. Usage: patch_synthesis.py [OUT_DIR]"""
import os
import pickle
import sys

import numpy as np

import tessera


def main(out="."):
    os.makedirs(out, exist_ok=True)
    bricks = tessera.exemplar("bricks", 96, 96, seed=2)
    model = tessera.PatchModel(bricks, patch_width=32, patch_height=32, overlap=8)
    texture = model.synthesize(384, 256, seed=7)
    tessera.write_png(os.path.join(out, "patch_texture.png"), texture)
    # windows are pure functions of (model, seed, x, y): render a far-away one, or a part again
    part = model.synthesize(128, 64, x=200, y=100, seed=7)
    assert np.array_equal(part, texture[100:164, 200:328])
    far = model.synthesize(256, 256, x=10**9, y=-10**9, seed=7)
    tessera.write_png(os.path.join(out, "patch_far_window.png"), far)
    # the model as bytes (or pickle) rebuilds the same texture
    again = pickle.loads(pickle.dumps(model))
    assert np.array_equal(again.synthesize(64, 64, seed=7), texture[:64, :64])
    print(f"model of {model.num_patches} patches ({len(model.save())} bytes saved); wrote patch_texture.png, "
          f"patch_far_window.png to {out}")


if __name__ == "__main__":
    main(*sys.argv[1:2])
