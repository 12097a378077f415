#!/usr/bin/python3
"""Times the moving chain page (explain --html) in headless Chromium, opened from file:// as a
learner opens it: from a control change to the new picture and numbers on the page, medians over
repeated changes of the camera's first control; then the twin's draw alone, in the browser's module
(tr_redraw, one thread) against the native executable (render --backend cpu --threads 1: its
setup + draw + readback), on the same state, in the same run.

Scenes: the chapter's scene (scenes/cgfs-transforms.json, 600 x 600), scenes/lit-gouraud.json, and
a 10,000-instance grid (the chapter's cube, 25 x 20 x 20, written from scenes/catlike-grid.json).

With --baseline OTHER_EXE, the pages OTHER_EXE writes (an earlier build, say) are timed in the same
run, each scene's right after this build's, and the table gives each change's time as a ratio.

Usage: scripts/bench-chain-page.py [--exe build/bin/twinraster] [--baseline EXE] [--changes 41]
                                   [--draws 15] [--out DIR] [--json FILE]
Prints a table; --json writes the figures (format twinraster.bench-chain-page/1; with --baseline,
rows for both, each with its "exe")."""
import argparse
import hashlib
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def browser():
    options = Options()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--window-size=1400,1000"):
        options.add_argument(a)
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"),
                              options=options)
    driver.set_script_timeout(600)
    return driver


def grid_scene(work):
    scene = json.load(open(os.path.join(ROOT, "scenes", "catlike-grid.json")))
    scene["comment"] = "The chapter's cube as a grid of 10,000 instances (25 x 20 x 20), for the page's bench."
    scene["instances"][0]["grid"]["count"] = [25, 20, 20]
    path = os.path.join(work, "grid-10000.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def page_of(exe, scene, work, name):
    page = os.path.join(work, name + ".html")
    r = subprocess.run([exe, "explain", scene, "--html", page], capture_output=True, text=True)
    if r.returncode != 0 or r.stderr:
        sys.exit("bench-chain-page: explain --html %s: %s" % (scene, r.stderr.strip()))
    return page


# Runs in the page: `changes` moves of the camera's first control, alternating up and down by a
# small step as a drag does, each timed from the change to the state drawn (picture and panels).
TIME_CHANGES = """
const [changes, done] = [arguments[0], arguments[arguments.length - 1]];
const api = window.twinrasterPage;
api.ready.then(async () => {
  const slider = document.querySelector('#twinraster-controls fieldset input[type=range]');
  const id = slider.id.replace(/-slider$/, '');
  const low = Number(slider.min), high = Number(slider.max), start = Number(slider.value);
  const step = (high - low) / 200;
  const wall = [], module = [];
  for (let i = 0; i < changes; ++i) {
    const value = Math.min(high, Math.max(low, start + (i % 2 ? -step : step) * (1 + (i % 5))));
    const t0 = performance.now();
    await api.setControl(id, value);
    wall.push(performance.now() - t0);
    module.push(api.lastUpdateMs);
  }
  done({control: slider.getAttribute('aria-label'), wall, module, scene: api.sceneText(),
        draws: api.redrawMs(arguments[1])});
}, (e) => done({error: String(e)}));
"""

NATIVE_TIMES = re.compile(r"CPU twin, 1 thread\)\s+setup ([0-9.]+) ms, draw ([0-9.]+) ms, readback ([0-9.]+) ms")


def native_draws(exe, scene, work, runs):
    times = []
    for _ in range(runs):
        r = subprocess.run([exe, "render", scene, "--backend", "cpu", "--threads", "1", "-o",
                            os.path.join(work, "native.png")], capture_output=True, text=True)
        m = NATIVE_TIMES.search(r.stdout)
        if r.returncode != 0 or not m:
            sys.exit("bench-chain-page: render %s: %s%s" % (scene, r.stdout, r.stderr))
        times.append(sum(float(x) for x in m.groups()))
    return times


def bench(driver, exe, name, scene, work, changes, draws):
    work = os.path.join(work, hashlib.sha256(os.path.realpath(exe).encode()).hexdigest()[:12])
    os.makedirs(work, exist_ok=True)
    page = page_of(exe, scene, work, name)
    driver.get("file://" + page)
    got = driver.execute_async_script(TIME_CHANGES, changes, draws)
    if "error" in got:
        sys.exit("bench-chain-page: %s: the page did not get ready: %s" % (name, got["error"]))
    state = os.path.join(work, name + "-state.json")
    with open(state, "w") as f:
        f.write(got["scene"])
    native = native_draws(exe, state, work, draws)
    size = os.path.getsize(page)
    return {"scene": name, "exe": exe, "page_bytes": size, "control": got["control"], "changes": changes,
            "change_to_picture_ms": statistics.median(got["wall"]),
            "module_update_ms": statistics.median(got["module"]),
            "wasm_draw_ms": statistics.median(got["draws"]), "native_draw_ms": statistics.median(native),
            "draws": draws}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "bin", "twinraster"))
    parser.add_argument("--baseline", help="another twinraster whose pages are timed beside --exe's")
    parser.add_argument("--changes", type=int, default=41)
    parser.add_argument("--draws", type=int, default=15)
    parser.add_argument("--out", help="keep the pages and states here (default: a temporary folder)")
    parser.add_argument("--json", help="write the figures here")
    a = parser.parse_args()
    work = a.out or tempfile.mkdtemp(prefix="bench-chain-page.")
    os.makedirs(work, exist_ok=True)
    scenes = [("chapter", os.path.join(ROOT, "scenes", "cgfs-transforms.json")),
              ("lit-gouraud", os.path.join(ROOT, "scenes", "lit-gouraud.json")),
              ("grid-10000", grid_scene(work))]
    exes = [a.exe] + ([a.baseline] if a.baseline else [])
    driver = browser()
    try:
        # The browser's first page runs slower while its compiler warms up: that run is left out.
        bench(driver, exes[-1], scenes[0][0], scenes[0][1], work, a.changes, a.draws)
        rows = [bench(driver, exe, name, scene, work, a.changes, a.draws) for name, scene in scenes for exe in exes]
    finally:
        driver.quit()
    print("%-12s %-9s %10s %14s %12s %12s %12s %7s" % ("scene", "build", "page", "change->shown", "module",
                                                       "wasm draw", "native draw", "ratio"))
    for r in rows:
        print("%-12s %-9s %8.0f KB %11.2f ms %9.2f ms %9.2f ms %9.2f ms %6.2fx" % (
            r["scene"], "baseline" if r["exe"] != a.exe else "this", r["page_bytes"] / 1000,
            r["change_to_picture_ms"], r["module_update_ms"], r["wasm_draw_ms"], r["native_draw_ms"],
            r["wasm_draw_ms"] / max(r["native_draw_ms"], 1e-9)))
    if a.baseline:
        for this, base in zip(rows[0::2], rows[1::2]):
            print("%-12s change->shown: this build %.2f ms, baseline %.2f ms (%.2fx faster)" % (
                this["scene"], this["change_to_picture_ms"], base["change_to_picture_ms"],
                base["change_to_picture_ms"] / max(this["change_to_picture_ms"], 1e-9)))
    print("medians: change->shown over %d changes of each scene's first camera control; draws over %d "
          "(wasm: tr_redraw in the page; native: render --backend cpu --threads 1, setup + draw + readback)"
          % (a.changes, a.draws))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"format": "twinraster.bench-chain-page/1", "rows": rows}, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
