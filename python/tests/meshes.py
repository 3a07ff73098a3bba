"""Small closed meshes for the geometry and surface tests (and examples): (V float64, F int64)."""
import numpy as np


def uv_sphere(rings=10, segments=20, radius=1.0):
    """A closed UV sphere with outward, counter-clockwise faces."""
    verts = [(0.0, 0.0, radius)]
    for i in range(1, rings):
        t = np.pi * i / rings
        for j in range(segments):
            p = 2 * np.pi * j / segments
            verts.append((radius * np.sin(t) * np.cos(p), radius * np.sin(t) * np.sin(p), radius * np.cos(t)))
    verts.append((0.0, 0.0, -radius))
    faces = []
    south = len(verts) - 1

    def ring(i, j):
        return 1 + (i - 1) * segments + j % segments

    for j in range(segments):
        faces.append((0, ring(1, j), ring(1, j + 1)))
        faces.append((south, ring(rings - 1, j + 1), ring(rings - 1, j)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)
            faces.append((a, c, d))
            faces.append((a, d, b))
    return np.asarray(verts, dtype=np.float64), np.asarray(faces, dtype=np.int64)
