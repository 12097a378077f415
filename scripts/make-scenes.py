#!/usr/bin/env python3
"""Writes the generated scene files: scenes/hard/*.json (the cases that break naive renderers; the
three hard/lit-*.json scenes are written by hand), scenes/bench/*.json (the benchmark's large
scene), the grid scenes (scenes/one-million-cubes.json, scenes/catlike-grid.json), the book's
figures 10-4 and 10-5 and scenes/catlike-orthographic.json.

Rerun with `python3 scripts/make-scenes.py` (from any directory; `--out DIR` writes into DIR
instead of scenes/, which a CTest test uses to check that the committed files are this script's
output). The output is deterministic, byte for byte, and committed, so this only needs to run again
when a case changes."""
import argparse
import json
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT_DIR = os.path.join(ROOT, "scenes")

CUBE_V = [[1, 1, 1], [-1, 1, 1], [-1, -1, 1], [1, -1, 1], [1, 1, -1], [-1, 1, -1], [-1, -1, -1], [1, -1, -1]]
CUBE_T = [[0, 1, 2, "red"], [0, 2, 3, "red"], [4, 0, 3, "green"], [4, 3, 7, "green"], [5, 4, 7, "blue"],
          [5, 7, 6, "blue"], [1, 5, 6, "yellow"], [1, 6, 2, "yellow"], [4, 5, 1, "purple"], [4, 1, 0, "purple"],
          [2, 6, 7, "cyan"], [2, 7, 3, "cyan"]]


def cube():
    return {"vertices": CUBE_V, "triangles": CUBE_T}


def dump(obj, indent=0):
    """JSON with short arrays on one line, so that the files stay readable."""
    pad = "  " * indent
    if isinstance(obj, dict):
        return "{\n" + ",\n".join(f"{pad}  {json.dumps(k)}: {dump(v, indent + 1)}" for k, v in obj.items()) + "\n" + pad + "}"
    if isinstance(obj, list):
        if all(not isinstance(x, (dict, list)) for x in obj):
            return json.dumps(obj)
        if all(isinstance(x, list) for x in obj) and sum(len(json.dumps(x)) for x in obj) < 100:
            return "[" + ", ".join(json.dumps(x) for x in obj) + "]"
        return "[\n" + ",\n".join(f"{pad}  {dump(x, indent + 1)}" for x in obj) + "\n" + pad + "]"
    return json.dumps(obj)


def out_path(name):
    """Where a file of scenes/ goes: `name` is its path inside scenes/."""
    path = os.path.join(OUT_DIR, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    return path


def write(name, scene):
    with open(out_path(name), "w") as f:
        f.write(dump(scene) + "\n")


def hd(comment):
    return {"comment": comment, "canvas": {"width": 1920, "height": 1080, "background": [255, 255, 255]},
            "viewport": {"width": 16 / 9, "height": 1, "distance": 1}}


def small(comment, w=320, h=240):
    return {"comment": comment, "canvas": {"width": w, "height": h, "background": [255, 255, 255]},
            "viewport": {"width": w / h, "height": 1, "distance": 1}}


def far_scenes():
    for exponent in (3, 5, 7):
        d = 10.0 ** exponent
        origin = [d * 1.0, d * 0.5, d * 0.25]
        at = lambda x, y, z: [origin[0] + x, origin[1] + y, origin[2] + z]
        s = hd(f"Far from the origin: the same small scene translated by about 1e{exponent} units, camera next to it, "
               "non-integer positions and scales. Expected: methods compose-f64 and camera-relative keep vertex error "
               "far below 1/256 px; float composition (compose-f32, steps-f32) degrades as the offset grows. GPU == CPU twin.")
        s["depth"] = {"near": 0.1, "far": 100}
        s["camera"] = {"position": at(0.13, 0.57, -0.71), "rotation": {"axis": "y", "degrees": 7.3}}
        s["models"] = {"cube": cube()}
        s["instances"] = [
            {"model": "cube", "transform": {"scale": 0.731, "rotation": {"axis": [0.3, 1, 0.2], "degrees": 33.3},
                                            "translation": at(-1.37, 0.21, 5.13)}},
            {"model": "cube", "transform": {"scale": [0.45, 1.27, 0.61], "rotation": {"axis": "x", "degrees": -21.7},
                                            "translation": at(1.61, -0.43, 6.29)}},
            {"model": "cube", "transform": {"scale": 0.173, "translation": at(0.07, 0.33, 2.77)}},
        ]
        write(f"hard/far-1e{exponent}.json", s)


def near_plane_scenes():
    s = small("Near plane and behind the camera: triangles straddling the near plane (z = 0.5), straddling camera-space "
              "z = 0, and wholly behind the camera. Expected: homogeneous clipping draws only the parts in front of "
              "near; nothing behind the camera appears (no wrapped-around triangles). GPU == CPU twin.")
    s["depth"] = {"near": 0.5, "far": 50}
    s["camera"] = {"position": [0, 0, 0]}
    s["models"] = {"tris": {
        "vertices": [[-3, -1, 0.2], [2, -1.5, 6], [0.5, 2, 3],      # straddles near (z 0.2 .. 6)
                     [-2, 1, -2], [2.5, 1.5, 4], [-1, -2, 5],        # straddles z = 0
                     [-1, -1, -3], [1, -1, -3], [0, 1, -1],          # wholly behind
                     [4, -3, -6], [-4, 3, 9], [4, 3, 9]],            # long: from behind to far ahead
        "triangles": [[0, 1, 2, "red"], [3, 4, 5, "green"], [6, 7, 8, "blue"], [9, 10, 11, [255, 128, 0]]]}}
    s["instances"] = [{"model": "tris"}]
    write("hard/near-plane.json", s)

    s = small("The camera inside a cube: every face straddles or surrounds the camera, several cross z = 0. "
              "Expected: the inside of the cube fills the view, faces meeting at clipped edges without gaps. GPU == CPU twin.")
    s["depth"] = {"near": 0.05, "far": 20}
    s["camera"] = {"position": [0.2, -0.3, 0.1], "rotation": [{"axis": "y", "degrees": 25}, {"axis": "x", "degrees": -15}]}
    s["models"] = {"cube": cube()}
    s["instances"] = [{"model": "cube", "transform": {"scale": 2.0}}]
    write("hard/camera-inside-cube.json", s)


def depth_scenes():
    # Two parallel tilted plates 0.02 apart, 40-50 units away; the farther (blue) is drawn first, so
    # every pixel where depth cannot tell them apart shows blue: those are z-fighting pixels.
    plate = {"vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], "triangles": [[0, 1, 2, "red"], [0, 2, 3, "red"]]}
    plate_far = {"vertices": plate["vertices"], "triangles": [[0, 1, 2, "blue"], [0, 2, 3, "blue"]]}
    for exponent in range(1, 7):
        for reversed_z in (False, True):
            far = 100.0
            near = far * 10.0 ** -exponent
            name = f"depth-ratio-1e-{exponent}" + ("-reversed" if reversed_z else "")
            s = small(f"Depth precision: two parallel plates 0.02 apart, about 45 units away, near/far = 1e-{exponent}"
                      + (", reversed Z (depth test GREATER, cleared to 0)" if reversed_z else ", standard Z (LESS, cleared to 1)")
                      + ". The farther plate (blue) is drawn first: each blue pixel inside the red plate is z-fighting. "
                      "Expected: standard Z fights once near/far is small enough; reversed Z holds. GPU == CPU twin.", 256, 256)
            s["viewport"] = {"width": 1, "height": 1, "distance": 1}
            s["depth"] = {"near": near, "far": far, "reversed": reversed_z}
            s["camera"] = {"position": [0, 0, 0]}
            s["models"] = {"front": plate, "back": plate_far}
            tilt = {"axis": "x", "degrees": 60}
            s["instances"] = [
                {"model": "back", "transform": {"scale": 18, "rotation": tilt, "translation": [0, 0, 45.02]}},
                {"model": "front", "transform": {"scale": 18, "rotation": tilt, "translation": [0, 0, 45.0]}},
            ]
            write(f"hard/{name}.json", s)


def degenerate_scene():
    s = small("Degenerate geometry: zero-area triangles (a repeated vertex, three collinear points), slivers a hair wide, "
              "sub-pixel triangles, and triangles reaching beyond +-16384 and +-32768 pixels (clipped to the viewport, "
              "since lavapipe has no guard band with a depth buffer). Expected: zero-area draws nothing; every other "
              "pixel is decided by the same rules on both backends. GPU == CPU twin.")
    s["camera"] = {"position": [0, 0, 0]}
    # At z = 1 one unit is 240 px (canvas height 240, Vh = 1), so x = 70 is 16800 px and x = 140 is 33600 px.
    s["models"] = {"degenerate": {
        "vertices": [[-1, -0.5, 4], [1, -0.4, 4], [-1, -0.5, 4],                    # repeated vertex
                     [-1, 0, 4], [0, 0.1, 4], [1, 0.2, 4],                         # collinear
                     [-1.2, 0.6, 3], [1.3, 0.6001, 3], [1.3, 0.6003, 3],           # sliver
                     [0.1, -0.1, 2], [0.1003, -0.1, 2], [0.1, -0.0996, 2],          # sub-pixel
                     [-70, -0.8, 1], [70, -0.8, 1], [0, 30, 1],                    # beyond 16384 px
                     [-140, 0.9, 1.5], [140, 0.95, 1.5], [0.3, -50, 1.5]],         # beyond 32768 px
        "triangles": [[0, 1, 2, "red"], [3, 4, 5, "red"], [6, 7, 8, "blue"], [9, 10, 11, "purple"],
                      [12, 13, 14, [200, 200, 200]], [15, 16, 17, [0, 160, 0]]]}}
    s["instances"] = [{"model": "degenerate"}]
    write("hard/degenerate.json", s)


def transform_scenes():
    s = small("Zero and negative scale: a cube flattened to nothing (scale 0), a mirrored cube (scale -1 on x: the winding "
              "flips, which matters only with culling, and twinraster does not cull) and a cube with all three scales negative. "
              "Expected: the zero-scale instance draws nothing; the mirrored ones draw as mirrors. GPU == CPU twin.")
    s["camera"] = {"position": [0, 0, -6]}
    s["models"] = {"cube": cube()}
    s["instances"] = [
        {"model": "cube", "transform": {"scale": 0, "translation": [-2.5, 0, 0]}},
        {"model": "cube", "transform": {"scale": [-1, 1, 1], "rotation": {"axis": "y", "degrees": 30}, "translation": [0, 0, 0]}},
        {"model": "cube", "transform": {"scale": -0.7, "rotation": {"axis": "x", "degrees": 20}, "translation": [2.5, 0, 0]}},
    ]
    write("hard/zero-negative-scale.json", s)

    s = small("Scales from 1e-6 to 1e6: a cube scaled 1e-6 (sub-pixel), one scaled 1e6 far away (and around the "
              "camera's line of sight), and ordinary ones. Expected: the tiny cube covers at most a pixel; the huge cube is "
              "clipped by the far plane; nothing overflows. GPU == CPU twin.")
    s["depth"] = {"near": 0.1, "far": 5e6}
    s["camera"] = {"position": [0, 0, 0]}
    s["models"] = {"cube": cube()}
    s["instances"] = [
        {"model": "cube", "transform": {"scale": 1e-6, "translation": [0.0021, 0.0013, 1]}},
        {"model": "cube", "transform": {"scale": 1e-3, "translation": [-0.3, 0.2, 2]}},
        {"model": "cube", "transform": {"scale": 1, "rotation": {"axis": "y", "degrees": 40}, "translation": [1.5, -0.5, 6]}},
        {"model": "cube", "transform": {"scale": 1e3, "translation": [-2500, 1200, 9000]}},
        {"model": "cube", "transform": {"scale": 1e6, "rotation": {"axis": "z", "degrees": 10}, "translation": [0, -1.5e6, 4e6]}},
    ]
    write("hard/extreme-scales.json", s)

    s = small("Up vector 1e-7 away from parallel to the view direction: the lookat camera must still build an "
              "orthonormal frame (the loader rejects only exact parallelism). Expected: a valid, if arbitrary-looking, "
              "roll; orthonormal camera rotation; GPU == CPU twin.")
    s["camera"] = {"eye": [0, 0, -5], "center": [0, 0, 3], "up": [1e-7, 0, 1]}
    s["models"] = {"cube": cube()}
    s["instances"] = [{"model": "cube", "transform": {"rotation": {"axis": "y", "degrees": 30}, "translation": [0.5, 0.3, 0]}},
                      {"model": "cube", "transform": {"scale": 0.5, "translation": [-2, 1, 2]}}]
    write("hard/up-near-parallel.json", s)

    for reortho in (False, True):
        s = small("A camera rotation accumulated from a million small steps (30 degrees about a tilted axis in 1e6 steps, "
                  "each product rounded in double), " + ("re-orthonormalized after every step" if reortho else
                  "never re-orthonormalized") + ". Expected: the camera ends up 30 degrees round; the drift away from "
                  "orthonormal is measured by the tests. GPU == CPU twin.")
        s["camera"] = {"position": [0, 0, -4], "rotation": {"axis": [0.2, 1, 0.1], "degrees": 30, "steps": 1000000,
                                                             "reorthonormalize": reortho}}
        s["models"] = {"cube": cube()}
        s["instances"] = [{"model": "cube", "transform": {"translation": [1.5, 0, 1]}},
                          {"model": "cube", "transform": {"scale": 0.5, "translation": [-1, 0.5, 2]}}]
        write("hard/accumulated-rotation" + ("-reorthonormalized" if reortho else "") + ".json", s)


def bench_scene():
    # A UV sphere of 48 rings x 64 segments (about 6k triangles), instanced 20 times: over 100k
    # triangles at 1920x1080.
    rings, segments = 48, 64
    vertices = []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for k in range(segments):
            phi = 2 * math.pi * k / segments
            vertices.append([round(math.sin(theta) * math.cos(phi), 6), round(math.cos(theta), 6),
                             round(math.sin(theta) * math.sin(phi), 6)])
    palette = ["red", "green", "blue", "yellow", "purple", "cyan"]
    idx = lambda r, k: r * segments + (k % segments)
    triangles = []
    for r in range(rings):
        for k in range(segments):
            c = palette[(r + k) % len(palette)]
            if r > 0:
                triangles.append([idx(r, k), idx(r + 1, k), idx(r, k + 1), c])
            if r < rings - 1:
                triangles.append([idx(r, k + 1), idx(r + 1, k), idx(r + 1, k + 1), c])
    s = hd(f"Benchmark load: a {len(triangles)}-triangle sphere instanced 20 times ({20 * len(triangles)} triangles) at "
           "1920x1080, overlapping in depth.")
    s["depth"] = {"near": 0.5, "far": 200}
    s["camera"] = {"eye": [0, 6, -14], "center": [0, 0, 6], "up": [0, 1, 0]}
    s["models"] = {"sphere": {"vertices": vertices, "triangles": triangles}}
    instances = []
    for i in range(20):
        x, z = (i % 5) * 3.2 - 6.4, (i // 5) * 3.5 + 1
        instances.append({"model": "sphere", "transform": {"scale": 1.4 + 0.1 * (i % 3), "rotation": {"axis": "y", "degrees": 17 * i},
                                                           "translation": [x, math.sin(i) * 0.8, z]}})
    s["instances"] = instances
    with open(out_path("bench/spheres-100k.json"), "w") as f:
        json.dump(s, f, separators=(",", ":"))
        f.write("\n")


def transform_order_scenes():
    # Figures 10-4 and 10-5 of the chapter: the same rotation and translation, applied in the two
    # orders, written as transform lists. Seen from above and behind the origin, where a small
    # cube marks the origin the rotation turns about.
    for figure, steps, what in (
            ("10-4", [{"rotation": {"axis": "y", "degrees": 45}}, {"translation": [0, 0, 5]}],
             "rotate 45 degrees about Y around the origin, then translate along Z: the cube turns in place and "
             "moves 5 units ahead"),
            ("10-5", [{"translation": [0, 0, 5]}, {"rotation": {"axis": "y", "degrees": 45}}],
             "translate along Z, then rotate 45 degrees about Y around the origin: the rotation swings the "
             "translated cube around the origin, 45 degrees off to the side")):
        s = small(f"Computer Graphics from Scratch, figure {figure}: {what}. The small cube marks the origin. "
                  "The transform is a list of steps, applied in the order written.", 600, 600)
        s["viewport"] = {"width": 1.25, "height": 1.25, "distance": 1}
        s["depth"] = {"near": 1, "far": 40}
        s["camera"] = {"eye": [0, 9, -3], "center": [0, 0, 3], "up": [0, 1, 0]}
        s["models"] = {"cube": cube()}
        s["instances"] = [{"model": "cube", "transform": {"scale": 0.15}},
                          {"model": "cube", "transform": steps}]
        write(f"cgfs-figure-{figure}.json", s)


def orthographic_scenes():
    # Catlike Coding's section 5.1: an orthographic camera keeps x and y whatever z. The
    # transformation grid seen from a corner: parallel edges stay parallel, far cubes stay as big as
    # near ones.
    s = small("Catlike Coding, 'Rendering 1: Matrices', section 5.1: the 10 x 10 x 10 transformation grid (cubes "
              "0.5 wide, 1 apart) seen by an orthographic camera from a corner. No cube shrinks with distance; "
              "depth is linear from near to far. GPU == CPU twin.", 800, 600)
    s["viewport"] = {"width": 20, "height": 15, "distance": 1, "projection": "orthographic"}
    s["depth"] = {"near": 1, "far": 60}
    s["camera"] = {"eye": [16, 12, -20], "center": [0, 0, 0], "up": [0, 1, 0]}
    s["models"] = {"cube": cube()}
    s["instances"] = [{"model": "cube", "transform": {"scale": 0.25},
                       "grid": {"count": [10, 10, 10], "spacing": [1, 1, 1]}}]
    write("catlike-orthographic.json", s)

    # Hard cases of the orthographic projection.
    s = small("Orthographic, edge-on: a triangle whose plane contains the viewing direction (x = 0, camera looking "
              "along +Z) projects to a line of zero area and draws nothing; beside it the same triangle turned by "
              "1e-3 degrees is a sliver a fraction of a pixel wide, and a triangle turned by 30 degrees draws "
              "normally. Expected: the edge-on triangle covers no pixel on either renderer. GPU == CPU twin.")
    s["viewport"] = {"width": 4, "height": 3, "distance": 1, "projection": "orthographic"}
    s["depth"] = {"near": 1, "far": 20}
    s["camera"] = {"position": [0, 0, 0]}
    s["models"] = {"tri": {"vertices": [[0, -1, 3], [0, 1, 4], [0, 0.2, 8]], "triangles": [[0, 1, 2, "red"]]}}
    s["instances"] = [
        {"model": "tri"},
        {"model": "tri", "transform": {"rotation": {"axis": "y", "degrees": 0.001}, "translation": [-0.9, 0, 0]}},
        {"model": "tri", "transform": {"rotation": {"axis": "y", "degrees": 30}, "translation": [0.9, 0, 0]}},
    ]
    write("hard/orthographic-edge-on.json", s)

    for reversed_z in (False, True):
        s = small("Orthographic, geometry at the near and far planes: squares exactly at z = near (depth 0, or 1 "
                  "reversed) and z = far, squares a hair inside and outside each, and a long triangle from in front of "
                  "near to beyond far, clipped at both. Depth is linear in z, so these land on the ends of the depth "
                  "range exactly as written. Expected: GPU == CPU twin; the truth may differ where float rounds a "
                  "depth at exactly 0 or 1 across the clip plane.")
        s["viewport"] = {"width": 8, "height": 6, "distance": 1, "projection": "orthographic"}
        s["depth"] = {"near": 2, "far": 10, "reversed": reversed_z}
        s["camera"] = {"position": [0, 0, 0]}
        square = {"vertices": [[-0.5, -0.5, 0], [0.5, -0.5, 0], [0.5, 0.5, 0], [-0.5, 0.5, 0]],
                  "triangles": [[0, 1, 2, "green"], [0, 2, 3, "green"]]}
        s["models"] = {"square": square,
                       "long": {"vertices": [[1.4, -2.8, 1], [3.9, -2.6, 12], [1.6, 2.8, 6]], "triangles": [[0, 1, 2, [255, 128, 0]]]}}
        s["instances"] = [{"model": "long"}] + [
            {"model": "square", "transform": {"translation": [x, y, z]}}
            for (x, y, z) in ((-2.5, 1.5, 2), (-1.2, 1.5, 2 + 1e-6), (0.1, 1.5, 2 - 1e-6),
                              (-2.5, -1.5, 10), (-1.2, -1.5, 10 - 1e-6), (0.1, -1.5, 10 + 1e-6))]
        write("hard/orthographic-near-far" + ("-reversed" if reversed_z else "") + ".json", s)


def grid_scenes():
    # The chapter's question, "What if we wanted to render one million cubes?", as one instance
    # with a 100 x 100 x 100 grid: cubes 0.6 wide, 1 apart, seen whole from above a corner.
    s = hd("One million cubes (the chapter's question, section 'Models and Instances'): one instance of the "
           "chapter's cube with a 100 x 100 x 100 grid, cubes 0.6 wide and 1 apart, 12 million triangles.")
    s["depth"] = {"near": 1, "far": 400}
    s["camera"] = {"eye": [90, 70, -160], "center": [0, 0, 0], "up": [0, 1, 0]}
    s["models"] = {"cube": cube()}
    s["instances"] = [{"model": "cube", "transform": {"scale": 0.3},
                       "grid": {"count": [100, 100, 100], "spacing": [1, 1, 1]}}]
    write("one-million-cubes.json", s)

    # Catlike Coding's transformation grid (Rendering 1): 10 x 10 x 10 points 1 apart, centred on
    # the origin, seen by a camera on the -z side with a 60-degree vertical field of view (Unity's
    # default): Vh = 2 tan 30 at d = 1.
    s = small("Catlike Coding, 'Rendering 1: Matrices': the 10 x 10 x 10 transformation grid, points 1 apart "
              "centred on the origin (GetCoordinates), as cubes 0.5 wide; camera at (0, 1, -16), 60-degree field of view.",
              800, 600)
    vh = 2 * math.tan(math.radians(30))
    s["viewport"] = {"width": vh * 800 / 600, "height": vh, "distance": 1}
    s["camera"] = {"position": [0, 1, -16]}
    s["models"] = {"cube": cube()}
    s["instances"] = [{"model": "cube", "transform": {"scale": 0.25},
                       "grid": {"count": [10, 10, 10], "spacing": [1, 1, 1]}}]
    write("catlike-grid.json", s)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="Writes the project's generated scene files.")
    parser.add_argument("--out", help="the directory to write into (default: scenes)")
    OUT_DIR = os.path.abspath(parser.parse_args().out or OUT_DIR)
    far_scenes()
    near_plane_scenes()
    depth_scenes()
    degenerate_scene()
    transform_scenes()
    bench_scene()
    grid_scenes()
    transform_order_scenes()
    orthographic_scenes()
