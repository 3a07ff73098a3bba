#!/usr/bin/env python3
"""Surface tiling from Python: the polycube map of a closed mesh (a sphere built with NumPy), its
charts and quad layout, saved and loaded. Usage: surface.py [OUT_DIR]"""
import os
import sys

import numpy as np

import tessera


def uv_sphere(rings=12, segments=24):
    t = np.pi * np.arange(1, rings) / rings
    p = 2 * np.pi * np.arange(segments) / segments
    ring = np.stack([np.outer(np.sin(t), np.cos(p)), np.outer(np.sin(t), np.sin(p)),
                     np.outer(np.cos(t), np.ones_like(p))], axis=-1).reshape(-1, 3)
    V = np.concatenate([[[0, 0, 1]], ring, [[0, 0, -1]]]).astype(np.float64)
    idx = lambda i, j: 1 + (i - 1) * segments + j % segments  # noqa: E731
    south = len(V) - 1
    F = [(0, idx(1, j), idx(1, j + 1)) for j in range(segments)]
    F += [(south, idx(rings - 1, j + 1), idx(rings - 1, j)) for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j), idx(i + 1, j + 1)
            F += [(a, c, d), (a, d, b)]
    return V, np.asarray(F, dtype=np.int64)


def main(out="."):
    os.makedirs(out, exist_ok=True)
    V, F = uv_sphere()
    pc = tessera.PolycubeMap.build(V, F, tiles_across=4)
    print(f"{len(pc.charts)} charts, {pc.num_corners} corners, {pc.num_edges} edges, {pc.num_quads} quads "
          f"of side {pc.tile_size:.3f}")
    tessera.write_mesh(os.path.join(out, "surface_polycube.obj"), pc.polycube_positions, pc.faces)
    tessera.write_png(os.path.join(out, "surface_polycube.png"),
                      tessera.render_mesh_preview(pc.polycube_positions, pc.faces, 400, 400,
                                                  elevation_degrees=30))
    # a UV sphere has slivers at its poles: remeshed, its triangles are even (no creases on a sphere)
    V2, F2, stats = tessera.remesh(V, F, edges_across=16, feature_angle=180)
    print(f"remeshed: {len(F)} -> {len(F2)} triangles, smallest angle {stats['min_angle_input']:.1f} -> "
          f"{stats['min_angle']:.1f} degrees")
    tessera.write_mesh(os.path.join(out, "surface_remeshed.obj"), V2, F2)
    path = os.path.join(out, "sphere.polycube")
    pc.save(path)
    back = tessera.PolycubeMap.load(path)
    assert np.array_equal(back.quad_corners, pc.quad_corners)
    print("wrote surface_polycube.obj, surface_polycube.png, sphere.polycube to", out)


if __name__ == "__main__":
    main(*sys.argv[1:2])
