#!/usr/bin/env python3
"""Wang tiles from Python: build the complete 2-colour set from an exemplar, compose a window of the
infinite plane (hash colouring) and one through Cohen's scanline colouring, pack the GPU atlas, and
save the set as a tile directory. Usage: wang_tiles.py [OUT_DIR]"""
import os
import sys

import numpy as np

import tessera


def main(out="."):
    os.makedirs(out, exist_ok=True)
    rock = tessera.exemplar("rock", 128, 128, seed=2)
    tiles = tessera.build_wang_tiles(rock, tile_size=48, seed=1)
    print(f"{tiles.num_tiles} tiles of {tiles.tile_size} px, exact for {tiles.exact_mip_levels} mip levels")
    # any window of the unbounded plane: render two overlapping windows, they agree where they overlap
    plane = tiles.compose(384, 256, x=-100, y=40, seed=5)
    part = tiles.compose(100, 100, x=0, y=100, seed=5)
    assert np.array_equal(part, plane[60:160, 100:200])
    tessera.write_png(os.path.join(out, "wang_plane.png"), plane)
    tessera.write_png(os.path.join(out, "wang_scanline_outlined.png"),
                      tiles.compose(384, 256, coloring="scanline", outline=True, seed=5))
    atlas = tiles.atlas()
    tessera.write_png(os.path.join(out, "wang_atlas.png"), atlas["image"])
    tiles.save(os.path.join(out, "wang_set"))
    print("wrote wang_plane.png, wang_scanline_outlined.png, wang_atlas.png, wang_set/ to", out)


if __name__ == "__main__":
    main(*sys.argv[1:2])
