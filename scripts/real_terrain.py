#!/usr/bin/python3
"""A real elevation model as a terrain mesh, a fly-over camera path, and figures of a ground-anchored run.

  real_terrain.py mesh NPZ OUT.obj          the DEM as a z-up OBJ heightfield in metres
  real_terrain.py path OUT.obj PATH.txt N    N cameras flying over it, 1 % of the view distance per frame
  real_terrain.py stats STATS.jsonl          min/mean stability, continuity, level jump, frame time
  real_terrain.py stretch OUT.obj F.tsuv     texture stretch per visible face (anisotropy of its uv map)
  real_terrain.py plot A.jsonl B.jsonl OUT.png  per-frame frame_ms of two --stats runs (A red, B blue;
                                                 grid lines every 50 ms), a PNG written with zlib

The DEM is matplotlib's sample jacksboro_fault_dem.npz (USGS, 3 arc-second, 344 x 403 samples round
the Jacksboro fault, Tennessee; Debian package python-matplotlib-data). Uses Debian's numpy.
"""
import json
import math
import struct
import sys
import zlib

import numpy as np


def dem_mesh(npz, out):
    d = np.load(npz)
    z = d["elevation"].astype(np.float64)
    rows, cols = z.shape
    lat = 0.5 * (float(d["ymin"]) + float(d["ymax"]))
    # arc degrees to metres (spherical earth, R = 6371 km)
    metre = math.pi / 180 * 6371000.0
    dx = float(d["dx"]) * metre * math.cos(math.radians(lat))
    dy = float(d["dy"]) * metre
    with open(out, "w") as f:
        f.write("# jacksboro_fault_dem.npz (USGS DEM, matplotlib sample data): %d x %d samples, "
                "%.1f x %.1f m cells, elevation %.0f..%.0f m\n" % (cols, rows, dx, dy, z.min(), z.max()))
        for r in range(rows):
            y = (rows - 1 - r) * dy  # the first row is the north edge
            f.write("".join("v %.3f %.3f %.3f\n" % (c * dx, y, z[r, c]) for c in range(cols)))
        for r in range(rows - 1):
            for c in range(cols - 1):
                a = r * cols + c + 1  # OBJ indices from 1; counter-clockwise seen from above
                b, e, g = a + 1, a + cols, a + cols + 1
                f.write("f %d %d %d\nf %d %d %d\n" % (a, e, b, b, e, g))
    print("%s: %d vertices, %d faces, %.1f x %.1f km, relief %.0f m"
          % (out, rows * cols, 2 * (rows - 1) * (cols - 1), (cols - 1) * dx / 1000, (rows - 1) * dy / 1000,
             z.max() - z.min()))


def read_obj(path):
    v, f = [], []
    with open(path) as fh:
        for line in fh:
            if line.startswith("v "):
                v.append([float(t) for t in line.split()[1:4]])
            elif line.startswith("f "):
                f.append([int(t.split("/")[0]) - 1 for t in line.split()[1:4]])
    return np.array(v), np.array(f, dtype=np.int64)


def camera_path(obj, out, n):
    v, _ = read_obj(obj)
    lo, hi = v.min(axis=0), v.max(axis=0)
    ext = hi - lo
    # 400 m over the highest ground near the south edge, looking north and down ahead
    eye = np.array([lo[0] + 0.5 * ext[0], lo[1] + 0.08 * ext[1], hi[2] + 400.0])
    target = np.array([eye[0], lo[1] + 0.4 * ext[1], lo[2] + 0.5 * ext[2]])
    step = 0.01 * np.linalg.norm(target - eye)
    with open(out, "w") as f:
        for i in range(n):
            d = np.array([0.0, i * step, 0.0])
            e, t = eye + d, target + d
            f.write("%.3f %.3f %.3f %.3f %.3f %.3f 60\n" % (*e, *t))


def stats(path):
    rows = [json.loads(line) for line in open(path) if line.startswith("{")]
    later = rows[1:]
    ms = sorted(r["frame_ms"] for r in later)
    out = {
        "frames": len(rows),
        "visible_mean": sum(r["visible"] for r in rows) / len(rows),
        "stable_min": min(r["stable_faces"] for r in later),
        "stable_mean": sum(r["stable_faces"] for r in later) / len(later),
        "continuous_min": min(r["continuous_edges"] for r in rows),
        "continuous_mean": sum(r["continuous_edges"] for r in rows) / len(rows),
        "max_level_jump": max(r["max_level_jump"] for r in rows),
        "resynthesized_mean": sum(r["resynthesized"] for r in later) / len(later),
        "first_frame_ms": rows[0]["frame_ms"],
        "frame_ms_median": ms[len(ms) // 2],
        "frame_ms_max": ms[-1],
    }
    if "stretch_max" in rows[0]:  # ground-anchored frames: the texture stretch of the faces in view
        out["stretch_median_max"] = max(r["stretch_median"] for r in rows)
        out["stretch_p95_max"] = max(r["stretch_p95"] for r in rows)
        out["stretch_max"] = max(r["stretch_max"] for r in rows)
    print(json.dumps(out))


def stretch(obj, tsuv):
    v, f = read_obj(obj)
    with open(tsuv, "rb") as fh:
        data = fh.read()
    magic, version, nf = struct.unpack_from("<4sII", data, 0)
    assert magic == b"TSUV" and version == 3 and nf == len(f), (magic, version, nf, len(f))
    rec = np.frombuffer(data, dtype=np.dtype([("uv", "<f4", 6), ("off", "<f4", 2), ("level", "<i4"),
                                              ("scale", "<f4"), ("state", "<u4")]), count=nf, offset=40)
    vis = rec["state"] != 0
    p = v[f[vis]]
    uv = rec["uv"][vis].astype(np.float64).reshape(-1, 3, 2)
    # the affine map from the face's plane (orthonormal frame) to uv; its singular values' ratio
    # is the stretch of the texture across the face (1: congruent)
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    a = e1 / np.linalg.norm(e1, axis=1)[:, None]
    n = np.cross(e1, e2)
    b = np.cross(n / np.linalg.norm(n, axis=1)[:, None], a)
    P = np.stack([np.stack([np.einsum("ij,ij->i", e1, a), np.einsum("ij,ij->i", e1, b)], 1),
                  np.stack([np.einsum("ij,ij->i", e2, a), np.einsum("ij,ij->i", e2, b)], 1)], 1)
    U = np.stack([uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]], 1)
    J = np.linalg.solve(P, U)  # rows: plane coordinates -> uv
    s = np.linalg.svd(J, compute_uv=False)
    ratio = s[:, 0] / s[:, 1]
    slope = np.degrees(np.arccos(np.abs(n[:, 2]) / np.linalg.norm(n, axis=1)))
    q = np.percentile(ratio, [50, 95, 99])
    print(json.dumps({"faces": int(vis.sum()), "stretch_median": round(float(q[0]), 4),
                      "stretch_p95": round(float(q[1]), 4), "stretch_p99": round(float(q[2]), 4),
                      "stretch_max": round(float(ratio.max()), 4),
                      "over_5_percent": round(float((ratio > 1.05).mean()), 4),
                      "slope_median_deg": round(float(np.median(slope)), 1),
                      "slope_max_deg": round(float(slope.max()), 1)}))


def plot(a, b, out, ymax=550.0):
    w, h, m = 720, 320, 20
    img = np.full((h, w, 3), 255, np.uint8)

    def ypix(ms):
        return int(round(h - m - (min(ms, ymax) / ymax) * (h - 2 * m)))

    for g in range(0, int(ymax) + 1, 50):
        img[ypix(g), m:w - m] = (215, 215, 215) if g else (90, 90, 90)
    img[m:h - m + 1, m] = (90, 90, 90)
    for path, colour in ((a, (200, 40, 40)), (b, (40, 80, 200))):
        ms = [json.loads(line)["frame_ms"] for line in open(path) if line.startswith("{")]
        xs = [m + int(round(i * (w - 2 * m - 1) / (len(ms) - 1))) for i in range(len(ms))]
        for i in range(len(ms) - 1):
            for t in np.linspace(0, 1, 200):
                x = int(round(xs[i] + t * (xs[i + 1] - xs[i])))
                y = int(round(ypix(ms[i]) + t * (ypix(ms[i + 1]) - ypix(ms[i]))))
                img[max(0, y - 1):y + 2, max(0, x - 1):x + 2] = colour
        for x, v in zip(xs, ms):
            img[max(0, ypix(v) - 3):ypix(v) + 4, max(0, x - 3):x + 4] = colour
    raw = b"".join(b"\0" + img[y].tobytes() for y in range(h))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xffffffff)

    with open(out, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "mesh":
        dem_mesh(sys.argv[2], sys.argv[3])
    elif cmd == "path":
        camera_path(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    elif cmd == "stats":
        stats(sys.argv[2])
    elif cmd == "stretch":
        stretch(sys.argv[2], sys.argv[3])
    elif cmd == "plot":
        plot(sys.argv[2], sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)
