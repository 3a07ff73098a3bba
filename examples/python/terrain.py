#!/usr/bin/env python3
"""Terrain texturing (paper 003) from Python: a heightfield mesh and one synthesized frame, with the
scale field that sizes the texture by view distance. Usage: terrain.py [OUT_DIR]"""
import os
import sys

import tessera


def main(out="."):
    os.makedirs(out, exist_ok=True)
    V, F = tessera.make_terrain(cells_x=96, cells_y=96, height=14, seed=3)
    tessera.write_mesh(os.path.join(out, "terrain.obj"), V, F)
    grass = tessera.exemplar("grass", 128, 128, seed=1)
    frame = tessera.render_terrain_frame(V, F, grass, width=480, height=270, camera="grazing", seed=7,
                                         sun=(0.45, -0.35, 0.8))
    tessera.write_png(os.path.join(out, "terrain_frame.png"), frame["image"])
    field = tessera.render_terrain_frame(V, F, grass, width=480, height=270, camera="grazing", seed=7,
                                         shading="scale_field", sun=(0.45, -0.35, 0.8))
    tessera.write_png(os.path.join(out, "terrain_scale_field.png"), field["image"])
    print(f"{len(F)} triangles, {frame['visible_faces']} visible, {frame['levels']} levels; "
          f"wrote terrain.obj, terrain_frame.png, terrain_scale_field.png to {out}")


if __name__ == "__main__":
    main(*sys.argv[1:2])
