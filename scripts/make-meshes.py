#!/usr/bin/env python3
"""Writes the project's own Wavefront OBJ meshes into scenes/meshes/: torus.obj (quads, v//vn),
sphere.obj (icosphere, v/vt/vn triangles), gem.obj and gem.mtl (a faceted gem, positions only,
triangles and n-gons, two materials, partly negative indices), terrain.obj (a height field, quads,
v//vn) and knot.obj (a (2,3) torus knot tube, triangles, v//vn). Every mesh is computed here from
formulas; nothing is copied from anywhere.

Rerun with `python3 scripts/make-meshes.py` (from any directory; `--out DIR` writes into DIR
instead, which a CTest test uses to check that the committed meshes are this script's output).
The output is deterministic, byte for byte, and committed, so this only needs to run again when a
mesh changes. Before writing,
the script reads each file back from its own text and checks it: every face is counter-clockwise
seen from outside (the geometric normal (b - a) x (c - a) of every triangle of its fan, and for
quads of the other diagonal's split too, points the same way as the corners' vn), closed meshes are
closed and consistently wound (every edge used once each way, positive volume); then it prints one
summary line per file."""
import argparse
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join("scenes", "meshes")


def num(x):
    """A number as '%.6f' without trailing zeros ('1', '-0.35', '0.123457'); never '-0'."""
    s = ("%.6f" % x).rstrip("0").rstrip(".")
    return "0" if s == "-0" else s


def vec(*xs):
    return " ".join(num(x) for x in xs)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def length(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    return scale(a, 1.0 / length(a))


# --- Reading the written text back, and checking it -------------------------------------------

def parse_obj(text):
    """The OBJ's v, vt, vn and faces (each a list of (v, vt, vn) 0-based indices, None where
    absent), negative (relative) indices resolved against the counts so far, as a loader does."""
    v, vt, vn, faces = [], [], [], []

    def index(field, count):
        if field == "":
            return None
        i = int(field)
        assert i != 0, "OBJ indices start at 1"
        i = i - 1 if i > 0 else count + i
        assert 0 <= i < count, f"index {field} out of range ({count} defined)"
        return i

    for line in text.splitlines():
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "v":
            v.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "vt":
            vt.append(tuple(float(w) for w in words[1:3]))
        elif words[0] == "vn":
            vn.append(tuple(float(w) for w in words[1:4]))
        elif words[0] == "f":
            corners = []
            for w in words[1:]:
                parts = (w.split("/") + ["", ""])[:3]
                corners.append((index(parts[0], len(v)), index(parts[1], len(vt)), index(parts[2], len(vn))))
            assert len(corners) >= 3, "a face needs 3 corners"
            faces.append(corners)
        else:
            assert words[0] in ("mtllib", "usemtl", "o", "g", "s"), f"unexpected OBJ line: {line}"
    return v, vt, vn, faces


def check_obj(path, text, closed):
    """Asserts the winding and normals of the OBJ text; returns its summary line."""
    v, vt, vn, faces = parse_obj(text)
    for n in vn:
        assert abs(length(n) - 1) < 1e-5, f"{path}: vn {n} is not unit length"
    triangles = 0
    volume = 0.0
    edges = {}
    for face in faces:
        k = len(face)
        fans = [[(0, i, i + 1) for i in range(1, k - 1)]]
        if k == 4:  # a loader may split a quad along the other diagonal (tinyobjloader takes the shorter)
            fans.append([(1, 2, 3), (1, 3, 0)])
        for fan in fans:
            for tri in fan:
                a, b, c = (v[face[i][0]] for i in tri)
                n = cross(sub(b, a), sub(c, a))
                assert length(n) > 1e-12, f"{path}: degenerate triangle {tri} in face {face}"
                for i in tri:
                    if face[i][2] is not None:
                        assert dot(n, vn[face[i][2]]) > 0, f"{path}: face {face} is wound against its normals"
        triangles += k - 2
        for i in range(1, k - 1):
            volume += dot(v[face[0][0]], cross(v[face[i][0]], v[face[i + 1][0]])) / 6
        for i in range(k):
            e = (face[i][0], face[(i + 1) % k][0])
            assert e not in edges, f"{path}: edge {e} used twice the same way (inconsistent winding)"
            edges[e] = True
    if closed:
        for a, b in edges:
            assert (b, a) in edges, f"{path}: edge {(a, b)} has no twin: the mesh is not closed"
        assert volume > 0, f"{path}: faces point inwards (volume {volume})"
    line = f"{path}: {len(v)} vertices, "
    if vt:
        line += f"{len(vt)} texcoords, "
    return line + f"{len(vn)} normals, {len(faces)} faces, {triangles} triangles (fans), {len(text.encode())} bytes"


def write(name, text, closed=True):
    path = os.path.join(OUT, name)
    if name.endswith(".obj"):
        summary = check_obj(path, text, closed)
    else:
        summary = f"{path}: {len(text.encode())} bytes"
    with open(os.path.join(OUT_DIR, name), "w", newline="\n") as f:
        f.write(text)
    print(summary)


def header(what):
    return [f"# generated by scripts/make-meshes.py: {what}"]


# --- The meshes -------------------------------------------------------------------------------

def torus():
    """P(t, p) = ((R + r cos p) cos t, r sin p, (R + r cos p) sin t); the normal is the unit
    vector from the tube's centre circle, (cos p cos t, sin p, cos p sin t). Going round the tube
    (dP/dp) before going round the axis (dP/dt) is counter-clockwise seen from outside."""
    big, small, around, tube = 1.0, 0.35, 48, 24
    lines = header(f"a torus, major radius {num(big)}, minor radius {num(small)}, {around} x {tube} quads, "
                   "axis along y, centred at the origin; one unit vn per v")
    for i in range(around):
        t = 2 * math.pi * i / around
        for j in range(tube):
            p = 2 * math.pi * j / tube
            lines.append("v " + vec((big + small * math.cos(p)) * math.cos(t), small * math.sin(p),
                                    (big + small * math.cos(p)) * math.sin(t)))
    for i in range(around):
        t = 2 * math.pi * i / around
        for j in range(tube):
            p = 2 * math.pi * j / tube
            lines.append("vn " + vec(math.cos(p) * math.cos(t), math.sin(p), math.cos(p) * math.sin(t)))
    at = lambda i, j: (i % around) * tube + (j % tube) + 1
    for i in range(around):
        for j in range(tube):
            q = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j))
            lines.append("f " + " ".join(f"{k}//{k}" for k in q))
    write("torus.obj", "\n".join(lines) + "\n")


def sphere():
    """An icosahedron subdivided 3 times (each triangle into 4, new vertices pushed onto the unit
    sphere): 642 vertices, 1280 triangles. vn = the position. vt: u is the longitude, 0.5 at +x and
    growing towards -z (so an image is not mirrored seen from outside), v the latitude, 0 at the
    south pole and 1 at the north pole (+y). Triangles across the seam (x < 0, z = 0) get their own
    vt with u past 1; a pole corner takes the mean u of its triangle's other corners."""
    g = (1 + math.sqrt(5)) / 2
    pts = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g),
           (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    pts = [normalize(p) for p in pts]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
            (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
            (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(3):
        mid = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                mid[key] = len(pts)
                pts.append(normalize(scale(add(pts[a], pts[b]), 0.5)))
            return mid[key]

        finer = []
        for a, b, c in tris:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = finer

    def longitude(p):
        if abs(p[0]) < 1e-12 and abs(p[2]) < 1e-12:
            return "pole"
        if p[0] < 0 and p[2] == 0:
            return "seam"
        return 0.5 + math.atan2(-p[2], p[0]) / (2 * math.pi)

    uvs, uv_index, corner_uv = [], {}, []
    for tri in tris:
        us = [longitude(pts[k]) for k in tri]
        known = [u for u in us if isinstance(u, float)]
        if max(known) - min(known) > 0.5:
            us = [u + 1 if isinstance(u, float) and u < 0.5 else u for u in us]
            known = [u for u in us if isinstance(u, float)]
        us = [(1.0 if sum(known) / len(known) >= 0.5 else 0.0) if u == "seam" else u for u in us]
        known = [u for u in us if isinstance(u, float)]
        us = [sum(known) / len(known) if u == "pole" else u for u in us]
        ids = []
        for k, u in zip(tri, us):
            text = vec(u, 0.5 + math.asin(max(-1.0, min(1.0, pts[k][1]))) / math.pi)
            if text not in uv_index:
                uv_index[text] = len(uvs) + 1
                uvs.append(text)
            ids.append(uv_index[text])
        corner_uv.append(ids)

    lines = header(f"an icosphere, radius 1, centred at the origin, the icosahedron subdivided 3 times "
                   f"({len(tris)} triangles); spherical vt, vn = position")
    lines += ["v " + vec(*p) for p in pts]
    lines += ["vt " + t for t in uvs]
    lines += ["vn " + vec(*p) for p in pts]
    for tri, ids in zip(tris, corner_uv):
        lines.append("f " + " ".join(f"{k + 1}/{t}/{k + 1}" for k, t in zip(tri, ids)))
    write("sphere.obj", "\n".join(lines) + "\n")


def gem():
    """An 8-sided brilliant, positions only: an octagonal table (one 8-gon), a crown of 16
    triangles down to the girdle, a girdle of 8 upright quads, a pavilion of 16 triangles to a
    middle ring and 8 more to the culet (the point). Table and crown rings are turned half a step
    against each other, as are girdle and pavilion ring. The crown and girdle are material 'crown',
    written with positive indices; the pavilion is material 'pavilion', its vertices and faces
    written after the crown's, with negative (relative) indices only."""
    n = 8
    step = 2 * math.pi / n
    ring = lambda radius, y, turn: [(radius * math.cos((i + turn) * step), y, radius * math.sin((i + turn) * step))
                                    for i in range(n)]
    table = ring(0.55, 0.42, 0.5)
    girdle_top, girdle_bottom = ring(1.0, 0.06, 0.0), ring(1.0, -0.06, 0.0)
    pavilion = ring(0.52, -0.45, 0.5)
    culet = (0.0, -0.92, 0.0)

    lines = header("a faceted gem (8-sided brilliant: table, crown, girdle, pavilion to a point), width 2, "
                   "centred near the origin, axis along y; positions only, face normals to be computed; "
                   "the pavilion uses negative indices")
    lines.append("mtllib gem.mtl")
    lines += ["v " + vec(*p) for p in table + girdle_top + girdle_bottom]
    T = lambda i: (i % n) + 1
    G = lambda i: n + (i % n) + 1
    L = lambda i: 2 * n + (i % n) + 1
    face = lambda *ks: "f " + " ".join(str(k) for k in ks)
    lines.append("usemtl crown")
    # Seen from above (+y), angles grow from +x towards +z, which is clockwise: the table, facing
    # up, goes round the other way.
    lines.append(face(*(T(-i) for i in range(n))))
    for i in range(n):
        lines.append(face(G(i), T(i), G(i + 1)))       # a girdle edge up to a table corner
        lines.append(face(T(i - 1), T(i), G(i)))       # a table edge down to a girdle corner
    for i in range(n):
        lines.append(face(G(i), G(i + 1), L(i + 1), L(i)))
    lines += ["v " + vec(*p) for p in pavilion + [culet]]
    count = 4 * n + 1  # vertices defined so far
    rel = lambda k: k - count - 1  # the negative index of 1-based vertex k
    P = lambda i: 3 * n + (i % n) + 1
    C = 4 * n + 1
    lines.append("usemtl pavilion")
    for i in range(n):
        lines.append(face(rel(L(i)), rel(L(i + 1)), rel(P(i))))
        lines.append(face(rel(P(i)), rel(L(i + 1)), rel(P(i + 1))))
    for i in range(n):
        lines.append(face(rel(P(i)), rel(P(i + 1)), rel(C)))
    write("gem.obj", "\n".join(lines) + "\n")
    write("gem.mtl", "\n".join(["# generated by scripts/make-meshes.py: the two materials of gem.obj",
                                "newmtl crown", "Kd 0.2 0.55 0.9", "",
                                "newmtl pavilion", "Kd 0.75 0.15 0.45"]) + "\n")


def terrain():
    """A 40 x 40 grid of quads over [-2, 2] x [-2, 2] in x and z, y = h(x, z), a sum of sines; vn
    from the analytic gradient, normalize(-dh/dx, 1, -dh/dz). Faces wind counter-clockwise seen
    from above."""
    cells = 40
    waves = [  # amplitude, frequency in x, frequency in z, phase
        (0.22, 1.1, 0.7, 0.3), (0.12, -0.8, 1.9, 1.2), (0.06, 2.9, 2.3, -0.7), (0.03, -4.1, 3.7, 2.1)]

    def height(x, z):
        return sum(a * math.sin(fx * x + fz * z + ph) for a, fx, fz, ph in waves)

    def gradient(x, z):
        return (sum(a * fx * math.cos(fx * x + fz * z + ph) for a, fx, fz, ph in waves),
                sum(a * fz * math.cos(fx * x + fz * z + ph) for a, fx, fz, ph in waves))

    coords = [-2 + 4 * i / cells for i in range(cells + 1)]
    lines = header(f"a terrain patch, {cells} x {cells} quads over [-2, 2] x [-2, 2] in x and z, heights a sum of "
                   f"{len(waves)} sines, vn from the analytic gradient")
    for x in coords:
        for z in coords:
            lines.append("v " + vec(x, height(x, z), z))
    for x in coords:
        for z in coords:
            hx, hz = gradient(x, z)
            lines.append("vn " + vec(*normalize((-hx, 1.0, -hz))))
    at = lambda i, j: i * (cells + 1) + j + 1
    for i in range(cells):
        for j in range(cells):
            q = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j))
            lines.append("f " + " ".join(f"{k}//{k}" for k in q))
    write("terrain.obj", "\n".join(lines) + "\n", closed=False)


def knot():
    """A (2, 3) torus knot, c(t) = s ((2 + cos 3t) cos 2t, sin 3t, (2 + cos 3t) sin 2t), as a tube of
    radius rho around it, on its Frenet frame (periodic with the curve, so the tube closes without a
    seam): P(t, a) = c(t) + rho (cos a N + sin a B), whose unit normal is cos a N + sin a B. Going
    round the tube before going along the curve is counter-clockwise seen from outside."""
    along, around, s, rho = 120, 12, 0.5, 0.17

    def curve(t):
        r, r1, r2 = 2 + math.cos(3 * t), -3 * math.sin(3 * t), -9 * math.cos(3 * t)
        c, sn = math.cos(2 * t), math.sin(2 * t)
        p = (r * c, math.sin(3 * t), r * sn)
        d1 = (r1 * c - 2 * r * sn, 3 * math.cos(3 * t), r1 * sn + 2 * r * c)
        d2 = (r2 * c - 4 * r1 * sn - 4 * r * c, -9 * math.sin(3 * t), r2 * sn + 4 * r1 * c - 4 * r * sn)
        return scale(p, s), scale(d1, s), scale(d2, s)

    centres, frames = [], []
    for i in range(along):
        p, d1, d2 = curve(2 * math.pi * i / along)
        b = cross(d1, d2)
        assert length(b) > 1e-6, "the Frenet frame needs nonzero curvature"
        curvature = length(b) / length(d1) ** 3
        assert rho * curvature < 0.9, "the tube must be thinner than the radius of curvature"
        tangent, b = normalize(d1), normalize(b)
        frames.append((cross(b, tangent), b))
        centres.append(p)
    # The tube must not run into itself: curve points more than a sixth of the way apart along it
    # stay more than a tube's width apart.
    gap = min(length(sub(centres[i], centres[j])) for i in range(along) for j in range(i + along // 6, along)
              if (j - i) <= along - along // 6)
    assert gap > 2.4 * rho, f"the tube touches itself (strands {gap} apart)"

    lines = header(f"a (2,3) torus knot tube, {along} x {around} segments ({2 * along * around} triangles), "
                   f"tube radius {num(rho)}, axis along y, centred at the origin; one unit vn per v")
    normals = []
    for (nv, bv), p in zip(frames, centres):
        for j in range(around):
            a = 2 * math.pi * j / around
            n = add(scale(nv, math.cos(a)), scale(bv, math.sin(a)))
            lines.append("v " + vec(*add(p, scale(n, rho))))
            normals.append(n)
    lines += ["vn " + vec(*n) for n in normals]
    at = lambda i, j: (i % along) * around + (j % around) + 1
    for i in range(along):
        for j in range(around):
            a, b, c, d = at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)
            lines.append(f"f {a}//{a} {b}//{b} {c}//{c}")
            lines.append(f"f {a}//{a} {c}//{c} {d}//{d}")
    write("knot.obj", "\n".join(lines) + "\n")


OUT_DIR = os.path.join(ROOT, OUT)

if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="Writes the project's OBJ meshes.")
    parser.add_argument("--out", help="the directory to write into (default: scenes/meshes)")
    OUT_DIR = os.path.abspath(parser.parse_args().out or OUT_DIR)
    os.makedirs(OUT_DIR, exist_ok=True)
    torus()
    sphere()
    gem()
    terrain()
    knot()
