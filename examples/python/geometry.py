#!/usr/bin/env python3
"""Geometric textures (paper 000) from Python: a ring exemplar, a geometric Wang tile set, and a plane
tiled from it, written as OBJ meshes and preview pictures. Usage: geometry.py [OUT_DIR]"""
import os
import sys

import tessera


def main(out="."):
    os.makedirs(out, exist_ok=True)
    V, F = tessera.mesh_exemplar("rings", seed=1)
    tessera.write_mesh(os.path.join(out, "geometry_exemplar.obj"), V, F)
    tessera.write_png(os.path.join(out, "geometry_exemplar.png"),
                      tessera.render_mesh_preview(V, F, 480, 360, elevation_degrees=60))
    tiles = tessera.GeometricTileSet.build(V, F, tile_size=6.4, seed=3)
    print(f"{tiles.num_tiles} tiles; edge colours (N, E, S, W) of tile 0: {tuple(tiles.edges[0])}")
    PV, PF = tiles.tile_plane(4, 3, seed=5)
    tessera.write_mesh(os.path.join(out, "geometry_plane.obj"), PV, PF)
    tessera.write_png(os.path.join(out, "geometry_plane.png"),
                      tessera.render_mesh_preview(PV, PF, 640, 480, elevation_degrees=65))
    print(f"plane of 4 x 3 tiles: {len(PV)} vertices, {len(PF)} faces -> {out}")


if __name__ == "__main__":
    main(*sys.argv[1:2])
