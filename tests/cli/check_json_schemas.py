#!/usr/bin/env python3
"""Runs the real twinraster executable for each --json output and validates what it prints
against that output's schema in docs/schemas/. Each schema is also proven strict on the real
output: a copy with one key missing from any object, or with one key too many, must fail.

Run as: check_json_schemas.py --exe build/bin/twinraster --source <repository>
Exits 1 naming every failure; CTest runs it (tests/cli/CMakeLists.txt)."""

import argparse
import base64
import copy
import json
import os
import struct
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("check_json_schemas: this python3 has no jsonschema module (apt-get install python3-jsonschema)")

# A camera at the origin and a vertex in its plane (camera z = 0): clip w is 0, so the divided
# coordinates are not finite and print as null, which the explain schema must allow.
# The GPU process made to fail on purpose (the test-only variable of gpu/isolated_gpu.hpp).
GPU_CRASH = "render whose Vulkan driver crashes: the twin's image and the report still written"
GPU_HANG = "render whose Vulkan driver hangs past --timeout"
NO_SSE = "render --backend both where the twin has no rules: the difference judged"
ENVIRONMENTS = {GPU_CRASH: {"TWINRASTER_TEST_GPU_FAULT": "abort"}, GPU_HANG: {"TWINRASTER_TEST_GPU_FAULT": "hang"},
                NO_SSE: {"GALLIUM_OVERRIDE_CPU_CAPS": "nosse"}}

W_ZERO_SCENE = {
    "canvas": {"width": 8, "height": 6},
    "viewport": {"width": 1, "height": 1, "distance": 1},
    "camera": {"position": [0, 0, 0]},
    "models": {"m": {"vertices": [[1, 0, 0], [0, 1, 5], [1, 1, 5]], "triangles": [[0, 1, 2, "red"]]}},
    "instances": [{"model": "m"}],
}


def tiny_gltf():
    """A .gltf of one triangle in a data: URI, placed by two nodes: bench --loaders' input."""
    data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    return {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": len(data)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "nodes": [{"mesh": 0, "rotation": [0, 0.6, 0, 0.8]}, {"mesh": 0, "translation": [2, 0, 0], "scale": [1, 2, 1]}],
        "scenes": [{"nodes": [0, 1]}],
    }


def objects(value, path="$"):
    """Every object in `value` with its path; of each array, only the first element."""
    if isinstance(value, dict):
        yield path, value
        for key, child in value.items():
            yield from objects(child, f"{path}.{key}")
    elif isinstance(value, list) and value:
        yield from objects(value[0], f"{path}[0]")


def at(document, path):
    node = document
    for part in path[2:].replace("[0]", ".0").split(".") if path != "$" else []:
        node = node[0] if part == "0" else node[part]
    return node


def strictness_failures(validator, document):
    """The mutations of a valid document that the schema wrongly accepts."""
    failures = []
    for path, obj in objects(document):
        for key in list(obj):
            mutated = copy.deepcopy(document)
            del at(mutated, path)[key]
            if validator.is_valid(mutated):
                failures.append(f"accepts {path} without \"{key}\"")
        mutated = copy.deepcopy(document)
        at(mutated, path)["unexpected_key"] = None
        if validator.is_valid(mutated):
            failures.append(f"accepts an extra key in {path}")
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    scenes = os.path.join(args.source, "scenes")
    transforms = os.path.join(scenes, "cgfs-transforms.json")

    with tempfile.TemporaryDirectory(prefix="twinraster-schemas-") as tmp:
        out = lambda name: os.path.join(tmp, name)
        # A glTF triangle seen by a perspective camera without zfar: an infinite far plane.
        triangle = base64.b64encode(struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)).decode()
        with open(out("infinite.gltf"), "w") as f:
            json.dump({"asset": {"version": "2.0"},
                       "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64," + triangle}],
                       "bufferViews": [{"buffer": 0, "byteLength": 36}],
                       "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
                       "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                       "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
                       "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 3]}],
                       "scenes": [{"nodes": [0, 1]}]}, f)
        engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
        # (what, schema, arguments, standard input, expected exit code, extra check on the document)
        cases = [
            ("explain of a glTF file: the node chain of each instance, by name", "explain",
             ["explain", engine, "--json", "--instance", "3", "--vertex", "0"], None, 0,
             lambda d: d["instances"][0]["transform_steps"][0]["kind"] == "matrix"
             and d["instances"][0]["transform_steps"][0]["label"].startswith("node ")
             and d["instances"][0]["transform_steps"][-1]["kind"] == "scale"
             and d["instances"][0]["transform_steps"][-1]["matrix"][2][2] == -1),
            ("explain of a glTF camera without zfar: the far plane is infinite", "explain",
             ["explain", out("infinite.gltf"), "--json"], None, 0,
             lambda d: d["depth"]["far"] is None and d["depth"]["near"] == 0.1
             and all(all(c is not None for c in corner) for corner in d["frustum"]["camera"]["far"])),
            ("explain", "explain", ["explain", transforms, "--json"], None, 0,
             lambda d: len(d["instances"]) == 2 and len(d["instances"][0]["vertices"]) == 8),
            ("explain --instance --vertex", "explain",
             ["explain", transforms, "--json", "--instance", "1", "--vertex", "6"], None, 0,
             lambda d: len(d["instances"]) == 1 and len(d["instances"][0]["vertices"]) == 1),
            ("explain of a vertex where w = 0, from standard input", "explain", ["explain", "-", "--json"],
             json.dumps(W_ZERO_SCENE), 0,
             lambda d: d["scene"] == "<stdin>" and d["instances"][0]["vertices"][0]["ndc"][0] is None),
            ("explain of a grid scene: 16 of 1000 instances traced, the grid described", "explain",
             ["explain", os.path.join(scenes, "catlike-grid.json"), "--json"], None, 0,
             lambda d: d["instance_count"] == 1000 and len(d["instances"]) == 16 and d["grids"][0]["copies"] == 1000
             and d["instances"][11]["grid_copy"] == {"instance": 0, "ijk": [1, 1, 0]}),
            ("explain of a lit scene: the normal matrix and each vertex's light", "explain",
             ["explain", os.path.join(scenes, "normals-stretched-square.json"), "--json", "--vertex", "0"], None, 0,
             lambda d: d["lighting"]["ambient"] == 0 and d["instances"][0]["shading"] == "flat"
             and d["instances"][0]["normal_matrix"][0][0] == 0.5
             and abs(d["instances"][0]["vertices"][0]["light"]["intensity"] - 2 / 5 ** 0.5) < 1e-12),
            ("explain of an OBJ file on its own", "explain",
             ["explain", os.path.join(scenes, "meshes", "gem.obj"), "--json", "--vertex", "0"], None, 0,
             lambda d: d["scene"] == "gem" and d["lighting"] is not None and d["instances"][0]["shading"] == "flat"),
            ("render of a lit scene on both backends", "render",
             ["render", os.path.join(scenes, "lit-gouraud.json"), "--json", "-o", out("lit.png")], None, 0,
             lambda d: d["differing_pixels"] == 0),
            ("render --backend gpu", "render", ["render", transforms, "--json", "--backend", "gpu", "-o", out("g.png")],
             None, 0, lambda d: d["backends"]["cpu"] is None and d["differing_pixels"] is None),
            ("render --backend cpu", "render", ["render", transforms, "--json", "--backend", "cpu", "-o", out("c.png")],
             None, 0, lambda d: d["backends"]["gpu"] is None and d["diff"] is None),
            ("render --backend both", "render", ["render", transforms, "--json", "-o", out("b.png")], None, 0,
             lambda d: d["rules"] == "vulkan" and d["differing_pixels"] == 0
             and d["backends"]["gpu"]["output"] == out("b-gpu.png") and d["backends"]["gpu"]["status"] == "rendered"
             and d["backends"]["gpu"]["driver"].startswith("Mesa ") and d["twin_rules"]["exact"]
             and d["twin_rules"]["text"].startswith("lavapipe rules, Mesa " + d["twin_rules"]["mesa"])),
            (GPU_CRASH, "render", ["render", transforms, "--json", "-o", out("crash.png")], None, 5,
             lambda d: d["backends"]["gpu"]["status"] == "crashed" and d["backends"]["gpu"]["output"] is None
             and "(SIGABRT)" in d["backends"]["gpu"]["problem"] and d["backends"]["cpu"]["output"] == out("crash-cpu.png")
             and d["differing_pixels"] is None and d["twin_rules"] is not None
             and d["verdict"] == "crashed" and d["exit_code"] == 5 and "(SIGABRT)" in d["reason"]),
            (GPU_HANG, "render", ["render", transforms, "--json", "--timeout", "1", "--backend", "gpu",
             "-o", out("hang.png")], None, 5,
             lambda d: d["backends"]["gpu"]["status"] == "timed out" and d["twin_rules"] is None),
            ("render --rules book", "render", ["render", transforms, "--json", "--rules", "book", "-o", out("book.png")],
             None, 0, lambda d: d["rules"] == "book" and d["backends"]["gpu"] is None
             and d["backends"]["cpu"]["output"] == out("book.png") and d["differing_pixels"] is None),
            ("render a scene from standard input", "render", ["render", "-", "--json", "--backend", "cpu", "-o",
             out("s.png")], open(transforms).read(), 0, lambda d: d["scene"] == "-"),
            ("render several scenes: JSON Lines, one object per scene", "render",
             ["render", transforms, os.path.join(scenes, "lookat.json"), "--json", "--backend", "cpu", "-o", out("many")],
             None, 0, lambda ds: [d["scene"] for d in ds] == [transforms, os.path.join(scenes, "lookat.json")] and
             ds[1]["backends"]["cpu"]["output"] == os.path.join(out("many"), "lookat.png") and ds[1]["instances"] == 3
             and all(d["verdict"] == "rendered" and d["exit_code"] == 0 for d in ds)),
            ("render several scenes, one unreadable: its line too, verdict error", "render",
             ["render", transforms, out("broken.json"), "--json", "--backend", "cpu", "-o", out("some")], None, 2,
             lambda ds: [d["verdict"] for d in ds] == ["rendered", "error"] and ds[1]["exit_code"] == 2
             and ds[1]["reason"].startswith(out("broken.json") + ": line 1, column ") and ds[1]["width"] is None
             and ds[1]["backends"] == {"gpu": None, "cpu": None}),
            ("render of one scene that cannot be read, --rules book", "render",
             ["render", out("broken.json"), "--json", "--rules", "book", "-o", out("broken.png")], None, 2,
             lambda d: d["verdict"] == "error" and d["rules"] == "book" and d["twin_rules"] is None),
            ("verify lavapipe's image", "verify",
             ["verify", transforms, out("b-gpu.png"), "--json", "--subpixel-bits", "8"], None, 0,
             lambda d: d["passed"] and d["verdict"] == "passed" and d["pixels"]["violations"] == 0 and d["worst"] is None
             and d["rules_from"] == {"subpixel_bits": "option", "strict_lines": "notes"} and d["alpha"]["not_opaque"] == 0
             and d["map"] == out("b-gpu-map.png") and d["pixels"]["certain"] + d["pixels"]["uncertain"] == 600 * 600),
            ("verify another scene's image: violations", "verify",
             ["verify", transforms, out("other.png"), "--json", "--no-map"], None, 1,
             lambda d: not d["passed"] and d["verdict"] == "failed" and d["worst"]["distance"] > 0 and len(d["worst"]["allowed"]) >= 1
             and d["map"] is None),
            ("verify --coverage of the twin's image, its clear colour given", "verify",
             ["verify", transforms, out("c.png"), "--coverage", "--background", "255,255,255", "--json"], None, 0,
             lambda d: d["format"] == "twinraster.verify-coverage/2" and d["passed"] and d["background_from"] == "option"
             and d["pixels"]["violations"] == 0 and d["first_spill"] is None and d["map"] == out("c-map.png")
             and d["pixels"]["certainly_covered"] + d["pixels"]["certainly_uncovered"] + d["pixels"]["uncertain"]
             == 600 * 600),
            ("verify --coverage of another scene's image: spills and holes", "verify",
             ["verify", transforms, out("other.png"), "--coverage", "--hole-tolerance", "0.5", "--json", "--no-map"],
             None, 1,
             lambda d: d["verdict"] == "failed" and d["pixels"]["spills"] > 0 and d["pixels"]["holes"] > 0
             and d["first_spill"]["colour"] != [255, 255, 255] and d["first_hole"]["colour"] == [255, 255, 255]
             and d["pixels"]["holes_allowed"] > 0 and d["map"] is None),
            ("render --verify", "render", ["render", transforms, "--json", "--verify", "-o", out("v.png")], None, 0,
             lambda d: d["verify"]["image"] == "gpu" and d["verify"]["passed"] and d["verify"]["subpixel_bits"] == 8
             and d["verify"]["map"] == out("v-gpu-map.png")),
            (NO_SSE, "render", ["render", os.path.join(scenes, "hard", "depth-ratio-1e-4.json"), "--json", "-o",
                                out("nosse.png")], None, 6,
             lambda d: d["differing_pixels"] > 0 and not d["twin_rules"]["exact"]
             and d["verify"]["verdict"] == "inconclusive" and d["verify"]["pixels"]["violations"] == 0
             and d["verdict"] == "inconclusive" and d["exit_code"] == 6
             and d["verify"]["map"] is None),
            ("compare identical", "compare", ["compare", out("b-gpu.png"), out("b-cpu.png"), "--json"], None, 0,
             lambda d: d["identical"] and d["diff"] is None),
            ("compare different", "compare",
             ["compare", out("c.png"), out("other.png"), "--json", "--diff", out("d.png")], None, 1,
             lambda d: d["differing_pixels"] > 0 and d["diff"] == out("d.png")),
            ("compare different sizes", "compare", ["compare", out("c.png"), out("small.png"), "--json"], None, 1,
             lambda d: not d["same_size"] and d["differing_pixels"] is None),
            ("bench, every method", "bench",
             ["bench", "--runs", "1", "--only", "cgfs-scene", "--scenes", scenes, "--json"], None, 0,
             lambda d: len(d["rows"]) >= 8 and len(d["summary"]["cpu_twin_over_lavapipe"]) >= 1
             and len(d["summary"]["cpu_twin_over_swiftshader"]) == 1),
            ("bench --scale, two small counts", "bench-scale",
             ["bench", "--scale", "--counts", "1000,64", "--runs", "1", "--json", "-q"], None, 0,
             lambda d: [r["instances"] for r in d["rows"]] == [64, 1000] and all(r["identical"] for r in d["rows"])
             and d["rows"][1]["triangles"] == 12000 and d["processes"] is None
             and [len(r["png_encoders"]) for r in d["rows"]] == [5, 5]),
            ("bench --scale with the fixed costs, a batch of 12", "bench-scale",
             ["bench", "--scale", "--counts", "8", "--runs", "1", "--scenes", scenes, "--batch-scenes", "12", "--json",
              "-q"], None, 0,
             # Measured, not ordered: on a loaded machine a scene's process may time under the
             # floor's (the bench reports that ratio; a test cannot assert it).
             lambda d: d["processes"]["batch_scenes"] == 12 and d["processes"]["batch_ms"] > 0
             and d["processes"]["cpu_scene_ms"] > 0 and d["processes"]["floor_ms"] > 0),
            ("bench --verify, the chapter's scene", "bench-verify",
             ["bench", "--verify", "--only", "cgfs-transforms", "--runs", "1", "--scenes", scenes, "--json", "-q"], None, 0,
             lambda d: len(d["rows"]) == 1 and d["rows"][0]["violations"] == 0 and d["rows"][0]["triangles"] == 24),
            ("bench --loaders, a tiny .gltf", "bench-loaders",
             ["bench", "--loaders", "--gltf", out("tiny.gltf"), "--runs", "1", "--json", "-q"], None, 0,
             lambda d: [r["loader"] for r in d["rows"]] == ["gltf", "json-exact", "json-float"]
             and d["instances"] == 2 and d["triangles"] == 1 and all(r["same_counts"] for r in d["rows"])
             and all(r["processes"]["render_ms"] > 0 for r in d["rows"]) and d["process_floor"]["help_ms"] > 0),
            ("bench, depth scenes, two methods", "bench",
             ["bench", "--runs", "1", "--only", "depth-ratio-1e-1", "--methods", "compose-f32,cpu-twin", "--scenes",
              scenes, "--json", "-q"], None, 0,
             lambda d: d["summary"]["cpu_twin_over_lavapipe"] == [] and d["summary"]["cpu_twin_over_swiftshader"] == []
             and d["summary"]["far_1e7_vertex_error_px"]["compose-f32"] is None),
            ("bench, a lit scene: every row's colour error", "bench",
             ["bench", "--runs", "1", "--only", "lit-flat", "--methods", "compose-f32,cpu-twin", "--scenes", scenes,
              "--json", "-q"], None, 0,
             lambda d: all(r["colour_error"] is not None and r["colour_pixels"] > 0 for r in d["rows"])),
        ]
        # The second and third images compare: another scene of the same size, and a smaller one.
        setup = [
            ["render", os.path.join(scenes, "cgfs-scene.json"), "--backend", "cpu", "-o", out("other.png")],
            ["render", "-", "--backend", "cpu", "-o", out("small.png")],
        ]
        with open(out("tiny.gltf"), "w") as f:
            json.dump(tiny_gltf(), f)
        with open(out("broken.json"), "w") as f:
            f.write('{"canvas": ')
        for i, command in enumerate(setup):
            subprocess.run([args.exe] + command, check=True, capture_output=True,
                           input=json.dumps(W_ZERO_SCENE).encode() if i == 1 else None)

        failures = []
        validators = {}
        for what, schema_name, arguments, stdin, expected_exit, check in cases:
            if schema_name not in validators:
                with open(os.path.join(args.source, "docs", "schemas", f"{schema_name}.schema.json")) as f:
                    schema = json.load(f)
                jsonschema.Draft202012Validator.check_schema(schema)
                validators[schema_name] = jsonschema.Draft202012Validator(schema)
            validator = validators[schema_name]
            failures_before = len(failures)
            run = subprocess.run([args.exe] + arguments, input=stdin.encode() if stdin else None,
                                 capture_output=True, stdin=None if stdin else subprocess.DEVNULL,
                                 env={**os.environ, **ENVIRONMENTS.get(what, {})})
            if run.returncode != expected_exit:
                failures.append(f"{what}: exit code {run.returncode}, expected {expected_exit}: {run.stderr.decode()}")
                continue
            # One JSON document, or JSON Lines (render with several scenes): one document per line.
            try:
                documents = [json.loads(run.stdout)]
            except json.JSONDecodeError:
                try:
                    documents = [json.loads(line) for line in run.stdout.splitlines() if line.strip()]
                except json.JSONDecodeError as e:
                    failures.append(f"{what}: standard output is neither one JSON document nor JSON Lines: {e}")
                    continue
            errors = []
            for document in documents:
                errors += sorted(validator.iter_errors(document), key=lambda e: list(e.path))
            for error in errors:
                where = "$" + "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in error.path)
                failures.append(f"{what}: {where}: {error.message}")
            checked = documents[0] if len(documents) == 1 else documents
            if not errors and not check(checked):
                failures.append(f"{what}: valid, but not what this case expects:\n{json.dumps(checked, indent=2)}")
            if not errors:
                for document in documents:
                    failures += [f"{what}: the {schema_name} schema {f}" for f in strictness_failures(validator, document)]
            print(f"{what}: {'ok' if len(failures) == failures_before else 'FAILED'}")

    for failure in failures:
        print("FAIL " + failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
