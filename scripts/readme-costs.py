#!/usr/bin/python3
"""Writes the README's "What a scene costs" table from a bench run's JSON, so that every figure in
it is one that run measured:

  scripts/readme-costs.py [--check] [SCALE.json VERIFY.json [LOADERS.json] README.md]

The defaults are docs/generated/bench/scale.json, verify.json and loaders.json (what `bench --scale
--out docs/generated/bench`, `bench --verify --out ...` and `bench --loaders --out ...` write) and
README.md; without LOADERS.json the table has no loaders' row. The
table is the lines between the two marker comments. --check rewrites nothing and exits 1 when the
README's table is not what the JSON says (a CTest test runs it).
"""
import argparse
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN = "<!-- costs: scripts/readme-costs.py writes this table from docs/generated/bench -->"
END = "<!-- end of costs -->"


def scene_name(row):
    return os.path.basename(row["scene"])


def loaders_row(loaders):
    rows = {r["loader"]: r for r in loaders["rows"]}
    gltf, json_row = loaders["rows"][0], rows["json-exact"]
    return ("`%s` (%s triangles), file to Scene, against the same scene as JSON: time and peak memory per triangle"
            % (os.path.basename(loaders["asset"]), format(loaders["triangles"], ",")),
            "%.1f ns, %.0f B against %.1f ns, %.0f B (%.1fx, %.1fx)"
            % (gltf["load_ns_per_triangle"], gltf["peak_rss_bytes_per_triangle"], json_row["load_ns_per_triangle"],
               json_row["peak_rss_bytes_per_triangle"], json_row["load_ratio"], json_row["peak_rss_ratio"]))


def table(scale, verify, loaders=None):
    p = scale["processes"]
    if p is None:
        raise SystemExit("readme-costs.py: the scale run measured no fixed costs (no chapter scene)")
    frame = scale["rows"][-1]
    encoders = {e["encoder"]: e for e in frame["png_encoders"]}
    ours, level1 = encoders["runs (level 1, the default)"], encoders["libdeflate 1"]
    in_process = {scene_name(r): r for r in verify["rows"]}
    processes = {scene_name(r): r for r in verify["processes"]}
    scenes = [("the chapter's scene", "cgfs-transforms.json"), ("lit-gouraud", "lit-gouraud.json"),
              ("the million cubes", "one-million-cubes.json")]
    floor = "not measured" if p["driver_floor_ms"] is None else "%.1f ms" % p["driver_floor_ms"]
    rows = [
        ("the process floor, `twinraster --help`", "%.1f ms" % p["floor_ms"]),
        ("the chapter's scene, `render --backend cpu`, a whole process",
         "%.1f ms (%.2fx the floor)" % (p["cpu_scene_ms"], p["cpu_scene_over_floor"])),
        ("the Vulkan floor: `twinraster --version` with lavapipe's driver alone", floor),
        ("the chapter's scene, `render --backend gpu`, the GPU child process included", "%.1f ms" % p["gpu_scene_ms"]),
        ("%s scenes of %dx%d, both backends, `--report` and `--junit`, one process"
         % (format(p["batch_scenes"], ","), p["batch_side"], p["batch_side"]), "%.2f s" % (p["batch_ms"] / 1000)),
        ("a 1920x1080 PNG at the default level (the frame of the largest count, %s cubes)"
         % format(frame["instances"], ","),
         "%.2f ms, %.0f MB/s (libdeflate level 1: %.2f ms)" % (ours["ms"], ours["mb_per_s"], level1["ms"])),
    ]
    for label, name in scenes:
        if name in processes:
            r = processes[name]
            rows.append(("`verify` against `render`, whole processes, %s: passing / failing" % label,
                         "%.2fx / %.2fx (%.1f / %.1f ms against %.1f)"
                         % (r["passing_ratio"], r["failing_ratio"], r["verify_passing_ms"], r["verify_failing_ms"],
                            r["render_ms"])))
    rows.append(("the verifier against the twin's draw, in one process: %s"
                 % " / ".join(label for label, name in scenes if name in in_process),
                 " / ".join("%.2fx" % in_process[name]["ratio"] for _, name in scenes if name in in_process)))
    if loaders is not None:
        rows.append(loaders_row(loaders))
    lines = ["| what | measured |", "|---|---|"]
    lines += ["| %s | %s |" % row for row in rows]
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--check", action="store_true")
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    files = args.files or [os.path.join(ROOT, "docs/generated/bench/scale.json"),
                           os.path.join(ROOT, "docs/generated/bench/verify.json"),
                           os.path.join(ROOT, "docs/generated/bench/loaders.json"), os.path.join(ROOT, "README.md")]
    if len(files) not in (3, 4):
        parser.error("give SCALE.json VERIFY.json [LOADERS.json] README.md, or none")
    with open(files[0]) as f:
        scale = json.load(f)
    with open(files[1]) as f:
        verify = json.load(f)
    loaders = None
    if len(files) == 4:
        with open(files[2]) as f:
            loaders = json.load(f)
    files = files[:2] + files[-1:]
    with open(files[2]) as f:
        readme = f.read().split("\n")
    if BEGIN not in readme or END not in readme:
        raise SystemExit("readme-costs.py: %s has no table markers" % files[2])
    begin, end = readme.index(BEGIN), readme.index(END)
    wanted = readme[:begin + 1] + table(scale, verify, loaders) + readme[end:]
    if args.check:
        if wanted != readme:
            print("readme-costs.py: %s's cost table is not what %s and %s say; run scripts/readme-costs.py"
                  % (files[2], files[0], files[1]), file=sys.stderr)
            return 1
        return 0
    with open(files[2], "w") as f:
        f.write("\n".join(wanted))
    return 0


if __name__ == "__main__":
    sys.exit(main())
