#!/usr/bin/env python3
"""Write the fuzz target's seed corpus (Testing/Fuzz/corpus/) and the hand-made regression
inputs (Testing/Fuzz/regressions/encoded-*).

Each seed is a small mesh encoded in the byte layout of ColorDecimationFuzz.h: closed and open
manifolds, flat and curved, and the hostile cases (bow-tie, fin, duplicates, mixed
orientation, polygons and strips, NaN, out-of-range ids, every colour type). The regression
inputs pin down, in a readable form, the bugs that fuzzing found (see regressions/README.md).
Usage:

    python3 make_corpus.py [CORPUS_FOLDER [REGRESSIONS_FOLDER]]

(default: corpus/ and regressions/ beside this file). The output is deterministic, so
re-running it leaves the committed files unchanged.
"""
import math
import os
import struct
import sys

# Byte codes (see ColorDecimationFuzz.h).
NAN_CODE = 224
INF_CODE = 225
RAW_DOUBLE = 255
BAD_ID = {"-1": 250, "n": 251, "n+1000": 252, "int32max": 253, "2^40": 254, "-2^40": 255}

TYPES = ["char", "signed char", "unsigned char", "short", "unsigned short", "int",
         "unsigned int", "long", "unsigned long", "long long", "unsigned long long", "float",
         "double", "vtkIdType"]
STRUCT = {"char": "b", "signed char": "b", "unsigned char": "B", "short": "h",
          "unsigned short": "H", "int": "i", "unsigned int": "I", "long": "q",
          "unsigned long": "Q", "long long": "q", "unsigned long long": "Q", "float": "f",
          "double": "d", "vtkIdType": "q"}
NO_COLOR = 14
CELL_COLOR = 15


def coord(x):
    """Grid code when x is on the 1/16 grid in range, else a raw double."""
    if isinstance(x, int) and x >= 224:
        return bytes([x])
    code = x * 16 + 112
    if abs(code - round(code)) < 1e-9 and 0 <= round(code) <= 223:
        return bytes([int(round(code))])
    return bytes([RAW_DOUBLE]) + struct.pack("<d", x)


def quantize(x):
    return round(x * 16) / 16


def encode(points, triangles, *, metric=0, preserve=False, no_ids=False, double=False,
           by_name=False, extra=False, stale_ids=False, cell_ghosts=None, point_ghosts=None,
           unnamed=False, target=225, angle=125, weight=0, scale=0, polys=(), strips=(),
           verts=(), lines=(), color_kind=2, components=3, raw=False, count_code=0,
           colors=None, controls=None, more_controls=None):
    """Encode one input. `colors` is a flat list of values (bytes unless raw)."""
    options = (metric & 3) | (4 if preserve else 0) | (8 if no_ids else 0) | \
        (16 if double else 0) | (32 if by_name else 0) | (64 if extra else 0) | \
        (128 if stale_ids else 0)
    more = (1 if cell_ghosts is not None else 0) | (2 if point_ghosts is not None else 0) | \
        (4 if unnamed else 0)
    out = bytearray([options, more, target, angle, weight, scale, len(points) % 251])
    for p in points:
        for x in p:
            out += coord(x)
    out += struct.pack("<H", len(triangles))
    for t in triangles:
        out += bytes(t)
    for section, modulo in ((polys, 9), (strips, 12), (verts, 4), (lines, 5)):
        out.append(len(section))
        for cell in section:
            assert len(cell) < modulo
            out.append(len(cell))
            out += bytes(cell)
    out += bytes([color_kind, (components - 1) | (0x80 if raw else 0), count_code])
    if color_kind not in (NO_COLOR, CELL_COLOR):
        if raw:
            fmt = "<" + STRUCT[TYPES[color_kind]]
            for v in colors:
                out += struct.pack(fmt, v)
        else:
            out += bytes(colors)
    if cell_ghosts is not None:
        out += bytes(cell_ghosts)
    if point_ghosts is not None:
        out += bytes(point_ghosts)
    if controls is not None:
        out.append(controls)
    if more_controls is not None:
        out.append(more_controls)
    return bytes(out)


def rgb(p, components=3):
    x, y, z = p
    c = [int(127.5 + 127.5 * math.sin(1.3 * x + 0.4)), 200 if y > 0 else 40,
         int(127.5 + 127.5 * math.cos(0.9 * z - x))]
    return (c + [255, 17])[:components] if components >= 3 else [c[0]]


def colors_for(points, components=3):
    return [v for p in points for v in rgb(p, components)]


def grid(nx, ny, flat=False, size=6.0):
    points, triangles = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = quantize(-size / 2 + size * i / nx)
            y = quantize(-size / 2 + size * j / ny)
            z = 0.0 if flat else quantize(0.5 * math.sin(x) * math.cos(y))
            points.append((x, y, z))
    for j in range(ny):
        for i in range(nx):
            a = j * (nx + 1) + i
            b, c, d = a + 1, a + nx + 2, a + nx + 1
            triangles += [(a, b, c), (a, c, d)]
    return points, triangles


def icosphere(level, radius=4.0):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in verts]
    for _ in range(level):
        cache, new_faces = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = [(verts[a][k] + verts[b][k]) / 2 for k in range(3)]
                n = math.sqrt(sum(x * x for x in m))
                verts.append(tuple(x / n for x in m))
                cache[key] = len(verts) - 1
            return cache[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return [tuple(quantize(radius * x) for x in v) for v in verts], faces


def torus(nu, nv, r1=4.0, r2=1.5):
    points, triangles = [], []
    for i in range(nu):
        for j in range(nv):
            u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
            points.append(tuple(quantize(x) for x in (
                (r1 + r2 * math.cos(v)) * math.cos(u), (r1 + r2 * math.cos(v)) * math.sin(u),
                r2 * math.sin(v))))
    for i in range(nu):
        for j in range(nv):
            a = i * nv + j
            b = ((i + 1) % nu) * nv + j
            c = ((i + 1) % nu) * nv + (j + 1) % nv
            d = i * nv + (j + 1) % nv
            triangles += [(a, b, c), (a, c, d)]
    return points, triangles


TETRAHEDRON = ([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)],
               [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])


def closed_seeds(s):
    """Closed surfaces: tetrahedron, octahedron, icospheres, torus."""
    tet_p, tet_t = TETRAHEDRON
    s["tetrahedron"] = encode(tet_p, tet_t, colors=colors_for(tet_p))
    oct_p = [(2, 0, 0), (-2, 0, 0), (0, 2, 0), (0, -2, 0), (0, 0, 2), (0, 0, -2)]
    oct_t = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5),
             (0, 3, 5)]
    s["octahedron"] = encode(oct_p, oct_t, target=250, colors=colors_for(oct_p))
    ico_p, ico_t = icosphere(1)
    s["icosphere1"] = encode(ico_p, ico_t, colors=colors_for(ico_p))
    s["icosphere1_target1_geometry"] = encode(ico_p, ico_t, metric=1, target=250,
                                              colors=colors_for(ico_p))
    s["icosphere1_float_colors"] = encode(
        ico_p, ico_t, double=True, color_kind=11, raw=True,
        colors=[v / 255 for v in colors_for(ico_p)])
    ico2_p, ico2_t = icosphere(2)  # 162 points, 320 triangles
    s["icosphere2"] = encode(ico2_p, ico2_t, angle=250, colors=colors_for(ico2_p))
    tor_p, tor_t = torus(10, 6)
    s["torus"] = encode(tor_p, tor_t, target=250, colors=colors_for(tor_p, 4), components=4)


def grid_seeds(s):
    """Open grids: flat, waved, with controls, scales, grey and unnamed colours, mixed
    orientation."""
    ico_p, ico_t = icosphere(1)
    g_p, g_t = grid(8, 8, flat=True)
    s["flat_grid"] = encode(g_p, g_t, colors=colors_for(g_p))
    s["flat_grid_preserve_boundary"] = encode(g_p, g_t, preserve=True, target=250,
                                              colors=colors_for(g_p))
    s["flat_grid_constant_color"] = encode(g_p, g_t, colors=[90] * (3 * len(g_p)))
    # The controls byte: MaximumError 1e-3 with a lock array; a triangle target of 5 with a
    # missing lock array; MaximumError NaN; a short lock array.
    s["icosphere1_max_error_locks"] = encode(ico_p, ico_t, colors=colors_for(ico_p),
                                             controls=2 | (1 << 5))
    s["flat_grid_target5_missing_lock"] = encode(g_p, g_t, colors=colors_for(g_p),
                                                 controls=(2 << 3) | (2 << 5))
    s["icosphere1_max_error_nan"] = encode(ico_p, ico_t, colors=colors_for(ico_p), controls=5)
    s["icosphere1_short_lock"] = encode(ico_p, ico_t, colors=colors_for(ico_p), controls=3 << 5)
    w_p, w_t = grid(10, 8)
    s["waved_grid_extra_arrays"] = encode(w_p, w_t, extra=True, stale_ids=True,
                                          colors=colors_for(w_p))
    s["waved_grid_scale_1e7"] = encode(w_p, w_t, scale=2, weight=6, colors=colors_for(w_p))
    s["waved_grid_scale_1e-7"] = encode(w_p, w_t, scale=1, weight=7, colors=colors_for(w_p))
    s["waved_grid_grey"] = encode(w_p, w_t, components=1, colors=colors_for(w_p, 1))
    s["waved_grid_unnamed_by_name"] = encode(w_p, w_t, unnamed=True, by_name=True,
                                             colors=colors_for(w_p))
    # Mixed orientation: every third triangle reversed.
    mixed = [t if k % 3 else (t[0], t[2], t[1]) for k, t in enumerate(w_t)]
    s["mixed_orientation"] = encode(w_p, mixed, colors=colors_for(w_p))
    s["mixed_orientation_consistent"] = encode(w_p, mixed, colors=colors_for(w_p), controls=0,
                                               more_controls=1)


def non_manifold_seeds(s):
    """Bow-tie, fin, duplicates, soups, zero areas, isolated points."""
    tet_p, _ = TETRAHEDRON
    g_p, g_t = grid(8, 8, flat=True)
    # Bow-tie: two fans sharing their centre.
    bow_p = [(0, 0, 0)] + [(2 * math.cos(a), 2 * math.sin(a), 0.5)
                           for a in [k * math.pi / 6 for k in range(12)]]
    bow_p = [tuple(quantize(x) for x in p) for p in bow_p]
    bow_t = [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5), (0, 7, 8), (0, 8, 9), (0, 9, 10),
             (0, 10, 11)]
    s["bowtie"] = encode(bow_p, bow_t, colors=colors_for(bow_p))
    # Fin: a third triangle on an interior edge of a grid.
    f_p, f_t = grid(4, 4)
    f_p = f_p + [(0.0, 0.0, 3.0)]
    s["fin"] = encode(f_p, f_t + [(6, 12, len(f_p) - 1)], colors=colors_for(f_p))
    s["duplicate_triangles"] = encode(f_p[:-1], f_t + f_t[3:6] + [(7, 13, 8)],
                                      colors=colors_for(f_p[:-1]))
    s["double_sided_triangle"] = encode(tet_p[:3], [(0, 1, 2), (0, 2, 1)],
                                        colors=colors_for(tet_p[:3]))
    s["single_triangle"] = encode(tet_p[:3], [(0, 1, 2)], target=250, colors=colors_for(tet_p[:3]))
    # Duplicate points: the grid's triangles as a soup, plus a zero-area row.
    soup_p = [g_p[i] for t in g_t[:20] for i in t]
    s["triangle_soup"] = encode(soup_p, [(3 * k, 3 * k + 1, 3 * k + 2) for k in range(20)],
                                colors=colors_for(soup_p))
    # PruneComponents on pieces: the grid's triangles as a soup (every triangle its own piece),
    # decimated to 5 triangles with every third point locked.
    s["triangle_soup_prune_locks"] = encode(soup_p, [(3 * k, 3 * k + 1, 3 * k + 2)
                                                     for k in range(20)],
                                            colors=colors_for(soup_p),
                                            controls=128 | (2 << 3) | (1 << 5))
    z_p = list(g_p)
    for i in range(9, 18):
        z_p[i] = z_p[i - 9]  # second row on the first: zero-area triangles
    s["zero_area_row"] = encode(z_p, g_t, colors=colors_for(z_p))
    s["isolated_points"] = encode(g_p + [(1, 1, 5), (-3, 2, -5)], g_t,
                                  colors=colors_for(g_p + [(1, 1, 5), (-3, 2, -5)]))


def cell_kind_seeds(s):
    """Polygons, strips, vertex and line cells."""
    # Polygons and strips.
    q_p, _ = grid(4, 4)
    quads = [(j * 5 + i, j * 5 + i + 1, j * 5 + i + 6, j * 5 + i + 5)
             for j in range(4) for i in range(2)]
    strips = [tuple(r * 5 + 2 + k // 2 + (5 if k % 2 else 0) for k in range(6)) for r in range(2)]
    s["polygons_and_strips"] = encode(q_p, [], polys=quads, strips=strips,
                                      verts=[(0,), (4, 24)], lines=[(0, 1, 2)],
                                      colors=colors_for(q_p))
    s["lines_and_verts_only"] = encode(q_p, [], verts=[(0,), (1, 2)], lines=[(3, 4, 5, 6)],
                                       colors=colors_for(q_p))


def bad_input_seeds(s):
    """NaN and infinite points, ids out of range, colour arrays of the wrong length or place,
    every colour type, ghosts."""
    tet_p, tet_t = TETRAHEDRON
    ico_p, ico_t = icosphere(1)
    w_p, w_t = grid(10, 8)
    # Errors.
    s["nan_point"] = encode(tet_p[:3] + [(NAN_CODE, 0, 0)], tet_t, colors=colors_for(tet_p))
    s["inf_point_float"] = encode([(INF_CODE, 0, 0)] + tet_p[1:], tet_t, colors=colors_for(tet_p))
    s["out_of_range_ids"] = encode(tet_p, tet_t[:3] + [(1, 2, BAD_ID["n"])],
                                   colors=colors_for(tet_p))
    s["negative_ids"] = encode(tet_p, tet_t[:3] + [(1, BAD_ID["-1"], 3)], colors=colors_for(tet_p))
    s["short_color_array"] = encode(ico_p, ico_t, count_code=5, colors=colors_for(ico_p)[:-3])
    s["long_color_array_geometry"] = encode(ico_p, ico_t, metric=1, count_code=6,
                                            colors=colors_for(ico_p) + [1, 2, 3])
    s["cell_color"] = encode(ico_p, ico_t, color_kind=CELL_COLOR)
    s["no_color"] = encode(ico_p, ico_t, color_kind=NO_COLOR)
    s["empty"] = b""
    # Every colour type, 1, 3 and 4 components, raw values.
    for kind, name in enumerate(TYPES):
        comps = (1, 3, 4)[kind % 3]
        values = colors_for(ico_p, comps)
        if name in ("float", "double"):
            values = [v / 255 if k % 7 else float("nan") for k, v in enumerate(values)]
        elif name in ("char", "signed char"):
            values = [v // 2 for v in values]
        s["icosphere1_color_" + name.replace(" ", "_")] = encode(
            ico_p, ico_t, color_kind=kind, components=comps, raw=True, colors=values)
    # Ghost cells and points.
    s["ghosts"] = encode(w_p, w_t, cell_ghosts=[1 if k % 11 == 0 else 0 for k in range(len(w_t))],
                         point_ghosts=[1 if k % 13 == 0 else 0 for k in range(len(w_p))],
                         colors=colors_for(w_p))


def seeds():
    s = {}
    for group in (closed_seeds, grid_seeds, non_manifold_seeds, cell_kind_seeds,
                  bad_input_seeds):
        group(s)
    return s


def regressions():
    """Readable versions of the inputs that once broke the filter."""
    r = {}
    ico_p, ico_t = icosphere(1)
    # A point-data array shorter than the number of points is copied past its end when the
    # filter does not use it as the colour: with the Geometry metric...
    r["encoded-empty-color-array-geometry"] = encode(
        ico_p, ico_t, metric=1, count_code=7, colors=[])
    # ... and when the colour array asked for by name is not there (the scalars, unnamed and
    # empty, are then not the colour).
    r["encoded-empty-unnamed-scalars"] = encode(
        ico_p, ico_t, unnamed=True, by_name=True, count_code=7, colors=[])
    # TargetReduction NaN (it passes vtkSetClampMacro): the target triangle count was computed
    # by converting NaN to an integer, undefined behaviour (UBSan: float-cast-overflow).
    r["encoded-nan-target-reduction"] = encode(ico_p, ico_t, target=253,
                                               colors=colors_for(ico_p))
    return r


def write(folder, files):
    os.makedirs(folder, exist_ok=True)
    for name, data in sorted(files.items()):
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)
    print("wrote %d files to %s" % (len(files), folder))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "corpus"), seeds())
    write(sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "regressions"), regressions())


if __name__ == "__main__":
    main()
