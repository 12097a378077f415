#!/usr/bin/python3
"""Times two twinraster builds side by side as whole processes, the way bench --scale does
(posix_spawn, wait, wall time): `--help` (the process floor) and `render -q
scenes/cgfs-transforms.json --backend cpu -o OUT.png`, the four commands in turn so that the
machine's drift is shared, and prints the medians and each build's ratio to its own floor. Each
build writes its own PNG in a fresh temporary directory, replaced every run.

  scripts/cpu-scene-floor.py BEFORE AFTER [--runs 61]
"""
import argparse
import os
import statistics
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "scenes", "cgfs-transforms.json")


def timed(argv, devnull):
    """Milliseconds from spawning argv to its exit; its output thrown away."""
    files = [(os.POSIX_SPAWN_DUP2, devnull, 1), (os.POSIX_SPAWN_DUP2, devnull, 2)]
    start = time.perf_counter()
    pid = os.posix_spawn(argv[0], argv, os.environ, file_actions=files)
    _, status = os.waitpid(pid, 0)
    elapsed = (time.perf_counter() - start) * 1000
    if status != 0:
        raise SystemExit(f"{' '.join(argv)} did not exit 0")
    return elapsed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--runs", type=int, default=61)
    args = parser.parse_args()
    builds = {"before": os.path.abspath(args.before), "after": os.path.abspath(args.after)}
    times = {(name, kind): [] for name in builds for kind in ("help", "render")}
    devnull = os.open(os.devnull, os.O_WRONLY)
    with tempfile.TemporaryDirectory(prefix="twinraster-floor-") as out:
        for run in range(args.runs + 2):  # the first two warm the page cache
            for name, exe in builds.items():
                floor = timed([exe, "--help"], devnull)
                render = timed([exe, "render", "-q", SCENE, "--backend", "cpu", "-o",
                                os.path.join(out, name + ".png")], devnull)
                if run >= 2:
                    times[(name, "help")].append(floor)
                    times[(name, "render")].append(render)
    for name in builds:
        floor, render = (statistics.median(times[(name, kind)]) for kind in ("help", "render"))
        print(f"{name:6s}  --help {floor:5.2f} ms  render {render:5.2f} ms  {render / floor:4.2f}x its floor")


if __name__ == "__main__":
    main()
