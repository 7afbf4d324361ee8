#!/usr/bin/env python3
"""Generates Lagoon's scene assets into scenes/assets/:

  buoy.gltf + buoy.bin   navigation buoy, 2.2 m tall, waterline at y = 0
  boat.gltf + boat.bin   5 m open motor boat, waterline at y = 0, bow toward +z
  rocks.gltf + rocks.bin three boulders bedded in sand, the sand at y = 0
  auv.gltf + auv.bin     2 m torpedo-shaped AUV, axis along z, bow toward +z, origin at its centre
  workboat.gltf + .bin   the boat with a painted hull in PBR textures (workboat_paint.png base colour,
                         workboat_normal.png plank seams, workboat_orm.png occlusion/roughness/metallic)
                         and a mooring rope whose texture (workboat_rope.png) is cut out by alpha MASK
  sand.png               256x256 seamlessly tiling RGBA8 sand texture
  README.md              what each asset is and how to regenerate it

Run from the repository root:
  python3 tools/gen_assets.py           rewrite the assets (and print a summary)
  python3 tools/gen_assets.py --check   verify the committed files equal a fresh generation and pass the
                                        checks (glTF structure, closed meshes, outward winding, PNG); exit 1
                                        otherwise

Python 3 standard library only. Output is byte-identical on every run: no timestamps, positions rounded to
1e-6 m before they are stored as float32, fixed JSON formatting, random numbers from random.Random with a
fixed seed (its random() sequence is guaranteed stable across Python versions).

Conventions (glTF's and Lagoon's): right-handed, +y up, metres, counter-clockwise front faces, the mean
water plane is y = 0. TEXCOORD_0 is in metres (1 UV unit = 1 m) so tiling textures can be scaled freely.
baseColorFactor values are linear (converted here from the sRGB paint colours below).
"""
import json
import math
import os
import random
import struct
import sys
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "scenes", "assets")
GENERATOR = "Lagoon tools/gen_assets.py"

# --------------------------------------------------------------------------------------------------------
# Small vector helpers (tuples of 3 floats)


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = length(a)
    return (a[0] / n, a[1] / n, a[2] / n) if n > 0 else (0.0, 1.0, 0.0)


def q(x):
    """Positions and UVs are rounded to 1e-6 so shared edges of separately built patches coincide exactly
    and last-bit differences of libm never reach the files; + 0.0 turns -0.0 into 0.0."""
    return round(x, 6) + 0.0


def qp(p):
    return (q(p[0]), q(p[1]), q(p[2]))


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def sinpi(s):
    """sin(pi*s), exactly 0 at s = 0 and 1 so surface edges do not pick up 1e-17 noise."""
    return 0.0 if s in (0.0, 1.0) else math.sin(math.pi * s)


def lerp(a, b, t):
    return a + (b - a) * t


def linspace(a, b, n):
    """n + 1 values from a to b, both ends exact."""
    return [a] + [a + (b - a) * k / n for k in range(1, n)] + [b]


def srgb_to_linear(c8):
    c = c8 / 255.0
    v = c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    return round(v, 4)


# --------------------------------------------------------------------------------------------------------
# Mesh building: a mesh is a list of primitives, one per material. Smooth surfaces are built as grids of
# points (a "patch"); vertex normals are shared inside a patch and split between patches, so a hard edge is
# simply a patch boundary.


class Prim:
    def __init__(self, material):
        self.material = material
        self.pos, self.nrm, self.uv, self.idx = [], [], [], []

    def vert(self, p, n, uv):
        self.pos.append(qp(p))
        self.nrm.append(normalize(n))
        self.uv.append((q(uv[0]), q(uv[1])))
        return len(self.pos) - 1

    def tri(self, a, b, c):
        pa, pb, pc = self.pos[a], self.pos[b], self.pos[c]
        if length(cross(sub(pb, pa), sub(pc, pa))) < 1e-10:
            return  # degenerate (a collapsed row at a pole or at the bow): skipped
        self.idx += [a, b, c]

    def compact(self):
        """Drops vertices no triangle uses (the duplicate points of collapsed rows)."""
        used = sorted(set(self.idx))
        remap = {old: new for new, old in enumerate(used)}
        self.pos = [self.pos[i] for i in used]
        self.nrm = [self.nrm[i] for i in used]
        self.uv = [self.uv[i] for i in used]
        self.idx = [remap[i] for i in self.idx]


class Mesh:
    def __init__(self, name):
        self.name = name
        self.prims = {}  # material name -> Prim, in insertion order

    def prim(self, material):
        if material not in self.prims:
            self.prims[material] = Prim(material)
        return self.prims[material]

    def triangles(self):
        return sum(len(p.idx) // 3 for p in self.prims.values())


def split_ac(pa, pb, pc, pd):
    """Whether quad a-b-c-d is split along a-c (else along b-d): the flatter of the two splits, so a quad
    with three corners on a symmetry plane (the stem) does not fold into a fin."""
    def flatness(t1, t2):
        n1, n2 = cross(sub(t1[1], t1[0]), sub(t1[2], t1[0])), cross(sub(t2[1], t2[0]), sub(t2[2], t2[0]))
        if length(n1) < 1e-10 or length(n2) < 1e-10:
            return 1.0
        return dot(normalize(n1), normalize(n2))
    return flatness((pa, pb, pc), (pa, pc, pd)) >= flatness((pa, pb, pd), (pb, pc, pd)) - 1e-9


def quad_tris(a, b, c, d, ac):
    return ((a, b, c), (a, c, d)) if ac else ((a, b, d), (b, c, d))


def grid_normals(P, flip):
    """Area-weighted vertex normals of a grid patch. The front of quad (i,j)-(i,j+1)-(i+1,j+1)-(i+1,j) is
    the side d(column) x d(row) points to, or the other side when flip."""
    rows, cols = len(P), len(P[0])
    N = [[(0.0, 0.0, 0.0)] * cols for _ in range(rows)]
    sign = -1.0 if flip else 1.0
    for i in range(rows - 1):
        for j in range(cols - 1):
            a, b, c, d = (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)
            ac = split_ac(P[i][j], P[i][j + 1], P[i + 1][j + 1], P[i + 1][j])
            for tri in quad_tris(a, b, c, d, ac):
                u, v, w = (P[ii][jj] for ii, jj in tri)
                n = mul(cross(sub(v, u), sub(w, u)), sign)
                for ii, jj in tri:
                    N[ii][jj] = add(N[ii][jj], n)
    return N


def grid_uv_arclength(P):
    """UV in metres: u = distance along rows (first column), v = distance along each row's columns."""
    U = [0.0]
    for i in range(1, len(P)):
        U.append(U[-1] + length(sub(P[i][0], P[i - 1][0])))
    UV = []
    for i, row in enumerate(P):
        v, r = 0.0, []
        for j, p in enumerate(row):
            if j:
                v += length(sub(p, row[j - 1]))
            r.append((U[i], v))
        UV.append(r)
    return UV


def emit_grid(prim, P, N, UV, flip, cols=None):
    """Adds the sub-grid of columns cols = (j0, j1) (inclusive; all by default) as triangles."""
    j0, j1 = cols if cols else (0, len(P[0]) - 1)
    ids = [[prim.vert(P[i][j], N[i][j], UV[i][j]) for j in range(j0, j1 + 1)] for i in range(len(P))]
    for i in range(len(P) - 1):
        for j in range(j1 - j0):
            a, b, c, d = ids[i][j], ids[i][j + 1], ids[i + 1][j + 1], ids[i + 1][j]
            ac = split_ac(P[i][j0 + j], P[i][j0 + j + 1], P[i + 1][j0 + j + 1], P[i + 1][j0 + j])
            for (u, v, w) in quad_tris(a, b, c, d, ac):
                if flip:
                    prim.tri(u, w, v)
                else:
                    prim.tri(u, v, w)


def patch(prim, P, flip=False, UV=None):
    P = [[qp(p) for p in row] for row in P]
    emit_grid(prim, P, grid_normals(P, flip), UV or grid_uv_arclength(P), flip)


def planar_uv(p, n):
    """Metric UV of a flat face: the two world axes most parallel to the face."""
    ax = max(range(3), key=lambda k: abs(n[k]))
    a, b = [k for k in range(3) if k != ax]
    return (p[a], p[b])


def fan(prim, boundary, normal):
    """A flat convex polygon (boundary: its corners in order, not repeated) as a fan around its centroid,
    wound so its front faces along normal."""
    boundary = [qp(p) for p in boundary]
    dedup = [p for k, p in enumerate(boundary) if p != boundary[k - 1]]
    c = mul((sum(p[0] for p in dedup), sum(p[1] for p in dedup), sum(p[2] for p in dedup)), 1.0 / len(dedup))
    turn = (0.0, 0.0, 0.0)
    for k in range(len(dedup)):
        turn = add(turn, cross(sub(dedup[k - 1], c), sub(dedup[k], c)))
    if dot(turn, normal) < 0:
        dedup.reverse()
    ci = prim.vert(c, normal, planar_uv(c, normal))
    ids = [prim.vert(p, normal, planar_uv(p, normal)) for p in dedup]
    for k in range(len(ids)):
        prim.tri(ci, ids[k - 1], ids[k])


def hexahedron(prim, corners):
    """A closed box with flat faces from 8 corners indexed x + 2*y + 4*z (each 0 or 1). Faces must be
    planar; each is wound to face away from the centre."""
    centre = mul(corners[0], 0.0)
    for p in corners:
        centre = add(centre, mul(p, 1.0 / 8.0))
    faces = ((0, 2, 6, 4), (1, 3, 7, 5), (0, 1, 5, 4), (2, 3, 7, 6), (0, 1, 3, 2), (4, 5, 7, 6))
    for f in faces:
        quad = [qp(corners[k]) for k in f]
        n = normalize(cross(sub(quad[2], quad[0]), sub(quad[3], quad[1])))
        fc = mul(add(add(quad[0], quad[1]), add(quad[2], quad[3])), 0.25)
        if dot(n, sub(fc, centre)) < 0:
            quad.reverse()
            n = mul(n, -1.0)
        ids = [prim.vert(p, n, planar_uv(p, n)) for p in quad]
        prim.tri(ids[0], ids[1], ids[2])
        prim.tri(ids[0], ids[2], ids[3])


def box(prim, lo, hi):
    hexahedron(prim, [(hi[0] if k & 1 else lo[0], hi[1] if k & 2 else lo[1], hi[2] if k & 4 else lo[2])
                      for k in range(8)])


class Xform:
    """p -> origin + R p with R a rotation (columns ex, ey, ez; determinant +1, so winding is kept)."""

    def __init__(self, origin=(0.0, 0.0, 0.0), ex=(1.0, 0.0, 0.0), ey=(0.0, 1.0, 0.0), ez=(0.0, 0.0, 1.0)):
        self.o, self.ex, self.ey, self.ez = origin, ex, ey, ez

    def vec(self, v):
        return add(add(mul(self.ex, v[0]), mul(self.ey, v[1])), mul(self.ez, v[2]))

    def point(self, p):
        return add(self.o, self.vec(p))

    @staticmethod
    def along(a, b):
        """Maps the local +y axis onto the segment a -> b (local y = 0 at a)."""
        ey = normalize(sub(b, a))
        helper = (0.0, 0.0, 1.0) if abs(ey[2]) < 0.9 else (1.0, 0.0, 0.0)
        ex = normalize(cross(ey, helper))
        ez = cross(ex, ey)
        return Xform(a, ex, ey, ez)


def revolve(mesh, segments, n, r_ref, xf=None):
    """Surface of revolution about the local y axis. segments: [(material, [(r, y), ...], normals)], the
    profile running from the bottom axis outward, up and back in to the axis; each segment is smooth and
    segment boundaries are hard edges. normals: [(nr, ny), ...] or None to derive them from the profile.
    Points are (r sin a, y, r cos a): with that orientation d(angle) x d(profile) points outward.
    UV: u = angle * r_ref, v = arc length along the profile (metres)."""
    xf = xf or Xform()
    v0 = 0.0
    for material, prof, nrms in segments:
        if nrms is None:
            nrms = []
            for k in range(len(prof)):
                a, b = prof[max(k - 1, 0)], prof[min(k + 1, len(prof) - 1)]
                dr, dy = b[0] - a[0], b[1] - a[1]
                m = math.hypot(dr, dy)
                nrms.append((dy / m, -dr / m))
        vs = [v0]
        for k in range(1, len(prof)):
            vs.append(vs[-1] + math.hypot(prof[k][0] - prof[k - 1][0], prof[k][1] - prof[k - 1][1]))
        v0 = vs[-1]
        P, N, UV = [], [], []
        for k, (r, y) in enumerate(prof):
            prow, nrow, uvrow = [], [], []
            for j in range(n + 1):
                ang = 2.0 * math.pi * (j % n) / n
                s, c = math.sin(ang), math.cos(ang)
                prow.append(qp(xf.point((r * s, y, r * c))))
                nr, ny = nrms[k]
                nrow.append(xf.vec((nr * s, ny, nr * c)))
                uvrow.append((2.0 * math.pi * j / n * r_ref, vs[k]))
            P.append(prow)
            N.append(nrow)
            UV.append(uvrow)
        emit_grid(mesh.prim(material), P, N, UV, False)


def cylinder(mesh, material, radius, y0, y1, n, xf=None):
    revolve(mesh, [(material, [(0.0, y0), (radius, y0)], None),
                   (material, [(radius, y0), (radius, y1)], None),
                   (material, [(radius, y1), (0.0, y1)], None)], n, radius, xf)


def sphere(mesh, material, radius, n_around, n_up):
    prof, nrms = [], []
    for k in range(n_up + 1):
        phi = -0.5 * math.pi + math.pi * k / n_up
        c, s = (0.0 if k in (0, n_up) else math.cos(phi)), math.sin(phi)
        prof.append((radius * c, radius * s))
        nrms.append((c, s))
    revolve(mesh, [(material, prof, nrms)], n_around, radius)


# --------------------------------------------------------------------------------------------------------
# Materials (paint colours in sRGB 0-255; stored linear as glTF requires)

MATERIALS = {
    "buoy_red": ((196, 30, 32), 0.45),
    "buoy_white": ((236, 236, 230), 0.45),
    "boat_hull_white": ((238, 238, 232), 0.3),
    "boat_stripe_blue": ((22, 64, 142), 0.3),
    "boat_deck": ((196, 194, 184), 0.85),
    "boat_windscreen": ((34, 42, 52), 0.1),
    "boat_motor": ((36, 36, 40), 0.4),
    "rock_grey": ((118, 112, 100), 0.9),
    "auv_yellow": ((236, 180, 22), 0.35),
    "auv_black": ((28, 28, 30), 0.5),
    "workboat_paint": ((255, 255, 255), 1.0),  # the textures carry colour and roughness
    "workboat_rope": ((255, 255, 255), 0.8),
}

# Materials with textures (issue 17): what material_json gives, plus these glTF fields; "*.png" values are
# texture references to images this generator writes.
TEXTURED_MATERIALS = {
    "workboat_paint": {"pbrMetallicRoughness": {"baseColorTexture": "workboat_paint.png",
                                                "metallicRoughnessTexture": "workboat_orm.png"},
                       "normalTexture": "workboat_normal.png", "occlusionTexture": "workboat_orm.png"},
    "workboat_rope": {"pbrMetallicRoughness": {"baseColorTexture": "workboat_rope.png"},
                      "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True},
}


def material_json(name, texture_index=None):
    """texture_index(png name) -> glTF texture index, for the TEXTURED_MATERIALS."""
    rgb, rough = MATERIALS[name]
    m = {"name": name,
         "pbrMetallicRoughness": {"baseColorFactor": [srgb_to_linear(c) for c in rgb] + [1.0],
                                  "metallicFactor": 0.0, "roughnessFactor": rough}}
    for key, value in TEXTURED_MATERIALS.get(name, {}).items():
        if key == "pbrMetallicRoughness":
            for k, png in value.items():
                m[key][k] = {"index": texture_index(png)}
        elif isinstance(value, str) and value.endswith(".png"):
            m[key] = {"index": texture_index(value)}
        else:
            m[key] = value
    return m


# --------------------------------------------------------------------------------------------------------
# Buoy: a red can float (radius 0.6 m, y = -0.8 .. 0.4, chamfered rims), a mast in red and white bands to
# y = 1.8 on a cage of four legs, a red sphere top mark to y = 2.2.

BUOY_SEGMENTS = 64


def build_buoy():
    flt = Mesh("buoy_float")
    R, ch, y0, y1 = 0.6, 0.04, -0.8, 0.4
    revolve(flt, [("buoy_red", [(0.0, y0), (R - ch, y0)], None),
                  ("buoy_red", [(R - ch, y0), (R, y0 + ch)], None),
                  ("buoy_red", [(R, y0 + ch), (R, 0.0), (R, y1 - ch)], None),  # a ring at the waterline
                  ("buoy_red", [(R, y1 - ch), (R - ch, y1)], None),
                  ("buoy_red", [(R - ch, y1), (0.0, y1)], None)], BUOY_SEGMENTS, R)

    mast = Mesh("buoy_mast")
    rm, bands = 0.11, [0.4, 0.75, 1.1, 1.45, 1.8]
    segs = [("buoy_white", [(0.0, bands[0]), (rm, bands[0])], None)]
    for k in range(4):
        segs.append(("buoy_white" if k % 2 == 0 else "buoy_red", [(rm, bands[k]), (rm, bands[k + 1])], None))
    segs.append(("buoy_red", [(rm, bands[-1]), (0.0, bands[-1])], None))
    revolve(mast, segs, 32, rm)

    cage = Mesh("buoy_cage")
    for k in range(4):
        a = math.pi / 4 + k * math.pi / 2
        foot = (0.42 * math.sin(a), 0.4, 0.42 * math.cos(a))
        head = (0.1 * math.sin(a), 1.45, 0.1 * math.cos(a))
        cylinder(cage, "buoy_red", 0.035, 0.0, length(sub(head, foot)), 12, Xform.along(foot, head))

    top = Mesh("buoy_topmark")
    sphere(top, "buoy_red", 0.22, 32, 16)

    nodes = [("float", flt, None), ("mast", mast, None), ("cage", cage, None),
             ("topmark", top, [0.0, 1.98, 0.0])]
    return "buoy", nodes


# --------------------------------------------------------------------------------------------------------
# Rocks: three boulders for a sandy floor (a cluster; place the root at the sand). Each is an icosphere
# (3 subdivisions) stretched to an ellipsoid, cut by a few random planes so it has the broken faces of real
# stone, roughened by smooth random bumps, and flattened 0.25 m below y = 0 so it sits buried in the sand.
# Normals are area-weighted vertex averages (one smooth shell per rock). Seeded, so byte-identical.

ROCK_SEED = 1913
ROCK_SUBDIV = 3
ROCKS = [  # node, translation, half-extents (x, y, z) in m
    ("rock_large", [0.0, 0.0, 0.0], (1.6, 1.1, 1.3)),
    ("rock_medium", [2.3, 0.0, 0.9], (0.9, 0.7, 0.8)),
    ("rock_small", [-1.4, 0.0, 1.9], (0.55, 0.4, 0.5)),
]
ROCK_BURY = 0.25


def icosphere(levels):
    """Unit icosphere: (points, triangles) with shared vertices, counter-clockwise seen from outside."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    pts = [normalize(p) for p in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                                  (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
            (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
            (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        mid, out = {}, []

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                pts.append(normalize(mul(add(pts[a], pts[b]), 0.5)))
                mid[key] = len(pts) - 1
            return mid[key]
        for a, b, c in tris:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = out
    return pts, tris


def rock_radius(d, cuts, bumps):
    """Distance from the centre to the rock's surface along unit direction d (unit-sphere space)."""
    r = 1.0
    for n, dist in cuts:  # a plane at distance dist along n caps the ray where it crosses the plane
        c = dot(d, n)
        if c > 1e-6:
            r = min(r, dist / c)
    for centre, amp, width in bumps:
        r += amp * math.exp((dot(d, centre) - 1.0) / width)
    return r


def random_unit(rng):
    while True:
        v = (2.0 * rng.random() - 1.0, 2.0 * rng.random() - 1.0, 2.0 * rng.random() - 1.0)
        if 0.01 < dot(v, v) <= 1.0:
            return normalize(v)


def rock_mesh(name, half, rng):
    cuts = [(random_unit(rng), 0.7 + 0.15 * rng.random()) for _ in range(11)]
    bumps = [(random_unit(rng), 0.06 * (2.0 * rng.random() - 1.0), 0.02 + 0.04 * rng.random())
             for _ in range(40)]
    dirs, tris = icosphere(ROCK_SUBDIV)
    pts = []
    for d in dirs:
        r = rock_radius(d, cuts, bumps)
        # The ellipsoid's centre sits at y = half_y - ROCK_BURY * 2 so the flattened base is buried.
        p = (half[0] * r * d[0], half[1] * r * d[1] + half[1] - 2.0 * ROCK_BURY, half[2] * r * d[2])
        pts.append(qp((p[0], max(p[1], -ROCK_BURY), p[2])))
    # The flat base is a hard edge: its faces get their own vertices facing down, and the sides' normals
    # average the side faces only.
    on_base = [p[1] == -ROCK_BURY for p in pts]
    side = [t for t in tris if not all(on_base[k] for k in t)]
    nrm = [(0.0, 0.0, 0.0)] * len(pts)
    for a, b, c in side:
        face = cross(sub(pts[b], pts[a]), sub(pts[c], pts[a]))  # length = 2 x area: area weighting
        for k in (a, b, c):
            nrm[k] = add(nrm[k], face)
    mesh = Mesh(name)
    prim = mesh.prim("rock_grey")

    def uv(p):
        return (p[0] + 0.5 * p[2], p[1] + 0.5 * p[2])
    ids = [prim.vert(p, n, uv(p)) for p, n in zip(pts, nrm)]
    base = {}
    for t in tris:
        if t in side:
            prim.tri(*[ids[k] for k in t])
            continue
        for k in t:
            if k not in base:
                base[k] = prim.vert(pts[k], (0.0, -1.0, 0.0), (pts[k][0], pts[k][2]))
        prim.tri(*[base[k] for k in t])
    return mesh


def build_rocks():
    rng = random.Random(ROCK_SEED)
    nodes = [(name, rock_mesh(name, half, rng), offset) for name, offset, half in ROCKS]
    return "rocks", nodes


# --------------------------------------------------------------------------------------------------------
# AUV: a 2 m torpedo-shaped survey vehicle (in the manner of a REMUS 100): a yellow cylinder of radius
# 0.16 m with an ellipsoidal nose, a black tail cone and four thin cruciform fins, axis along z.

AUV_HALF, AUV_R = 1.0, 0.16


def build_auv():
    body = Mesh("auv_body")
    nose = [(AUV_R * math.cos(0.5 * math.pi * k / 10), 0.7 + 0.3 * math.sin(0.5 * math.pi * k / 10))
            for k in range(11)]
    nose[-1] = (0.0, AUV_HALF)
    revolve(body, [("auv_black", [(0.0, -AUV_HALF), (0.04, -AUV_HALF)], None),
                   ("auv_black", [(0.04, -AUV_HALF), (AUV_R, -0.55)], None),
                   ("auv_yellow", [(AUV_R, -0.55), (AUV_R, 0.7)], None),
                   ("auv_yellow", nose, None)], 32, AUV_R, Xform.along((0.0, 0.0, 0.0), (0.0, 0.0, 1.0)))
    fins = Mesh("auv_fins")
    for k in range(4):  # a plate 0.12 m out from the tail cone, 0.2 m long, 1 cm thick
        a = 0.5 * math.pi * k
        out, side = (math.sin(a), math.cos(a), 0.0), (math.cos(a), -math.sin(a), 0.0)
        corners = []
        for c in range(8):
            r = 0.16 if c & 1 else 0.06
            z = -0.75 if c & 4 else -0.95
            t = -0.005 if c & 2 else 0.005  # (out, -side, z) is right-handed: outward faces
            corners.append(add(add(mul(out, r), mul(side, t)), (0.0, 0.0, z)))
        hexahedron(fins.prim("auv_black"), corners)
    return "auv", [("body", body, None), ("fins", fins, None)]


# --------------------------------------------------------------------------------------------------------
# Boat: a 5 m open motor boat. Lofted hard-chine hull (smooth topsides and bottom panels, hard edges at
# keel, chine, stem, sheer and transom), built as one closed shell: outer hull, transom, gunwale caps and
# foredeck, the cockpit's inner walls, floor, inner transom and bulkhead. Bow toward +z, port = +x.

L_HULL, SHELL, Y_FLOOR = 5.0, 0.05, 0.05
T_INNER, T_BULKHEAD = 0.01, 0.78  # cockpit from z = -2.45 (inner transom) to z = 1.4 (foredeck bulkhead)
STATIONS = [0.0] + linspace(T_INNER, T_BULKHEAD, 30) + linspace(T_BULKHEAD, 1.0, 12)[1:]
ROW_INNER, ROW_BULKHEAD = 1, 31


def hull_z(t):
    return -0.5 * L_HULL + L_HULL * t


def half_beam(t):  # at the gunwale
    if t <= 0.45:
        return 0.93 + 0.07 * math.sin(0.5 * math.pi * t / 0.45)
    return 0.0 if t >= 1.0 else math.cos(0.5 * math.pi * (t - 0.45) / 0.55)


def sheer_y(t):
    return 0.58 + 0.14 * t * t


def keel_y(t):
    return -0.35 if t <= 0.55 else -0.35 + 0.55 * ((t - 0.55) / 0.45) ** 2


def chine_y(t):
    return -0.15 if t <= 0.5 else -0.15 + 0.5 * ((t - 0.5) / 0.5) ** 2


def chine_x(t):
    return 0.84 * half_beam(t)


def topside(t, s):
    """Port topside, s = 0 at the chine to 1 at the gunwale; bulges 3.5 cm outward between them."""
    b, c = half_beam(t), chine_x(t)
    return (c + (b - c) * s + 0.035 * b * sinpi(s), lerp(chine_y(t), sheer_y(t), s), hull_z(t))


def bottom(t, s):
    """Port bottom panel, s = 0 at the keel to 1 at the chine; slightly convex."""
    return (chine_x(t) * s, lerp(keel_y(t), chine_y(t), s) - 0.012 * half_beam(t) * sinpi(s), hull_z(t))


def stripe_s(t):
    h = sheer_y(t) - chine_y(t)
    return 1.0 - 0.17 / h, 1.0 - 0.05 / h  # blue stripe from 17 cm to 5 cm below the gunwale


def topside_columns(t):
    lo, hi = stripe_s(t)
    return linspace(0.0, lo, 6) + linspace(lo, hi, 2)[1:] + [1.0]  # columns 0-6 white, 6-8 blue, 8-9 white


def floor_s(t):
    return (Y_FLOOR - chine_y(t)) / (sheer_y(t) - chine_y(t))


def liner(t, s):
    """Port cockpit wall: the topside moved SHELL inboard."""
    x, y, z = topside(t, s)
    return (x - SHELL, y, z)


def mirror(p):
    return (-p[0], p[1], p[2])


def deck_row(t, ref_t):
    """Points across the deck at station t, port (+x) to starboard: the two gunwale edges, the two inner
    gunwale edges and 7 points between, laid out as at station ref_t (where the cockpit opening is) and
    scaled with the beam, so rows toward the bow stay in order and the last collapses onto the stem."""
    X = topside(ref_t, 1.0)[0]
    xi = X - SHELL
    ref = [X] + [xi * (1.0 - k / 4.0) for k in range(9)] + [-X]
    if t == ref_t:
        xs = ref
    else:
        Xt = topside(t, 1.0)[0]
        xs = [Xt * (x / X) for x in ref]
    return [(x, sheer_y(t), hull_z(t)) for x in xs]


def build_boat():
    hull = Mesh("boat_hull")
    white, blue, deck = "boat_hull_white", "boat_stripe_blue", "boat_deck"
    T = STATIONS
    cockpit = T[ROW_INNER:ROW_BULKHEAD + 1]

    # Outer hull: port patches, then the starboard mirror images (flipped to keep them facing outward).
    PT = [[topside(t, s) for s in topside_columns(t)] for t in T]
    PB = [[bottom(t, s) for s in linspace(0.0, 1.0, 5)] for t in T]
    for P, flip in ((PT, False), ([[mirror(p) for p in row] for row in PT], True)):
        P = [[qp(p) for p in row] for row in P]
        N, UV = grid_normals(P, flip), grid_uv_arclength(P)
        emit_grid(hull.prim(white), P, N, UV, flip, (0, 6))
        emit_grid(hull.prim(blue), P, N, UV, flip, (6, 8))
        emit_grid(hull.prim(white), P, N, UV, flip, (8, 9))
    patch(hull.prim(white), PB, False)
    patch(hull.prim(white), [[mirror(p) for p in row] for row in PB], True)

    # Transom (outer face at z = -2.5), bounded by the hull section and the aft deck's first row.
    aft = [deck_row(t, T[ROW_INNER]) for t in T[:ROW_INNER + 1]]
    port_section = PB[0] + PT[0][1:]  # keel -> chine -> gunwale
    stbd_section = [mirror(p) for p in port_section]
    fan(hull.prim(white), list(reversed(port_section)) + stbd_section[1:] + list(reversed(aft[0][1:-1])),
        (0.0, 0.0, -1.0))

    # Deck: aft strip over the transom, gunwale caps beside the cockpit, foredeck to the stem.
    patch(hull.prim(white), aft, False)
    patch(hull.prim(white), [[topside(t, 1.0), liner(t, 1.0)] for t in cockpit], False)
    patch(hull.prim(white), [[mirror(liner(t, 1.0)), mirror(topside(t, 1.0))] for t in cockpit], False)
    fore = [deck_row(t, T[ROW_BULKHEAD]) for t in T[ROW_BULKHEAD:]]
    patch(hull.prim(deck), fore, False)

    # Cockpit: walls (facing inboard), floor, inner transom (facing +z) and bulkhead (facing -z).
    PL = [[liner(t, s) for s in linspace(floor_s(t), 1.0, 6)] for t in cockpit]
    patch(hull.prim(white), PL, True)
    patch(hull.prim(white), [[mirror(p) for p in row] for row in PL], False)
    PF = [[(x, Y_FLOOR, hull_z(t)) for x in linspace(PL[i][0][0], -PL[i][0][0], 8)]
          for i, t in enumerate(cockpit)]
    patch(hull.prim(deck), PF, False)
    for k, top_row, normal in ((0, aft[-1], (0.0, 0.0, 1.0)), (-1, fore[0], (0.0, 0.0, -1.0))):
        wall, floor = PL[k], PF[k]
        loop = list(reversed(wall)) + floor[1:-1] + [mirror(p) for p in wall] + list(reversed(top_row[2:-2]))
        fan(hull.prim(white), loop, normal)

    # Centre console with a tinted windscreen, and a bench seat behind it (local: origin on the floor).
    console = Mesh("boat_console")
    box(console.prim(white), (-0.3, 0.0, -0.25), (0.3, 0.9, 0.25))
    ws = []
    for k in range(8):
        x = 0.28 if k & 1 else -0.28
        y, z = (1.2, 0.08) if k & 2 else (0.9, 0.2)
        ws.append((x, y, z - (0.012 if k & 4 else 0.0)))
    hexahedron(console.prim("boat_windscreen"), ws)
    seat = Mesh("boat_seat")
    box(seat.prim(white), (-0.55, 0.0, -0.4), (0.55, 0.42, 0.0))

    # Outboard motor on the transom: clamp bracket, leg with cavitation plate, cowling.
    motor = Mesh("boat_outboard")
    m = motor.prim("boat_motor")
    box(m, (-0.1, 0.34, -2.62), (0.1, 0.66, -2.5))
    box(m, (-0.06, -0.5, -2.8), (0.06, 0.6, -2.62))
    box(m, (-0.16, -0.3, -2.9), (0.16, -0.28, -2.6))
    box(m, (-0.2, 0.6, -2.98), (0.2, 0.98, -2.55))

    nodes = [("hull", hull, None), ("console", console, [0.0, Y_FLOOR, 0.0]),
             ("seat", seat, [0.0, Y_FLOOR, -0.7]), ("outboard", motor, None)]
    return "boat", nodes


# --------------------------------------------------------------------------------------------------------
# Work boat (issue 17): the boat with its white hull painted in PBR textures that tile once per metre of
# TEXCOORD_0 (planks 0.25 m wide between 1 cm seams: a normal map, darker and occluded in the seams, the
# paint's roughness varying with grime), and a mooring rope from the bow down to the water: a flat strip
# whose texture's alpha is the twisted rope's outline (alpha MASK).

PAINT_SIZE = 128
PAINT_SEED = 4411
ROPE_W, ROPE_H = 64, 16
ROPE_TWIST_M = 0.2  # one repeat of the rope texture along the rope


def periodic_noise(rng, period, n):
    table = [[rng.random() for _ in range(period)] for _ in range(period)]

    def at(x, y):
        fx, fy = x * period / n, y * period / n
        ix, iy = int(fx), int(fy)
        tx, ty = fx - ix, fy - iy
        tx, ty = tx * tx * (3 - 2 * tx), ty * ty * (3 - 2 * ty)
        x0, x1, y0, y1 = ix % period, (ix + 1) % period, iy % period, (iy + 1) % period
        return lerp(lerp(table[y0][x0], table[y0][x1], tx), lerp(table[y1][x0], table[y1][x1], tx), ty)
    return at


def paint_textures():
    """Rows of the three hull textures (colour, normal, occlusion-roughness-metallic), PAINT_SIZE square."""
    n = PAINT_SIZE
    rng = random.Random(PAINT_SEED)
    grime, speck = periodic_noise(rng, 4, n), periodic_noise(rng, 32, n)
    plank = n // 4  # 0.25 m

    def seam(y):  # 1 in the middle of a seam, 0 outside; seams 1 cm (~1.3 px) wide, smooth over 4 px
        d = min((y % plank), plank - (y % plank)) / 2.0
        return max(0.0, math.cos(min(d, 2.0) * math.pi / 4.0)) ** 2 if d < 2.0 else 0.0

    colour, normal, orm = [], [], []
    for y in range(n):
        c_row, n_row, o_row = bytearray(), bytearray(), bytearray()
        # The seam's slope across v (finite difference of its depth, 1 mm deep per texel's 7.8 mm).
        slope = (seam(y + 1) - seam(y - 1)) * 0.5 * 0.4
        nv = normalize((0.0, slope, 1.0))
        for x in range(n):
            g = 0.7 * grime(x, y) + 0.3 * speck(x, y)
            shade = (1.0 - 0.12 * g) * (1.0 - 0.35 * seam(y))
            for k, base in enumerate((0.93, 0.93, 0.90)):
                c_row.append(int(round(255.0 * base * shade)))
            c_row.append(255)
            for k in range(3):
                n_row.append(int(round(255.0 * (0.5 + 0.5 * nv[k]))))
            n_row.append(255)
            o_row += bytes((int(round(255.0 * (1.0 - 0.6 * seam(y)))), int(round(255.0 * (0.25 + 0.45 * g))), 0,
                            255))
        colour.append(bytes(c_row))
        normal.append(bytes(n_row))
        orm.append(bytes(o_row))
    return colour, normal, orm


def rope_texture():
    """Rows of the rope texture: u along the rope (one twist of three strands), v across; alpha 0 outside
    the strands' outline."""
    rows = []
    for y in range(ROPE_H):
        v = (y + 0.5) / ROPE_H
        row = bytearray()
        for x in range(ROPE_W):
            u = (x + 0.5) / ROPE_W
            phase = (3.0 * u + 1.5 * v) % 1.0  # three strands, laid at an angle
            bulge = 0.5 + 0.5 * math.cos(2.0 * math.pi * phase)
            half = 0.32 + 0.12 * abs(math.cos(math.pi * 3.0 * u))  # the outline swells over each strand
            inside = abs(v - 0.5) < half
            shade = 0.55 + 0.45 * bulge
            row += bytes((int(round(205 * shade)), int(round(170 * shade)), int(round(110 * shade)),
                          255 if inside else 0))
        rows.append(bytes(row))
    return rows


def strip(prim, a, b, width, thickness, u_per_m):
    """A closed flat strip from a to b, `width` across (horizontal) and `thickness` thick; its two broad
    faces carry the texture (u along, v across), the narrow ones the texture's middle row."""
    xf = Xform.along(a, b)
    length_m = length(sub(b, a))
    w, t = width / 2.0, thickness / 2.0
    corners = {}
    for i in (0, 1):
        for j in (0, 1):
            for k in (0, 1):
                corners[(i, j, k)] = qp(xf.point(((2 * k - 1) * t, i * length_m, (2 * j - 1) * w)))
    faces = (((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)), ((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)),
             ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)), ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),
             ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)), ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)))
    centre = xf.point((0.0, length_m / 2.0, 0.0))
    for f in faces:
        quad = [corners[c] for c in f]
        n = normalize(cross(sub(quad[2], quad[0]), sub(quad[3], quad[1])))
        fc = mul(add(add(quad[0], quad[1]), add(quad[2], quad[3])), 0.25)
        if dot(n, sub(fc, centre)) < 0:
            quad.reverse()
            f = tuple(reversed(f))
            n = mul(n, -1.0)
        broad = f[0][2] == f[1][2] == f[2][2] == f[3][2]
        ids = [prim.vert(p, n, (c[0] * length_m * u_per_m, c[1] if broad else 0.5)) for p, c in zip(quad, f)]
        prim.tri(ids[0], ids[1], ids[2])
        prim.tri(ids[0], ids[2], ids[3])


def build_workboat():
    _, nodes = build_boat()
    hull = nodes[0][1]
    hull.name = "workboat_hull"
    paint = hull.prims.pop("boat_hull_white")
    paint.material = "workboat_paint"
    hull.prims = {"workboat_paint": paint, **hull.prims}
    rope = Mesh("workboat_rope")
    strip(rope.prim("workboat_rope"), (0.0, 0.62, 2.45), (0.0, -0.05, 4.6), 0.05, 0.012, 1.0 / ROPE_TWIST_M)
    return "workboat", nodes + [("mooring_rope", rope, None)]


# --------------------------------------------------------------------------------------------------------
# glTF writer: one .gltf (JSON) + one .bin; one bufferView per accessor, 4-byte aligned.

FLOAT, USHORT, UINT = 5126, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


def json_f32(x):
    """Shortest decimal that reads back as the same float32 (so min/max equal the stored data exactly)."""
    v = f32(x)
    for digits in range(1, 10):
        s = float("%.*g" % (digits, v))
        if f32(s) == v:
            return s + 0.0
    return v


def write_gltf(name, root_name, nodes):
    blob = bytearray()
    doc = {"asset": {"version": "2.0", "generator": GENERATOR},
           "scene": 0,
           "scenes": [{"name": root_name, "nodes": [0]}],
           "nodes": [{"name": root_name, "children": list(range(1, len(nodes) + 1))}],
           "meshes": [], "materials": [], "accessors": [], "bufferViews": []}
    materials = []

    def view(data, target):
        while len(blob) % 4:
            blob.append(0)
        doc["bufferViews"].append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                                   "target": target})
        blob.extend(data)
        return len(doc["bufferViews"]) - 1

    def accessor(values, ctype, atype, target, minmax=False):
        flat = [c for v in values for c in v] if atype != "SCALAR" else values
        fmt = {FLOAT: "f", USHORT: "H", UINT: "I"}[ctype]
        acc = {"bufferView": view(struct.pack("<%d%s" % (len(flat), fmt), *flat), target),
               "componentType": ctype, "count": len(values), "type": atype}
        if minmax:
            acc["min"] = [json_f32(min(v[k] for v in values)) for k in range(3)]
            acc["max"] = [json_f32(max(v[k] for v in values)) for k in range(3)]
        doc["accessors"].append(acc)
        return len(doc["accessors"]) - 1

    for node_name, mesh, translation in nodes:
        prims = []
        for prim in mesh.prims.values():
            prim.compact()
            if prim.material not in materials:
                materials.append(prim.material)
            attrs = {"POSITION": accessor(prim.pos, FLOAT, "VEC3", ARRAY_BUFFER, True),
                     "NORMAL": accessor(prim.nrm, FLOAT, "VEC3", ARRAY_BUFFER),
                     "TEXCOORD_0": accessor(prim.uv, FLOAT, "VEC2", ARRAY_BUFFER)}
            itype = USHORT if len(prim.pos) < 65536 else UINT
            prims.append({"attributes": attrs,
                          "indices": accessor(prim.idx, itype, "SCALAR", ELEMENT_ARRAY_BUFFER),
                          "material": materials.index(prim.material), "mode": 4})
        doc["meshes"].append({"name": mesh.name, "primitives": prims})
        node = {"name": node_name, "mesh": len(doc["meshes"]) - 1}
        if translation:
            node["translation"] = translation
        doc["nodes"].append(node)
    while len(blob) % 4:
        blob.append(0)
    images = []

    def texture_index(png):
        if png not in images:
            images.append(png)
        return images.index(png)

    doc["materials"] = [material_json(m, texture_index) for m in materials]
    if images:  # one texture per image, all with the default sampler (repeat, trilinear)
        doc["images"] = [{"uri": png} for png in images]
        doc["samplers"] = [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}]
        doc["textures"] = [{"sampler": 0, "source": k} for k in range(len(images))]
    doc["buffers"] = [{"uri": name + ".bin", "byteLength": len(blob)}]
    text = json.dumps(doc, indent=1) + "\n"
    return {name + ".gltf": text.encode("ascii"), name + ".bin": bytes(blob)}


# --------------------------------------------------------------------------------------------------------
# Sand texture: pale beige, fine grain, faint wind ripples; every term is periodic over 256 px so the
# texture tiles seamlessly.

SAND_SIZE = 256
SAND_SEED = 7031


def sand_pixels():
    n = SAND_SIZE
    rng = random.Random(SAND_SEED)

    def lattice(period):
        return [[rng.random() for _ in range(period)] for _ in range(period)]

    def value_noise(table, x, y):
        period = len(table)
        fx, fy = x * period / n, y * period / n
        ix, iy = int(fx), int(fy)
        tx, ty = fx - ix, fy - iy
        tx, ty = tx * tx * (3 - 2 * tx), ty * ty * (3 - 2 * ty)
        x0, x1, y0, y1 = ix % period, (ix + 1) % period, iy % period, (iy + 1) % period
        a = lerp(table[y0][x0], table[y0][x1], tx)
        b = lerp(table[y1][x0], table[y1][x1], tx)
        return lerp(a, b, ty)

    broad, mid, fine, finer = lattice(4), lattice(16), lattice(64), lattice(128)
    warp, amp = lattice(4), lattice(8)
    white = [rng.random() for _ in range(n * n)]
    grains = [rng.random() for _ in range(n * n)]
    base = (0.87, 0.80, 0.655)  # sRGB 0-1
    rows = []
    for y in range(n):
        row = bytearray()
        for x in range(n):
            i = y * n + x
            nb, nm = value_noise(broad, x, y), value_noise(mid, x, y)
            # Ripples: integer wave numbers (3, 10) per tile so they wrap; the phase is bent by smooth noise.
            phase = (2.0 * math.pi * (3 * x + 10 * y) / n
                     + 0.7 * math.pi * 2.2 * (value_noise(warp, x, y) - 0.5))
            ripple = math.sin(phase) + 0.3 * math.sin(2.0 * phase - 0.5)
            lum = (1.0 + 0.05 * (nb - 0.5) + 0.05 * (nm - 0.5) + 0.06 * (value_noise(fine, x, y) - 0.5)
                   + 0.05 * (value_noise(finer, x, y) - 0.5) + 0.09 * (white[i] - 0.5)
                   + (0.012 + 0.028 * value_noise(amp, x, y)) * ripple)
            tint = (1.0 + 0.03 * (nm - 0.5), 1.0, 1.0 - 0.04 * (nm - 0.5))
            g = grains[i]
            grain = (0.74, 0.70, 0.64) if g < 0.025 else (1.08, 1.08, 1.1) if g > 0.988 else (1.0, 1.0, 1.0)
            for k in range(3):
                row.append(max(0, min(255, int(round(255.0 * base[k] * lum * tint[k] * grain[k])))))
            row.append(255)
        rows.append(bytes(row))
    return rows


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def png_filter(kind, row, prev, bpp):
    out = bytearray(len(row))
    for i in range(len(row)):
        a = row[i - bpp] if i >= bpp else 0
        b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
        pred = (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]
        out[i] = (row[i] - pred) & 0xFF
    return bytes(out)


def png_unfilter(kind, data, prev, bpp):
    out = bytearray(len(data))
    for i in range(len(data)):
        a = out[i - bpp] if i >= bpp else 0
        b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
        pred = (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]
        out[i] = (data[i] + pred) & 0xFF
    return bytes(out)


def png_chunk(kind, data):
    crc = zlib.crc32(kind + data) & 0xFFFFFFFF
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc)


def encode_png(rows, width, height):
    """RGBA8 PNG; per row the filter with the smallest sum of absolute signed bytes (the usual heuristic)."""
    raw, prev = bytearray(), bytes(width * 4)
    for row in rows:
        def cost(k):
            return sum(v if v < 128 else 256 - v for v in png_filter(k, row, prev, 4)), k
        best = min(range(5), key=cost)
        raw.append(best)
        raw.extend(png_filter(best, row, prev, 4))
        prev = row
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", zlib.compress(bytes(raw), 9))
            + png_chunk(b"IEND", b""))


def decode_png(data):
    """Returns (width, height, rows) of an 8-bit RGBA PNG, checking the signature and every chunk CRC."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("bad PNG signature")
    pos, idat, ihdr = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack_from(">I", data, pos)
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        (crc,) = struct.unpack_from(">I", data, pos + 8 + n)
        if crc != zlib.crc32(kind + body) & 0xFFFFFFFF:
            raise ValueError("bad CRC in chunk %r" % kind)
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
        pos += 12 + n
    if not ihdr or ihdr[2:] != (8, 6, 0, 0, 0):
        raise ValueError("not an 8-bit RGBA non-interlaced PNG: IHDR %r" % (ihdr,))
    w, h = ihdr[0], ihdr[1]
    raw, rows, prev = zlib.decompress(idat), [], bytes(w * 4)
    stride = w * 4 + 1
    if len(raw) != stride * h:
        raise ValueError("image data has %d bytes, expected %d" % (len(raw), stride * h))
    for y in range(h):
        prev = png_unfilter(raw[y * stride], raw[y * stride + 1:(y + 1) * stride], prev, 4)
        rows.append(prev)
    return w, h, rows


# --------------------------------------------------------------------------------------------------------
# Checks (run on every generation, and on the committed files with --check)

COMPONENT = {5120: ("b", 1), 5121: ("B", 1), 5122: ("h", 2), 5123: ("H", 2), 5125: ("I", 4), 5126: ("f", 4)}
TYPE_SIZE = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


class CheckError(Exception):
    pass


def read_accessor(doc, blob, index):
    acc = doc["accessors"][index]
    bv = doc["bufferViews"][acc["bufferView"]]
    fmt, size = COMPONENT[acc["componentType"]]
    ncomp = TYPE_SIZE[acc["type"]]
    start = bv.get("byteOffset", 0) + acc.get("byteOffset", 0)
    nbytes = acc["count"] * ncomp * size
    where = "accessors[%d]" % index
    if bv.get("byteOffset", 0) + bv["byteLength"] > len(blob):
        raise CheckError("%s: bufferView ends past the buffer" % where)
    if acc.get("byteOffset", 0) + nbytes > bv["byteLength"]:
        raise CheckError("%s: data ends past its bufferView" % where)
    if start % size or "byteStride" in bv:
        raise CheckError("%s: misaligned or strided" % where)
    flat = struct.unpack_from("<%d%s" % (acc["count"] * ncomp, fmt), blob, start)
    return acc, (list(flat) if ncomp == 1 else [tuple(flat[k:k + ncomp]) for k in range(0, len(flat), ncomp)])


def check_gltf(name, files, expect):
    """Validates name.gltf + its .bin from files (a dict name -> bytes); returns a stats dict."""
    doc = json.loads(files[name + ".gltf"].decode("ascii"))
    if doc["asset"]["version"] != "2.0":
        raise CheckError("asset.version is not 2.0")
    (buf,) = doc["buffers"]
    uri = buf["uri"]
    if "/" in uri or "\\" in uri or ":" in uri or uri != name + ".bin":
        raise CheckError("buffer uri %r is not the plain relative name %s.bin" % (uri, name))
    blob = files[uri]
    if len(blob) != buf["byteLength"]:
        raise CheckError("%s is %d bytes, buffers[0].byteLength says %d"
                         % (uri, len(blob), buf["byteLength"]))
    for m in doc["materials"]:
        if len(m["pbrMetallicRoughness"]["baseColorFactor"]) != 4:
            raise CheckError("material %s has no baseColorFactor" % m["name"])
    (root,) = doc["scenes"][doc["scene"]]["nodes"]
    if not doc["nodes"][root].get("children"):
        raise CheckError("the root node has no children")
    # World placement (this generator uses translations only).
    place, stack = {}, [(root, (0.0, 0.0, 0.0))]
    while stack:
        k, offset = stack.pop()
        node = doc["nodes"][k]
        if "rotation" in node or "scale" in node or "matrix" in node:
            raise CheckError("node %s: only translations are expected" % node["name"])
        offset = add(offset, tuple(node.get("translation", (0.0, 0.0, 0.0))))
        if "mesh" in node:
            place[node["mesh"]] = (node["name"], offset)
        stack += [(c, offset) for c in node.get("children", [])]
    stats = {"meshes": [], "triangles": 0, "vertices": 0,
             "lo": [math.inf] * 3, "hi": [-math.inf] * 3, "materials": [m["name"] for m in doc["materials"]]}
    for mi, mesh in enumerate(doc["meshes"]):
        node_name, offset = place[mi]
        edges, volume, tris, lo, hi = {}, 0.0, 0, [math.inf] * 3, [-math.inf] * 3
        for pi, prim in enumerate(mesh["primitives"]):
            where = "%s primitive %d" % (mesh["name"], pi)
            itype = doc["accessors"][prim["indices"]]["componentType"]
            if prim.get("mode", 4) != 4 or itype not in (USHORT, UINT):
                raise CheckError("%s: not indexed triangles with 16/32-bit indices" % where)
            pacc, pos = read_accessor(doc, blob, prim["attributes"]["POSITION"])
            _, nrm = read_accessor(doc, blob, prim["attributes"]["NORMAL"])
            _, uv = read_accessor(doc, blob, prim["attributes"]["TEXCOORD_0"])
            _, idx = read_accessor(doc, blob, prim["indices"])
            if not (len(pos) == len(nrm) == len(uv)) or len(idx) % 3:
                raise CheckError("%s: attribute counts differ or index count is not a multiple of 3" % where)
            for k in range(3):
                if (f32(pacc["min"][k]) != min(p[k] for p in pos)
                        or f32(pacc["max"][k]) != max(p[k] for p in pos)):
                    raise CheckError("%s: POSITION min/max do not match the data" % where)
                lo[k], hi[k] = min(lo[k], pacc["min"][k]), max(hi[k], pacc["max"][k])
            if any(i >= len(pos) for i in idx):
                raise CheckError("%s: index out of range" % where)
            if set(idx) != set(range(len(pos))):
                raise CheckError("%s: unused vertices" % where)
            worst = max(abs(length(n) - 1.0) for n in nrm)
            if worst > 1e-5:
                raise CheckError("%s: normal length off by %g" % (where, worst))
            for t in range(0, len(idx), 3):
                a, b, c = idx[t], idx[t + 1], idx[t + 2]
                face = cross(sub(pos[b], pos[a]), sub(pos[c], pos[a]))
                if length(face) < 1e-12:
                    raise CheckError("%s: degenerate triangle %d" % (where, t // 3))
                if dot(face, add(add(nrm[a], nrm[b]), nrm[c])) <= 0.0:
                    raise CheckError("%s: triangle %d winds against its normals" % (where, t // 3))
                if min(dot(normalize(face), nrm[v]) for v in (a, b, c)) < 0.2:
                    raise CheckError("%s: triangle %d is far from its vertex normals" % (where, t // 3))
                volume += dot(pos[a], cross(pos[b], pos[c])) / 6.0
                for e in ((pos[a], pos[b]), (pos[b], pos[c]), (pos[c], pos[a])):
                    edges[e] = edges.get(e, 0) + 1
            tris += len(idx) // 3
        # Closed and consistently wound: every directed edge once, and its reverse once.
        bad = sum(1 for e, n in edges.items() if n != 1 or edges.get((e[1], e[0])) != 1)
        if bad:
            raise CheckError("%s: %d edges are open or not shared by exactly two oppositely wound triangles"
                             % (mesh["name"], bad))
        if volume <= 0.0:
            raise CheckError("%s: signed volume %g <= 0 (normals point inward)" % (mesh["name"], volume))
        wlo, whi = add(tuple(lo), offset), add(tuple(hi), offset)
        for k in range(3):
            stats["lo"][k], stats["hi"][k] = min(stats["lo"][k], wlo[k]), max(stats["hi"][k], whi[k])
        names = [doc["materials"][p["material"]]["name"] for p in mesh["primitives"]]
        stats["meshes"].append({"node": node_name, "mesh": mesh["name"], "triangles": tris, "volume": volume,
                                "lo": wlo, "hi": whi, "materials": names})
        stats["triangles"] += tris
        stats["vertices"] += sum(doc["accessors"][p["attributes"]["POSITION"]]["count"]
                                 for p in mesh["primitives"])
    stats["bin_bytes"] = len(blob)
    expect(stats)
    return stats


def near(a, b, tol):
    return abs(a - b) <= tol


def expect_buoy(s):
    m = {x["node"]: x for x in s["meshes"]}
    flt = m["float"]
    conds = [(1000 <= s["triangles"] <= 3000, "1k-3k triangles"),
             (near(flt["lo"][1], -0.8, 1e-6) and near(flt["hi"][1], 0.4, 1e-6), "float from y = -0.8 to 0.4"),
             (near(flt["hi"][0], 0.6, 1e-6) and near(flt["hi"][2], 0.6, 1e-6), "float radius 0.6"),
             (near(flt["volume"], math.pi * 0.36 * 1.2, 0.03), "float volume ~ pi r^2 h"),
             (near(m["mast"]["hi"][1], 1.8, 1e-6), "mast to y = 1.8"),
             (near(s["hi"][1], 2.2, 1e-6), "top mark to y = 2.2"),
             (s["bin_bytes"] < 300000, ".bin under 300 KB")]
    for ok, what in conds:
        if not ok:
            raise CheckError("buoy: expected " + what)


def expect_boat(s):
    hull = [x for x in s["meshes"] if x["node"] == "hull"][0]
    conds = [(2000 <= s["triangles"] <= 6000, "2k-6k triangles"),
             (near(hull["lo"][2], -2.5, 1e-6) and near(hull["hi"][2], 2.5, 1e-6),
              "hull from z = -2.5 to 2.5"),
             (near(hull["hi"][0], 1.0, 0.01) and near(hull["lo"][0], -1.0, 0.01), "beam 2 m"),
             (near(hull["lo"][1], -0.35, 0.01), "hull bottom at y = -0.35"),
             (near(s["hi"][2], 2.5, 1e-6), "the bow (+z) is the front-most point"),
             (s["bin_bytes"] < 300000, ".bin under 300 KB")]
    for ok, what in conds:
        if not ok:
            raise CheckError("boat: expected " + what)


def expect_rocks(s):
    m = {x["node"]: x for x in s["meshes"]}
    conds = [(2000 <= s["triangles"] <= 6000, "2k-6k triangles"),
             (all(near(x["lo"][1], -ROCK_BURY, 1e-6) for x in s["meshes"]), "every base flat at y = -0.25"),
             (1.0 <= m["rock_large"]["hi"][1] <= 1.8, "the large rock 1.0-1.8 m above the sand"),
             (m["rock_small"]["hi"][1] < m["rock_medium"]["hi"][1] < m["rock_large"]["hi"][1],
              "three sizes"),
             (all(x["volume"] > 0.1 for x in s["meshes"]), "solid rocks"),
             (s["bin_bytes"] < 300000, ".bin under 300 KB")]
    for ok, what in conds:
        if not ok:
            raise CheckError("rocks: expected " + what)


def expect_auv(s):
    m = {x["node"]: x for x in s["meshes"]}
    body = m["body"]
    conds = [(500 <= s["triangles"] <= 4000, "0.5k-4k triangles"),
             (near(body["lo"][2], -1.0, 1e-6) and near(body["hi"][2], 1.0, 1e-6), "body from z = -1 to 1"),
             (near(body["hi"][0], AUV_R, 1e-3) and near(body["lo"][1], -AUV_R, 1e-3), "radius 0.16"),
             (near(body["volume"], math.pi * AUV_R ** 2 * 1.6, 0.03), "body volume ~ a 1.6 m cylinder"),
             (s["bin_bytes"] < 300000, ".bin under 300 KB")]
    for ok, what in conds:
        if not ok:
            raise CheckError("auv: expected " + what)


def check_png(files, fresh_rows):
    w, h, rows = decode_png(files["sand.png"])
    if (w, h) != (SAND_SIZE, SAND_SIZE):
        raise CheckError("sand.png is %dx%d" % (w, h))
    if rows != fresh_rows:
        raise CheckError("sand.png pixels differ from a fresh generation")

    def diff(p, q):
        return sum(abs(p[k] - q[k]) for k in range(3))

    px = [[row[4 * x:4 * x + 4] for x in range(w)] for row in rows]
    inner_x = sum(diff(px[y][x], px[y][x + 1]) for y in range(h) for x in range(w - 1)) / (h * (w - 1))
    seam_x = sum(diff(px[y][w - 1], px[y][0]) for y in range(h)) / h
    inner_y = sum(diff(px[y][x], px[y + 1][x]) for y in range(h - 1) for x in range(w)) / ((h - 1) * w)
    seam_y = sum(diff(px[h - 1][x], px[0][x]) for x in range(w)) / w
    if seam_x > 1.25 * inner_x or seam_y > 1.25 * inner_y:
        raise CheckError("sand.png does not tile: seam steps %.1f/%.1f vs %.1f/%.1f inside"
                         % (seam_x, seam_y, inner_x, inner_y))
    mean = [sum(r[4 * x + k] for r in rows for x in range(w)) / (w * h) for k in range(4)]
    return {"mean": mean, "seam": (seam_x, seam_y), "inner": (inner_x, inner_y)}


# --------------------------------------------------------------------------------------------------------
# README


def fmt_box(lo, hi):
    return "x %.2f..%.2f, y %.2f..%.2f, z %.2f..%.2f" % (lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])


def readme(files, buoy, boat, rocks, auv):
    def table(s):
        lines = ["| node | mesh | triangles | bounds (m, model space) | materials (primitive order) |",
                 "|---|---|---|---|---|"]
        for m in s["meshes"]:
            lines.append("| `%s` | `%s` | %d | %s | %s |" % (m["node"], m["mesh"], m["triangles"],
                                                              fmt_box(m["lo"], m["hi"]),
                                                      ", ".join("`%s`" % x for x in m["materials"])))
        return "\n".join(lines)

    def mats(s):
        out = []
        for name in s["materials"]:
            rgb, rough = MATERIALS[name]
            out.append("- `%s`: sRGB (%d, %d, %d), roughness %.2f, metallic 0" % ((name,) + rgb + (rough,)))
        return "\n".join(out)

    return """# Scene assets

Generated by `tools/gen_assets.py`; do not edit these files by hand. To regenerate, run from the
repository root:

```
python3 tools/gen_assets.py          # rewrites every file in this folder
python3 tools/gen_assets.py --check  # exit 1 unless the files equal a fresh generation and pass the checks
```

Python 3 (standard library only) is needed only to regenerate or check the assets, not to build or run
Lagoon: the generated files are committed. The output is byte-identical on every run.

## Conventions (all assets)

- glTF 2.0: a `.gltf` JSON file with its binary buffer in the `.bin` file next to it (relative URI). Load the
  `.gltf`; keep the pair together.
- Right-handed, **+y up, metres**, counter-clockwise front faces, every mesh a closed surface with normals
  pointing outward. Normals are smooth across smooth surfaces and split along hard edges.
- **The waterline is y = 0** and the origin is on the waterline: place a model with its node translation
  at the water height (e.g. the wave height at the object's position) and it floats at its design
  draught.
- Vertices: POSITION, NORMAL, TEXCOORD_0; 16-bit indices. **TEXCOORD_0 is in metres** (1 UV unit = 1 m
  along the surface), so a tiling texture can be applied at any scale. No textures are referenced.
- Each file has one scene with one root node (the model's name) whose children carry the meshes; children
  only have translations. `baseColorFactor` is linear (glTF's rule); the sRGB paint colours are listed below.

## buoy.gltf / buoy.bin

A navigation buoy reaching %(buoy_top).1f m above the waterline, %(buoy_h).1f m overall
(buoy.gltf %(buoy_gltf)d bytes, buoy.bin %(buoy_bin)d bytes). Axis of symmetry = the y axis through the
origin; **the waterline is y = 0**: the red can float (radius 0.6 m, y = -0.8 to 0.4, chamfered rims; a
vertex ring at y = 0) floats with 0.8 m submerged. On it stands a cage of
four red legs and a mast (radius 0.11 m, to y = 1.8) in white/red/white/red bands from the bottom, topped
by a red sphere top mark (radius 0.22 m, to y = 2.2). %(buoy_tris)d triangles, %(buoy_verts)d vertices.
Bounds: %(buoy_box)s.

%(buoy_table)s

Materials:
%(buoy_mats)s

## boat.gltf / boat.bin

A small open motor boat, 5 m long and 2 m wide (boat.gltf %(boat_gltf)d bytes, boat.bin %(boat_bin)d
bytes). **Bow toward +z**, stern (transom) at z = -2.5, bow stem at z = +2.5; port side = +x, starboard =
-x; centreline x = 0. **The waterline is y = 0**: hull bottom (keel) at y = -0.35, gunwale (sheer) at
y = 0.58 aft rising to 0.72 at the bow (0.61 amidships). The origin is on the waterline amidships; in a
scene (+z = north) the unrotated boat heads north.

- Hull: lofted hard-chine V hull, one closed shell: smooth topsides and bottom panels, hard edges at the
  keel, chine, stem, gunwale and transom; a blue stripe from 17 to 5 cm below the gunwale (separate
  primitive, same smooth normals). Open cockpit from z = -2.45 to 1.4 with 5 cm thick sides, a floor at
  y = 0.05 (`boat_deck`), and a foredeck from z = 1.4 to the bow (`boat_deck`).
- Console: centre console amidships (z = -0.25 to 0.25, top at y = 0.95) with a tinted windscreen to
  y = 1.25; a bench seat behind it (z = -1.1 to -0.7).
- Outboard: a simple outboard motor hung on the transom, reaching aft to z = -2.98 and down to
  y = -0.5 (below the hull bottom, as a propeller leg does). Drop the `outboard` node for a hull-only boat.

%(boat_tris)d triangles, %(boat_verts)d vertices. Bounds: %(boat_box)s.

%(boat_table)s

Materials:
%(boat_mats)s

## rocks.gltf / rocks.bin

Three boulders for a sandy sea floor, as one cluster (rocks.gltf %(rocks_gltf)d bytes, rocks.bin
%(rocks_bin)d bytes). **y = 0 is the sand**: place the root node on the floor (e.g. at y = -10 for a floor
10 m down). Each rock is a closed, smooth shell whose flat base lies 0.25 m below y = 0, so it looks
bedded in the sand rather than resting on it. The shapes are icospheres stretched to ellipsoids, cut by a
few random planes (the broken faces of stone) and roughened by smooth random bumps, from a fixed seed.
The largest rock (at the origin) reaches %(rock_top).2f m above the sand. %(rocks_tris)d triangles,
%(rocks_verts)d vertices. Bounds: %(rocks_box)s.

%(rocks_table)s

Materials:
%(rocks_mats)s

## auv.gltf / auv.bin

A 2 m torpedo-shaped autonomous underwater vehicle in the manner of a REMUS 100 (auv.gltf %(auv_gltf)d
bytes, auv.bin %(auv_bin)d bytes). **Axis along z, bow toward +z**; the origin is on the axis at the middle
of its length (not a waterline: it runs submerged, e.g. as `vehicles[].depth_m`). A yellow cylinder of
radius 0.16 m from z = -0.55 to 0.7 with an ellipsoidal nose to z = 1.0, a black tail cone to z = -1.0 and
four black cruciform fins (1 cm plates, 0.2 m long) on the cone. %(auv_tris)d triangles, %(auv_verts)d
vertices. Bounds: %(auv_box)s.

%(auv_table)s

Materials:
%(auv_mats)s

## sand.png

A 256 x 256 RGBA8 sand texture (alpha 255 everywhere) that tiles seamlessly in both directions: pale
beige with fine grain noise, scattered darker and lighter grains, broad mottling and faint wind ripples
(about 24 px apart). The pixel values are sRGB: sample through an `_SRGB` format. Suggested scale: one
tile per 2 to 4 m of sea floor or beach.
""" % {
        "buoy_h": buoy["hi"][1] - buoy["lo"][1], "buoy_top": buoy["hi"][1],
        "buoy_gltf": len(files["buoy.gltf"]), "buoy_bin": len(files["buoy.bin"]),
        "buoy_tris": buoy["triangles"], "buoy_verts": buoy["vertices"],
        "buoy_box": fmt_box(buoy["lo"], buoy["hi"]),
        "buoy_table": table(buoy), "buoy_mats": mats(buoy),
        "boat_gltf": len(files["boat.gltf"]), "boat_bin": len(files["boat.bin"]),
        "boat_tris": boat["triangles"], "boat_verts": boat["vertices"],
        "boat_box": fmt_box(boat["lo"], boat["hi"]),
        "boat_table": table(boat), "boat_mats": mats(boat),
        "rocks_gltf": len(files["rocks.gltf"]), "rocks_bin": len(files["rocks.bin"]),
        "rock_top": [m for m in rocks["meshes"] if m["node"] == "rock_large"][0]["hi"][1],
        "rocks_tris": rocks["triangles"], "rocks_verts": rocks["vertices"],
        "rocks_box": fmt_box(rocks["lo"], rocks["hi"]),
        "rocks_table": table(rocks), "rocks_mats": mats(rocks),
        "auv_gltf": len(files["auv.gltf"]), "auv_bin": len(files["auv.bin"]),
        "auv_tris": auv["triangles"], "auv_verts": auv["vertices"], "auv_box": fmt_box(auv["lo"], auv["hi"]),
        "auv_table": table(auv), "auv_mats": mats(auv)}


# --------------------------------------------------------------------------------------------------------


def texture_rows():
    """Every texture but the sand: file name -> (rows, width, height)."""
    colour, normal, orm = paint_textures()
    return {"workboat_paint.png": (colour, PAINT_SIZE, PAINT_SIZE),
            "workboat_normal.png": (normal, PAINT_SIZE, PAINT_SIZE),
            "workboat_orm.png": (orm, PAINT_SIZE, PAINT_SIZE),
            "workboat_rope.png": (rope_texture(), ROPE_W, ROPE_H)}


def expect_workboat(s):
    rope = [x for x in s["meshes"] if x["node"] == "mooring_rope"]
    hull = [x for x in s["meshes"] if x["node"] == "hull"][0]
    conds = [(len(rope) == 1 and rope[0]["materials"] == ["workboat_rope"], "a mooring rope of workboat_rope"),
             (hull["materials"][0] == "workboat_paint", "the hull painted with workboat_paint"),
             (near(s["hi"][2], 4.6, 0.01), "the rope reaching 2.1 m ahead of the bow")]
    for ok, what in conds:
        if not ok:
            raise CheckError("workboat: expected " + what)


def check_textures(files, fresh):
    """The PNGs decode to the fresh pixels (another zlib may compress them differently)."""
    for name, (rows, w, h) in fresh.items():
        dw, dh, drows = decode_png(files[name])
        if (dw, dh) != (w, h) or drows != rows:
            raise CheckError("%s pixels differ from a fresh generation" % name)


def workboat_readme(files, s):
    return """
## `workboat.gltf` + `workboat.bin`: the boat in PBR materials (issue 17)

The motor boat above, its white hull painted with textures that tile once per metre of `TEXCOORD_0`, and
a mooring rope from the bow down to the water, ahead of the bow. %(tris)d triangles, %(verts)d vertices;
bounds %(box)s.

- `workboat_paint`: base colour `workboat_paint.png` (sRGB white paint, grime, darker plank seams every
  0.25 m), normal map `workboat_normal.png` (the seams' grooves), `workboat_orm.png` as occlusion (R) and
  metallic-roughness (G roughness 0.25-0.70 with the grime, B metallic 0); %(paint)d × %(paint)d texels each.
- `workboat_rope`: base colour `workboat_rope.png` (%(rw)d × %(rh)d, three twisted strands per %(twist).2f m), alpha
  MASK at 0.5 cutting out everything outside the strands' outline, double-sided. The rope is a flat strip
  5 cm wide: from the side it shows its cut-out outline, not a rectangle.

%(table)s
""" % {"tris": s["triangles"], "verts": s["vertices"], "box": fmt_box(s["lo"], s["hi"]), "paint": PAINT_SIZE,
       "rw": ROPE_W, "rh": ROPE_H, "twist": ROPE_TWIST_M,
       "table": "\n".join(["| node | mesh | triangles | materials |", "|---|---|---|---|"]
                           + ["| `%s` | `%s` | %d | %s |" % (m["node"], m["mesh"], m["triangles"],
                                                            ", ".join("`%s`" % x for x in m["materials"]))
                              for m in s["meshes"]])}


def generate():
    files = {}
    for build in (build_buoy, build_boat, build_rocks, build_auv, build_workboat):
        root_name, nodes = build()
        files.update(write_gltf(root_name, root_name, nodes))
    rows = sand_pixels()
    files["sand.png"] = encode_png(rows, SAND_SIZE, SAND_SIZE)
    for name, (trows, w, h) in texture_rows().items():
        files[name] = encode_png(trows, w, h)
    buoy = check_gltf("buoy", files, expect_buoy)
    boat = check_gltf("boat", files, expect_boat)
    rocks = check_gltf("rocks", files, expect_rocks)
    auv = check_gltf("auv", files, expect_auv)
    workboat = check_gltf("workboat", files, expect_workboat)
    files["README.md"] = (readme(files, buoy, boat, rocks, auv) + workboat_readme(files, workboat)).encode("utf-8")
    return files, rows, {"buoy": buoy, "boat": boat, "rocks": rocks, "auv": auv, "workboat": workboat}


def summary(stats, png):
    for name in ("buoy", "boat", "rocks", "auv", "workboat"):
        s = stats[name]
        print("%s.gltf: %d triangles, %d vertices, %s.bin %d bytes, bounds %s"
              % (name, s["triangles"], s["vertices"], name, s["bin_bytes"], fmt_box(s["lo"], s["hi"])))
        for m in s["meshes"]:
            print("  %-9s %-14s %5d triangles  closed, volume %.4f m^3  %s"
                  % (m["node"], m["mesh"], m["triangles"], m["volume"], fmt_box(m["lo"], m["hi"])))
    print("sand.png: 256x256 RGBA8, mean RGB %.0f %.0f %.0f, seam step %.1f/%.1f vs %.1f/%.1f inside (tiles)"
          % (png["mean"][0], png["mean"][1], png["mean"][2], png["seam"][0], png["seam"][1],
             png["inner"][0], png["inner"][1]))


def main(argv):
    if len(argv) > 1 and argv[1:] != ["--check"]:
        print(__doc__)
        return 2
    files, rows, stats = generate()
    if argv[1:] != ["--check"]:
        os.makedirs(OUT_DIR, exist_ok=True)
        for name, data in sorted(files.items()):
            with open(os.path.join(OUT_DIR, name), "wb") as f:
                f.write(data)
            print("wrote scenes/assets/%s (%d bytes)" % (name, len(data)))
        summary(stats, check_png(files, rows))
        return 0

    failures = []
    disk = {}
    for name in sorted(files):
        path = os.path.join(OUT_DIR, name)
        if not os.path.exists(path):
            failures.append("scenes/assets/%s is missing" % name)
            continue
        with open(path, "rb") as f:
            disk[name] = f.read()
        if disk[name] == files[name]:
            print("ok   scenes/assets/%s equals a fresh generation" % name)
        elif name.endswith(".png"):
            # Another zlib build may compress differently; the pixels are what must match.
            try:
                if name == "sand.png":
                    check_png(disk, rows)
                else:
                    check_textures(disk, {name: texture_rows()[name]})
                print("ok   scenes/assets/%s has the same pixels (compressed by another zlib)" % name)
            except (CheckError, ValueError, zlib.error) as e:
                failures.append("scenes/assets/%s: %s" % (name, e))
        else:
            failures.append("scenes/assets/%s differs from a fresh generation; "
                            "run python3 tools/gen_assets.py"
                            % name)
    extra = sorted(set(os.listdir(OUT_DIR)) - set(files)) if os.path.isdir(OUT_DIR) else []
    for name in extra:
        failures.append("scenes/assets/%s is not made by the generator" % name)
    try:
        if len(disk) == len(files):
            stats = {"buoy": check_gltf("buoy", disk, expect_buoy),
                     "boat": check_gltf("boat", disk, expect_boat),
                     "rocks": check_gltf("rocks", disk, expect_rocks),
                     "auv": check_gltf("auv", disk, expect_auv),
                     "workboat": check_gltf("workboat", disk, expect_workboat)}
            check_textures(disk, texture_rows())
            png = check_png(disk, rows)
            summary(stats, png)
    except (CheckError, ValueError, KeyError, struct.error, zlib.error) as e:
        failures.append("check failed: %s" % e)
    for f in failures:
        print("FAIL " + f)
    print("gen_assets --check: %s" % ("FAILED" if failures else "all assets OK"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
