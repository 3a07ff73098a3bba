#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets into tests/fuzz/corpus/<target>/ (small, valid and
nearly valid files of every variant each reader understands). Run from anywhere; overwrites only the
seed_* files, never the reproducers added by hand (crash_* from fuzzing, finding_* from issue 21)."""
import os
import struct
import zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def put(target, name, data):
    d = os.path.join(ROOT, target)
    os.makedirs(d, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(d, "seed_" + name), "wb") as f:
        f.write(data)


# --- png -----------------------------------------------------------------------------------------
def chunk(t, body):
    return struct.pack(">I", len(body)) + t + body + struct.pack(">I", zlib.crc32(t + body) & 0xFFFFFFFF)


def png(w, h, depth, ctype, rows, interlace=0, extra=(), idat_split=1, empty_idat=False):
    bpp = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype] * depth
    row_bytes = (w * bpp + 7) // 8
    raw = b""
    for y in range(h):
        raw += bytes([y % 5]) + bytes((rows(y, i)) & 0xFF for i in range(row_bytes))
    z = zlib.compress(raw, 9)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, interlace))
    for t, b in extra:
        out += chunk(t, b)
    if empty_idat:
        out += chunk(b"IDAT", b"")
    step = max(1, len(z) // idat_split)
    for i in range(0, len(z), step):
        out += chunk(b"IDAT", z[i:i + step])
    return out + chunk(b"IEND", b"")


g = lambda y, i: (y * 37 + i * 11)
put("png", "grey8.png", png(5, 4, 8, 0, g))
put("png", "grey1.png", png(9, 3, 1, 0, g))
put("png", "grey16.png", png(3, 3, 16, 0, g))
put("png", "rgb8.png", png(4, 4, 8, 2, g))
put("png", "rgba16.png", png(2, 3, 16, 6, g))
put("png", "ga8.png", png(3, 2, 8, 4, g))
put("png", "palette4_trns.png",
    png(6, 3, 4, 3, g, extra=[(b"PLTE", bytes(range(48))), (b"tRNS", bytes([0, 128, 255]))]))
put("png", "palette8.png", png(4, 2, 8, 3, lambda y, i: i % 3, extra=[(b"PLTE", bytes(range(9)))]))
put("png", "rgb_trns.png", png(3, 3, 8, 2, g, extra=[(b"tRNS", bytes(6))]))
put("png", "interlaced.png", png(9, 9, 8, 2, g, interlace=1))
put("png", "split_idat.png", png(8, 8, 8, 6, g, idat_split=4))
put("png", "empty_first_idat.png", png(4, 4, 8, 0, g, empty_idat=True))
put("png", "ancillary.png", png(2, 2, 8, 0, g, extra=[(b"tEXt", b"Comment\0fuzz"), (b"gAMA", b"\0\0\xb1\x8f")]))

# --- obj -----------------------------------------------------------------------------------------
put("obj", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
put("obj", "quad_uv.obj", "# quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\nf 1/1/1 2/2/1 3/3/1 4/4/1\n")
put("obj", "negative.obj", "v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\nvt 0.5\nf -3/-1 -2/-1 -1/-1\ng group\ns off\n")
put("obj", "normals.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 1 1 1e3\r\nvn 0 0 1\r\nf 1//1 2//1 3//1\r\nf 2//1 4//1 3//1\r\n")
put("obj", "continuation.obj", "v 0 0 \\\n 0\nv 1e-3 0 0\nv 0 -2.5E+2 0\nf 1 \\\n2 3\nusemtl x\nl 1 2\n")

# --- off -----------------------------------------------------------------------------------------
put("off", "triangle.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
put("off", "quad_colour.off", "COFF\n# comment\n4 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n1 1 0 0 0 1 1\n0 1 0 1 1 1 1\n"
    "4 0 1 2 3 255 0 0\n")
put("off", "counts_next_line.off", "NOFF\n\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 2 1 0\n")
put("off", "stoff.off", "STOFF 4 2 5\n0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n")

# --- ply -----------------------------------------------------------------------------------------
def ply_header(fmt, uv_face=False, uv_vertex=False, xyz="float", idx="int", cnt="uchar", extra=""):
    h = "ply\nformat %s 1.0\ncomment seed\nelement vertex 4\nproperty %s x\nproperty %s y\nproperty %s z\n" % (
        fmt, xyz, xyz, xyz)
    if uv_vertex:
        h += "property float u\nproperty float v\n"
    h += extra
    h += "element face 2\nproperty list %s %s vertex_indices\n" % (cnt, idx)
    if uv_face:
        h += "property list uchar float texcoord\n"
    return h + "end_header\n"


verts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
faces = [(0, 1, 2), (0, 2, 3)]
asc = ply_header("ascii") + "".join("%g %g %g\n" % v for v in verts) + "".join("3 %d %d %d\n" % f for f in faces)
put("ply", "ascii.ply", asc)
asc_uv = ply_header("ascii", uv_vertex=True) + "".join("%g %g %g %g %g\n" % (v + v[:2]) for v in verts) + \
    "".join("3 %d %d %d\n" % f for f in faces)
put("ply", "ascii_vertex_uv.ply", asc_uv)
asc_face_uv = ply_header("ascii", uv_face=True) + "".join("%g %g %g\n" % v for v in verts) + \
    "".join("3 %d %d %d 6 0 0 1 0 1 1\n" % f for f in faces)
put("ply", "ascii_face_uv.ply", asc_face_uv)
put("ply", "ascii_quad.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
    "property double z\nelement face 1\nproperty list uchar int vertex_index\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "4 0 1 2 3\n")
for endian, fmt, tag in (("<", "binary_little_endian", "le"), (">", "binary_big_endian", "be")):
    body = b"".join(struct.pack(endian + "fff", *v) for v in verts)
    body += b"".join(struct.pack(endian + "Biii", 3, *f) for f in faces)
    put("ply", "binary_%s.ply" % tag, ply_header(fmt).encode() + body)
    body = b"".join(struct.pack(endian + "ddd", *v) for v in verts)
    body += b"".join(struct.pack(endian + "HHHH", 3, *f) + struct.pack(endian + "B6f", 6, 0, 0, 1, 0, 1, 1)
                     for f in faces)
    put("ply", "binary_%s_face_uv.ply" % tag,
        ply_header(fmt, uv_face=True, xyz="double", idx="ushort", cnt="ushort").encode() + body)
body = b"".join(struct.pack("<bbb", *v) + b"\x07" for v in verts)
body += b"".join(struct.pack("<Ibbb", 3, *f) for f in faces)
put("ply", "binary_char.ply", ply_header("binary_little_endian", xyz="char", idx="char", cnt="uint",
                                         extra="property uchar flag\n").encode() + body)

# --- tile manifests --------------------------------------------------------------------------------
def manifest(nh, nv, tiles, size=16, extra=""):
    t = ",\n".join('    {"index": %d, "file": "%s", "edges": [%d, %d, %d, %d]%s}' % (i, f, *e, x)
                   for i, (f, e, x) in enumerate(tiles))
    return ('{\n  "tile_size": %s, "horizontal_colors": %d, "vertical_colors": %d,%s\n  "tiles": [\n%s\n  ]\n}\n'
            % (size, nh, nv, extra, t))


two = [("tile_%d.png" % i, ((i >> 0) & 1, (i >> 1) & 1, (i >> 2) & 1, (i >> 3) & 1), "") for i in range(16)]
put("tile_manifest", "complete_2x2.json", manifest(2, 2, two))
put("tile_manifest", "one.json", manifest(1, 1, [("a.png", (0, 0, 0, 0), ', "weight": 1.5')], extra=' "height": 0.25,'))
put("tile_manifest", "geometric.json", manifest(1, 1, [("tile_0.obj", (0, 0, 0, 0), "")], size="4.8",
                                                extra=' "edge_height": 0.1, "tile_world_size": 4.8,'))
put("tile_manifest", "tolerant.json", b'\xef\xbb\xbf' + b'// hand-written\n{"tiles": [{"edges": [0,0,0,0], "file": "b\\u00e9.png", '
    b'"index": 0,},], /* c */ "vertical_colors": 1, "horizontal_colors": 1, "tile_size": 8,}')
put("tile_manifest", "subdir.json", manifest(1, 1, [("sub/t.png", (0, 0, 0, 0), "")]))

# --- tile directories: tiles.json, "\n--tile--\n", one tile file (stored as tile_0.png and tile_0.obj)
grey16 = png(16, 16, 8, 2, g)
put("tile_dir", "image.bin", manifest(1, 1, [("tile_0.png", (0, 0, 0, 0), "")]).encode() + b"\n--tile--\n" + grey16)
put("tile_dir", "image_4.bin", manifest(2, 1, [("tile_0.png", (a, 0, b, 0), "") for a in (0, 1) for b in (0, 1)])
    .encode() + b"\n--tile--\n" + grey16)
obj_tile = "v 0.5 0.5 0\nv 3 0.5 0\nv 0.5 3 0.2\nf 1 2 3\n"
put("tile_dir", "geometric.bin", manifest(1, 1, [("tile_0.obj", (0, 0, 0, 0), "")], size="4",
                                          extra=' "edge_height": 0,').encode() + b"\n--tile--\n" + obj_tile.encode())
put("tile_dir", "missing_tile.bin", manifest(1, 1, [("tile_1.png", (0, 0, 0, 0), "")]))

# --- tsuv ------------------------------------------------------------------------------------------
def tsuv(n, version=2):
    out = b"TSUV" + struct.pack("<IIIIIIIf", version, n, 64, 48, 128, 128, 3, 0.5)
    for f in range(n):
        out += struct.pack("<6f2fIfI", 0.1 * f, 0.2, 0.3, 0.4, 0.5, 0.6, 1.5, -2.5, f % 3, 1.0, f & 1)
    return out


put("tsuv", "empty.tsuv", tsuv(0))
put("tsuv", "three.tsuv", tsuv(3))
put("tsuv", "wrong_version.tsuv", tsuv(1, version=1))
