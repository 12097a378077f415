#!/usr/bin/env python3
"""Writes the project's own glTF 2.0 scenes into scenes/gltf/: arm.gltf (a node hierarchy four
deep, T·R·S nodes with turned quaternions and non-uniform scales, a node written as a matrix, a
16:9 perspective camera on a turned rig), strips.gltf (an orthographic camera, TRIANGLE_FAN and
TRIANGLE_STRIP primitives, lit and unlit materials in one mesh, one of them double-sided) and
colonnade.glb (binary: one mesh with normals in an interleaved buffer and 8-bit indices, drawn by
five nodes, a 3:2 perspective camera without a far plane, three nodes down a rig). Each of them
has every feature tests/verify/gltf_coverage_test.cpp turns into a defect: a T·R·S node, a matrix
node that is not symmetric, a mesh under a parent, a camera whose aspect ratio is not 1. Every
vertex is computed here from formulas; nothing is copied from anywhere.

Rerun with `python3 scripts/make-gltf-scenes.py` (from any directory; `--out DIR` writes into DIR
instead, which a CTest test uses to check that the committed files are this script's output). The
standard library only; the output is deterministic, byte for byte (numbers rounded to 7 decimals
before they are written), and committed, so this only needs to run again when a scene changes.
The buffers of the .gltf files are base64 data: URIs; the .glb holds its buffer in its BIN chunk.
Every triangle is counter-clockwise seen from the side the camera sees (glTF's front face), so an
engine that culls the back faces of single-sided materials, as glTF asks, draws what twinraster
(which culls nothing) draws. Before writing, the script checks what it wrote: every index is below
its vertex count, every POSITION accessor's min and max are its values', every quaternion is a
unit one, and every matrix node's last row is 0 0 0 1 and its 3x3 part not symmetric; then it
prints one summary line per file."""
import argparse
import base64
import json
import math
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join("scenes", "gltf")

FLOAT, UBYTE, USHORT = 5126, 5121, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 4, 5, 6


def r7(x):
    """A number rounded to 7 decimals, never -0, so that the JSON is the same on every machine."""
    x = round(x, 7)
    return 0.0 if x == 0 else x


# --- Small linear algebra in glTF's right-handed frame; matrices are lists of rows.

def quat(axis, degrees):
    """The unit quaternion (x, y, z, w) of a turn by `degrees` about `axis` (right-handed)."""
    n = math.sqrt(sum(a * a for a in axis))
    h = math.radians(degrees) / 2
    return [a / n * math.sin(h) for a in axis] + [math.cos(h)]


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


def quat_matrix(q):
    x, y, z, w = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0], [0, 0, 0, 1]]


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def translate(t):
    return [[1, 0, 0, t[0]], [0, 1, 0, t[1]], [0, 0, 1, t[2]], [0, 0, 0, 1]]


def scale(s):
    return [[s[0], 0, 0, 0], [0, s[1], 0, 0], [0, 0, s[2], 0], [0, 0, 0, 1]]


def column_major(m):
    """glTF's `matrix`: the 16 numbers column by column."""
    return [r7(m[i][j]) for j in range(4) for i in range(4)]


def look_quat(eye, target):
    """A camera at `eye` looking at `target` with +Y up: glTF's camera looks down its -Z, so it is
    turned by the yaw about Y, then pitched about X."""
    d = [eye[i] - target[i] for i in range(3)]
    yaw = math.degrees(math.atan2(d[0], d[2]))
    pitch = -math.degrees(math.atan2(d[1], math.hypot(d[0], d[2])))
    return quat_mul(quat([0, 1, 0], yaw), quat([1, 0, 0], pitch))


# --- A document and its one buffer.

class Gltf:
    def __init__(self):
        self.buffer = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "twinraster scripts/make-gltf-scenes.py"},
                    "scene": 0, "scenes": [], "nodes": [], "meshes": [], "materials": [], "cameras": [],
                    "accessors": [], "bufferViews": [], "buffers": []}

    def _view(self, data, target, stride=None):
        while len(self.buffer) % 4:
            self.buffer.append(0)
        view = {"buffer": 0, "byteOffset": len(self.buffer), "byteLength": len(data), "target": target}
        if stride:
            view["byteStride"] = stride
        self.buffer += data
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, accessor):
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def vec3(self, points):
        """A VEC3 float accessor of its own view; min and max as the float32 values stored."""
        data = b"".join(struct.pack("<3f", *p) for p in points)
        stored = [struct.unpack("<3f", data[12 * i:12 * i + 12]) for i in range(len(points))]
        return self._accessor({"bufferView": self._view(data, ARRAY_BUFFER), "componentType": FLOAT,
                               "count": len(points), "type": "VEC3",
                               "min": [r7(min(p[k] for p in stored)) for k in range(3)],
                               "max": [r7(max(p[k] for p in stored)) for k in range(3)]})

    def interleaved(self, points, normals):
        """POSITION and NORMAL in one view, 24 bytes per vertex: two accessors into it."""
        data = b"".join(struct.pack("<6f", *p, *n) for p, n in zip(points, normals))
        view = self._view(data, ARRAY_BUFFER, stride=24)
        stored = [struct.unpack("<3f", data[24 * i:24 * i + 12]) for i in range(len(points))]
        position = self._accessor({"bufferView": view, "componentType": FLOAT, "count": len(points),
                                   "type": "VEC3", "min": [r7(min(p[k] for p in stored)) for k in range(3)],
                                   "max": [r7(max(p[k] for p in stored)) for k in range(3)]})
        normal = self._accessor({"bufferView": view, "byteOffset": 12, "componentType": FLOAT,
                                 "count": len(points), "type": "VEC3"})
        return position, normal

    def indices(self, values, component):
        fmt = {UBYTE: "B", USHORT: "H"}[component]
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        return self._accessor({"bufferView": self._view(data, ELEMENT_ARRAY_BUFFER), "componentType": component,
                               "count": len(values), "type": "SCALAR"})

    def material(self, name, rgb, unlit=False, double_sided=False):
        m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [r7(c) for c in rgb] + [1.0],
                                                    "metallicFactor": 0.0}}
        if double_sided:  # glTF culls back faces otherwise; twinraster draws both sides always
            m["doubleSided"] = True
        if unlit:
            m["extensions"] = {"KHR_materials_unlit": {}}
            self.doc.setdefault("extensionsUsed", ["KHR_materials_unlit"])
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, primitives):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        return len(self.doc["meshes"]) - 1

    def camera(self, camera):
        self.doc["cameras"].append(camera)
        return len(self.doc["cameras"]) - 1

    def node(self, name, t=None, r=None, s=None, matrix=None, mesh=None, camera=None):
        n = {"name": name}
        if matrix is not None:
            n["matrix"] = column_major(matrix)
        if t is not None:
            n["translation"] = [r7(x) for x in t]
        if r is not None:
            n["rotation"] = [r7(x) for x in r]
        if s is not None:
            n["scale"] = [r7(x) for x in s]
        if mesh is not None:
            n["mesh"] = mesh
        if camera is not None:
            n["camera"] = camera
        self.doc["nodes"].append(n)
        return len(self.doc["nodes"]) - 1

    def adopt(self, parent, children):
        """Written after the parent, so that the file lists nodes from the roots down."""
        self.doc["nodes"][parent]["children"] = children

    def finish(self, scene_name, roots):
        self.doc["scenes"].append({"name": scene_name, "nodes": roots})
        while len(self.buffer) % 4:
            self.buffer.append(0)
        return self


# --- Checks of what is written: the reader refuses much of this, but a mistake here could also
# make a scene that reads and draws something other than intended.

def check(g):
    doc, buf = g.doc, bytes(g.buffer)
    counts = []
    for mesh in doc["meshes"]:
        for p in mesh["primitives"]:
            pos = doc["accessors"][p["attributes"]["POSITION"]]
            view = doc["bufferViews"][pos["bufferView"]]
            stride = view.get("byteStride", 12)
            start = view["byteOffset"] + pos.get("byteOffset", 0)
            values = [struct.unpack_from("<3f", buf, start + i * stride) for i in range(pos["count"])]
            assert pos["min"] == [r7(min(v[k] for v in values)) for k in range(3)], mesh["name"]
            assert pos["max"] == [r7(max(v[k] for v in values)) for k in range(3)], mesh["name"]
            n = pos["count"]
            if "indices" in p:
                ind = doc["accessors"][p["indices"]]
                iv = doc["bufferViews"][ind["bufferView"]]
                fmt = {UBYTE: "B", USHORT: "H"}[ind["componentType"]]
                values = struct.unpack_from("<%d%s" % (ind["count"], fmt), buf, iv["byteOffset"])
                assert max(values) < n, mesh["name"]
                n = ind["count"]
            counts.append(n - 2 if p.get("mode", TRIANGLES) != TRIANGLES else n // 3)
    for node in doc["nodes"]:
        if "rotation" in node:
            assert abs(math.sqrt(sum(x * x for x in node["rotation"])) - 1) < 1e-6, node["name"]
        if "matrix" in node:
            m = node["matrix"]  # column-major: element (row i, column j) is m[4 * j + i]
            assert [m[3], m[7], m[11], m[15]] == [0, 0, 0, 1], node["name"]
            assert any(abs(m[4 * j + i] - m[4 * i + j]) > 0.1 for i in range(3) for j in range(3)), node["name"]
    return sum(counts)


def dump(obj, indent=0):
    """JSON with arrays of numbers on one line, so that a file reads node by node."""
    pad = "  " * indent
    if isinstance(obj, dict):
        items = ",\n".join("%s  %s: %s" % (pad, json.dumps(k), dump(v, indent + 1)) for k, v in obj.items())
        return "{\n" + items + "\n" + pad + "}"
    if isinstance(obj, list) and any(isinstance(x, (dict, list)) for x in obj):
        return "[\n" + ",\n".join(pad + "  " + dump(x, indent + 1) for x in obj) + "\n" + pad + "]"
    return json.dumps(obj)


def write(g, path, binary):
    triangles = check(g)
    doc = dict(g.doc)
    if binary:
        doc["buffers"] = [{"byteLength": len(g.buffer)}]
        text = json.dumps(doc, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        body = struct.pack("<I4s", len(text), b"JSON") + text
        body += struct.pack("<I4s", len(g.buffer), b"BIN\0") + bytes(g.buffer)
        data = struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body
    else:
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(g.buffer)).decode()
        doc["buffers"] = [{"byteLength": len(g.buffer), "uri": uri}]
        data = (dump(doc) + "\n").encode()
    with open(path, "wb") as f:
        f.write(data)
    print("%s: %d nodes, %d meshes of %d triangles in all, %d bytes" %
          (os.path.basename(path), len(doc["nodes"]), len(doc["meshes"]), triangles, len(data)))


# --- Meshes.

def box():
    """A cube from -0.5 to 0.5: 8 corners, 12 triangles counter-clockwise seen from outside."""
    points = [[x, y, z] for z in (-0.5, 0.5) for y in (-0.5, 0.5) for x in (-0.5, 0.5)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return points, [i for a, b, c, d in quads for i in (a, b, c, a, c, d)]


def arm():
    """A robot arm on a turntable: turntable → shoulder (a matrix) → elbow → forearm, meshes on
    the plinth, the shoulder, the upper arm and the forearm; the camera on a turned rig."""
    g = Gltf()
    points, triangles = box()
    position, indices = g.vec3(points), g.indices(triangles, USHORT)
    colours = {"plinth": [0.30, 0.32, 0.36], "joint": [0.80, 0.80, 0.75], "upper-arm": [0.95, 0.40, 0.05],
               "forearm": [0.05, 0.35, 0.85]}
    meshes = {name: g.mesh(name, [{"attributes": {"POSITION": position}, "indices": indices,
                                   "material": g.material(name, rgb)}]) for name, rgb in colours.items()}
    turntable = g.node("turntable", r=quat([0, 1, 0], 35))
    plinth = g.node("plinth", t=[0, 0.25, 0], r=quat([0, 1, 0], 10), s=[1.8, 0.5, 1.2], mesh=meshes["plinth"])
    # The shoulder as an exporter writes a baked transform: a matrix, turned about z and x (so not
    # symmetric), lifted onto the plinth, at half scale.
    shoulder = g.node("shoulder", matrix=mat_mul(mat_mul(mat_mul(translate([0, 0.55, 0]), quat_matrix(
        quat([0, 0, 1], -30))), quat_matrix(quat([1, 0, 0], 15))), scale([0.5, 0.5, 0.5])), mesh=meshes["joint"])
    upper = g.node("upper-arm", t=[0, 2.0, 0], r=quat([0, 1, 0], 20), s=[0.6, 3.0, 0.5], mesh=meshes["upper-arm"])
    elbow = g.node("elbow", t=[0, 3.6, 0], r=quat([0.2, 0, 1], 75))
    forearm = g.node("forearm", t=[0, 1.4, 0], r=quat([0.3, 1, 0], 40), s=[0.45, 2.6, 0.4], mesh=meshes["forearm"])
    g.adopt(turntable, [plinth, shoulder])
    g.adopt(shoulder, [upper, elbow])
    g.adopt(elbow, [forearm])
    lens = g.camera({"name": "16:9", "type": "perspective",
                     "perspective": {"yfov": 0.7, "aspectRatio": r7(16 / 9), "znear": 0.1, "zfar": 50}})
    eye = [0.5, 2.6, 5.5]
    rig = g.node("camera-rig", r=quat([0, 1, 0], -25))
    g.adopt(rig, [g.node("camera", t=eye, r=look_quat(eye, [0, 1.5, 0]), camera=lens)])
    return g.finish("arm", [turntable, rig])


def strips():
    """A stage seen by an orthographic camera: a floor drawn as a fan, a sign (a fan star and a
    strip frame, two materials in one mesh) written as a matrix, a ribbon strip under the sign."""
    g = Gltf()
    rim = 16
    disc = [[0, 0, 0]] + [[math.cos(2 * math.pi * k / rim), math.sin(2 * math.pi * k / rim), 0]
                          for k in range(rim + 1)]
    floor_mesh = g.mesh("floor", [{"attributes": {"POSITION": g.vec3(disc)}, "mode": TRIANGLE_FAN,
                                   "material": g.material("floor", [0.10, 0.45, 0.35])}])
    # The star: its centre, then points alternately out and in, indexed as a fan.
    star = [[0, 0, 0.01]] + [[-(0.8 if k % 2 == 0 else 0.35) * math.sin(math.pi * k / 5),
                              (0.8 if k % 2 == 0 else 0.35) * math.cos(math.pi * k / 5), 0.01] for k in range(10)]
    frame = [[sx * w, sy * w, 0] for w in (1.0, 0.85) for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    sign_mesh = g.mesh("sign", [
        {"attributes": {"POSITION": g.vec3(star)}, "indices": g.indices(list(range(11)) + [1], UBYTE),
         "mode": TRIANGLE_FAN, "material": g.material("star", [0.90, 0.10, 0.10], unlit=True)},
        {"attributes": {"POSITION": g.vec3(frame)}, "indices": g.indices([4, 0, 5, 1, 6, 2, 7, 3, 4, 0], UBYTE),
         "mode": TRIANGLE_STRIP, "material": g.material("frame", [0.95, 0.95, 0.90])}])
    wave = [[-1 + 2 * k / 11, 0.25 * math.sin(k * 0.9) + side * 0.12, 0.15 * math.cos(k * 0.7)]
            for k in range(12) for side in (-1, 1)]
    ribbon_mesh = g.mesh("ribbon", [{"attributes": {"POSITION": g.vec3(wave)}, "mode": TRIANGLE_STRIP,
                                     "material": g.material("ribbon", [1.0, 0.75, 0.05], unlit=True,
                                                                        double_sided=True)}])
    stage = g.node("stage", t=[0, -0.5, 0], r=quat([0, 1, 0], 20))
    floor = g.node("floor", r=quat_mul(quat([0, 1, 0], 10), quat([1, 0, 0], -90)), s=[3.0, 2.2, 1.0],
                   mesh=floor_mesh)
    sign = g.node("sign", matrix=mat_mul(mat_mul(translate([0.3, 1.5, -0.4]), quat_matrix(quat([0, 1, 0], 30))),
                                         scale([1.3, 0.9, 1.0])), mesh=sign_mesh)
    ribbon = g.node("ribbon", t=[0, -1.35, 0.1], r=quat([1, 0, 1], 25), s=[1.1, 1.4, 1.0], mesh=ribbon_mesh)
    g.adopt(stage, [floor, sign])
    g.adopt(sign, [ribbon])
    lens = g.camera({"name": "iso", "type": "orthographic",
                     "orthographic": {"xmag": 3.6, "ymag": 2.25, "znear": 0.1, "zfar": 30}})
    eye = [6, 5, 6]
    camera = g.node("camera", t=eye, r=look_quat(eye, [0, 0.3, 0]), camera=lens)
    return g.finish("strips", [stage, camera])


def column():
    """An octagonal column of height 1 on y, radius 0.5: smooth side normals, flat caps."""
    points, normals, triangles = [], [], []
    sides = 8
    for k in range(sides):
        a = 2 * math.pi * (k + 0.5) / sides
        for y in (0, 1):
            points.append([0.5 * math.cos(a), y, -0.5 * math.sin(a)])
            normals.append([math.cos(a), 0, -math.sin(a)])
    for k in range(sides):
        a, b = 2 * k, 2 * ((k + 1) % sides)
        triangles += [a, b, b + 1, a, b + 1, a + 1]
    for y, ny in ((0, -1), (1, 1)):
        centre = len(points)
        points.append([0, y, 0])
        normals.append([0, ny, 0])
        for k in range(sides):
            points.append(points[2 * k + y])
            normals.append([0, ny, 0])
        for k in range(sides):
            a, b = centre + 1 + k, centre + 1 + (k + 1) % sides
            triangles += [centre, a, b] if ny > 0 else [centre, b, a]
    return points, normals, triangles


def colonnade():
    """Four columns and a lintel on a stretched base, one mesh drawn by five nodes, one of them a
    matrix; a camera three nodes down a crane."""
    g = Gltf()
    points, normals, triangles = column()
    position, normal = g.interleaved(points, normals)
    stone = g.mesh("column", [{"attributes": {"POSITION": position, "NORMAL": normal},
                               "indices": g.indices(triangles, UBYTE),
                               "material": g.material("stone", [0.75, 0.68, 0.55])}])
    temple = g.node("temple", t=[0, -1, 0], r=quat([0, 1, 0], 15), s=[1.0, 1.2, 1.0])
    columns = []
    for k, (x, z) in enumerate(((-1.5, -1), (1.5, -1), (1.5, 1), (-1.5, 1))):
        if k == 2:
            columns.append(g.node("column-%d" % k, matrix=mat_mul(mat_mul(translate([x, 0, z]), quat_matrix(
                quat([0.1, 1, 0], 22.5))), scale([0.7, 2.0, 0.55])), mesh=stone))
        else:
            columns.append(g.node("column-%d" % k, t=[x, 0, z], r=quat([0, 1, 0], 11.25 * k), s=[0.6, 2.0, 0.6],
                                  mesh=stone))
    lintel = g.node("lintel", t=[-2, 2.25, -1], r=quat([0, 0, 1], -90), s=[0.5, 4.0, 0.9], mesh=stone)
    g.adopt(temple, columns + [lintel])
    lens = g.camera({"name": "3:2", "type": "perspective",
                     "perspective": {"yfov": 0.9, "aspectRatio": 1.5, "znear": 0.05}})
    crane = g.node("crane", t=[0, 0.3, 0], r=quat([0, 1, 0], -30))
    boom = g.node("boom", t=[0, 1.2, 1.5], r=quat([1, 0, 0], -5))
    g.adopt(crane, [boom])
    g.adopt(boom, [g.node("camera", t=[0, 0.6, 5], r=quat([1, 0, 0], -18), camera=lens)])
    return g.finish("colonnade", [temple, crane])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, OUT), help="the folder to write (default: %s)" % OUT)
    out = parser.parse_args().out
    os.makedirs(out, exist_ok=True)
    write(arm(), os.path.join(out, "arm.gltf"), binary=False)
    write(strips(), os.path.join(out, "strips.gltf"), binary=False)
    write(colonnade(), os.path.join(out, "colonnade.glb"), binary=True)


if __name__ == "__main__":
    main()
