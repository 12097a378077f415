#!/usr/bin/python3
"""Opens twinraster's pages in headless Chromium (Debian's chromium and chromium-driver, through
python3-selenium) and checks what a reader sees: every image loads, no console error, the numbers
equal the matching --json output, failures come first, a 1,000-scene report opens in seconds, and
names from scene files are shown as text, never run as markup. Saves screenshots for the README.

Usage: check_pages.py CASE --exe TWINRASTER --source REPO --work DIR [--screenshots DIR]
CASE: batch, crashes, thousand, hostile, chain, bench."""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
import urllib.parse

from selenium import webdriver
from selenium.common.exceptions import NoAlertPresentException
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("FAIL: " + message, file=sys.stderr)
    return condition


def run(args, env=None, expect=(0,), cwd=None):
    full_env = dict(os.environ)
    full_env.update(env or {})
    r = subprocess.run(args, capture_output=True, text=True, env=full_env, cwd=cwd)
    if r.returncode not in expect:
        sys.exit("%s exited %d (expected %s)\nstdout:\n%s\nstderr:\n%s" % (" ".join(args), r.returncode, expect, r.stdout[-4000:], r.stderr[-4000:]))
    return r


def browser(width=1400, height=1000):
    options = Options()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--allow-file-access-from-files", "--window-size=%d,%d" % (width, height)):
        options.add_argument(a)
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"), options=options)


def open_page(driver, path):
    start = time.monotonic()
    driver.get("file://" + os.path.abspath(path))
    return time.monotonic() - start


def check_images_load(driver, what):
    """Scrolls every <img> into view (they load lazily) and checks that each one decoded."""
    images = driver.find_elements(By.TAG_NAME, "img")
    for img in images:
        driver.execute_script("arguments[0].scrollIntoView()", img)
    deadline = time.monotonic() + 20
    broken = []
    while time.monotonic() < deadline:
        broken = driver.execute_script(
            "return Array.from(document.images).filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'))")
        if not broken:
            break
        time.sleep(0.2)
    check(not broken, "%s: images that do not load: %s" % (what, broken[:5]))
    return len(images)


def check_console(driver, what):
    errors = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
    check(not errors, "%s: console errors: %s" % (what, errors[:5]))


def check_no_alert(driver, what):
    try:
        driver.switch_to.alert
        check(False, what + ": a script ran (an alert is open)")
    except NoAlertPresentException:
        pass


def screenshot(driver, directory, name):
    if directory:
        os.makedirs(directory, exist_ok=True)
        driver.save_screenshot(os.path.join(directory, name))


def rows_of(driver):
    return driver.execute_script("""
      return Array.from(document.querySelectorAll('#scenes tbody tr')).map(r => ({
        scene: r.dataset.scene, shown: r.querySelector('td.name .path').textContent,
        verdict: r.dataset.verdict,
        differing: r.querySelector('td.differing').textContent,
        violations: r.querySelector('td.violations').textContent}))""")


def summary_of(driver):
    return driver.execute_script("""
      const s = {};
      document.querySelectorAll('#summary td[data-count]').forEach(td => s[td.dataset.count] = td.textContent);
      return s""")


def check_failures_first(rows, what):
    order = ["error", "crashed", "differing", "inconclusive", "verified", "identical", "rendered"]
    ranks = [order.index(r["verdict"]) for r in rows]
    check(ranks == sorted(ranks), "%s: rows not in failures-first order: %s" % (what, [r["verdict"] for r in rows]))


def validate_junit(path, source, what):
    r = subprocess.run(["xmllint", "--noout", "--schema", os.path.join(source, "docs/schemas/junit.xsd"), path],
                       capture_output=True, text=True)
    check(r.returncode == 0, "%s: JUnit XML does not validate: %s" % (what, r.stderr[-2000:]))
    return open(path, encoding="utf-8").read()


def render_batch(a, scenes, work, env=None, expect=(0, 1, 2, 5, 6), cwd=None):
    out, report, junit = os.path.join(work, "out"), os.path.join(work, "report"), os.path.join(work, "junit.xml")
    r = run([a.exe, "render", *scenes, "-o", out, "--report", report, "--junit", junit, "--json", "-q"], env, expect, cwd)
    lines = [json.loads(line) for line in r.stdout.splitlines() if line.strip()]
    return lines, os.path.join(report, "index.html"), junit


def case_batch(a):
    """Shipped scenes on lavapipe without SSE (where the twin has no rules, so differences are
    judged), and a scene that cannot be read: errors first, then verified, then identical."""
    work = a.work
    broken = os.path.join(work, "broken.json")
    with open(broken, "w") as f:
        f.write('{"canvas": {"width": 64, "height": 64}, "models": {')
    names = ["cgfs-transforms.json", "hard/depth-ratio-1e-4.json", "catlike-grid.json", "lit-flat.json", "cgfs-scene.json"]
    # Paths relative to the repository, as a user types them (and as the README's screenshot shows).
    scenes = [os.path.join("scenes", n) for n in names] + [os.path.relpath(broken, a.source)]
    lines, page, junit = render_batch(a, scenes, work, {"GALLIUM_OVERRIDE_CPU_CAPS": "nosse"}, cwd=a.source)
    by_scene = {j["scene"]: j for j in lines}
    check(len(lines) == len(scenes) - 1, "batch: one JSON line per readable scene, got %d" % len(lines))

    driver = browser()
    try:
        open_page(driver, page)
        rows = rows_of(driver)
        check(len(rows) == len(scenes), "batch: %d rows for %d scenes" % (len(rows), len(scenes)))
        check_failures_first(rows, "batch")
        check(rows and rows[0]["scene"] == scenes[-1] and rows[0]["verdict"] == "error", "batch: the unreadable scene is not first")
        for row in rows:
            j = by_scene.get(row["scene"])
            if j is None:
                continue
            want = "-" if j["differing_pixels"] is None else str(j["differing_pixels"])
            check(row["differing"] == want, "batch: %s differing px %s on the page, %s in --json" % (row["scene"], row["differing"], want))
            v = j["verify"]
            want = "-" if v is None else str(v["pixels"]["violations"])
            check(row["violations"] == want, "batch: %s violations %s on the page, %s in --json" % (row["scene"], row["violations"], want))
            expected = "identical" if j["differing_pixels"] == 0 else (v["verdict"].replace("passed", "verified").replace("failed", "differing") if v else "differing")
            check(row["verdict"] == expected, "batch: %s is %s on the page, %s by its --json" % (row["scene"], row["verdict"], expected))
        verified = sum(1 for j in lines if j["differing_pixels"] and j["verify"]["passed"])
        identical = sum(1 for j in lines if j["differing_pixels"] == 0)
        inconclusive = sum(1 for j in lines if j["differing_pixels"] and j["verify"]["verdict"] == "inconclusive")
        check(inconclusive >= 1, "batch: no inconclusive judgement (hard/depth-ratio-1e-4 without SSE gives one)")
        check(verified >= 1, "batch: lavapipe without SSE made no difference to judge (the test needs one)")
        s = summary_of(driver)
        check(s.get("scenes") == str(len(scenes)), "batch: summary scenes %s" % s.get("scenes"))
        check(s.get("identical") == str(identical), "batch: summary identical %s, --json says %d" % (s.get("identical"), identical))
        check(s.get("verified") == str(verified), "batch: summary verified %s, --json says %d" % (s.get("verified"), verified))
        check(s.get("inconclusive") == str(inconclusive), "batch: summary inconclusive %s, --json says %d" % (s.get("inconclusive"), inconclusive))
        check(s.get("errors") == "1", "batch: summary errors %s" % s.get("errors"))
        count = check_images_load(driver, "batch")
        check(count >= 2 * (len(scenes) - 1), "batch: %d images for %d drawn scenes" % (count, len(scenes) - 1))
        links = driver.execute_script("return Array.from(document.querySelectorAll('#scenes a')).map(a => a.href)")
        missing = [h for h in links if not os.path.isfile(re.sub("^file://", "", urllib.parse.unquote(h)))]
        check(not missing, "batch: links to missing full-size PNGs: %s" % missing[:3])
        check_console(driver, "batch")
        driver.execute_script("window.scrollTo(0, 0)")
        screenshot(driver, a.screenshots, "page-batch.png")
    finally:
        driver.quit()
    xml = validate_junit(junit, a.source, "batch")
    check(xml.count("<testcase ") == len(scenes), "batch: JUnit has %d testcases for %d scenes" % (xml.count("<testcase "), len(scenes)))
    check('<error type="error"' in xml, "batch: the unreadable scene is not a JUnit error")


def case_crashes(a):
    """A driver that crashes on every scene: each row says crashed, the twin's image still shows."""
    scenes = [os.path.join(a.source, "scenes", n) for n in ("cgfs-transforms.json", "lookat.json")]
    lines, page, junit = render_batch(a, scenes, a.work, {"TWINRASTER_TEST_GPU_FAULT": "abort"})
    driver = browser()
    try:
        open_page(driver, page)
        rows = rows_of(driver)
        check([r["verdict"] for r in rows] == ["crashed", "crashed"], "crashes: verdicts %s" % [r["verdict"] for r in rows])
        check(summary_of(driver).get("crashed") == "2", "crashes: summary crashed count")
        check_images_load(driver, "crashes")
        check_console(driver, "crashes")
    finally:
        driver.quit()
    xml = validate_junit(junit, a.source, "crashes")
    check(xml.count('<error type="crashed"') == 2, "crashes: JUnit errors for crashed scenes")


def case_thousand(a):
    """1,000 small scenes: the page stays under ~2 MB and opens within a few seconds."""
    work = a.work
    scenes_dir = os.path.join(work, "scenes")
    os.makedirs(scenes_dir, exist_ok=True)
    template = json.load(open(os.path.join(a.source, "scenes", "cgfs-transforms.json")))
    template["canvas"]["width"], template["canvas"]["height"] = 64, 64
    scenes = []
    for i in range(1000):
        path = os.path.join(scenes_dir, "s%04d.json" % i)
        template["camera"]["position"][0] = -3 + (i % 10) * 0.1
        with open(path, "w") as f:
            json.dump(template, f)
        scenes.append(path)
    start = time.monotonic()
    lines, page, junit = render_batch(a, scenes, work)
    print("thousand: rendered 1000 scenes in %.1f s" % (time.monotonic() - start))
    size = os.path.getsize(page)
    print("thousand: index.html is %d bytes" % size)
    check(size < 2_000_000, "thousand: index.html is %d bytes, over 2 MB" % size)
    driver = browser()
    try:
        seconds = open_page(driver, page)
        timing = driver.execute_script("const t = performance.timing; return t.loadEventEnd - t.navigationStart")
        print("thousand: page opened in %.2f s (load event after %d ms)" % (seconds, timing))
        check(seconds < 5, "thousand: the page took %.1f s to open" % seconds)
        rows = rows_of(driver)
        check(len(rows) == 1000, "thousand: %d rows" % len(rows))
        loaded = driver.execute_script("return Array.from(document.images).filter(i => i.complete && i.naturalWidth > 0).length")
        total = driver.execute_script("return document.images.length")
        print("thousand: %d of %d thumbnails loaded before scrolling" % (loaded, total))
        check(loaded < total, "thousand: every thumbnail loaded at once; they should load lazily")
        check_console(driver, "thousand")
    finally:
        driver.quit()
    validate_junit(junit, a.source, "thousand")


HOSTILE = ['<img src=x onerror=alert(1)>', '"quotes" & \'apostrophes\'', "a&amp;b <b>bold</b>", "<script>alert(2)<\\script>"]


def case_hostile(a):
    """Scene files and models named with markup: every page shows the names as text."""
    work = a.work
    template = json.load(open(os.path.join(a.source, "scenes", "cgfs-transforms.json")))
    template["canvas"]["width"], template["canvas"]["height"] = 96, 96
    model = template["models"].pop("cube")
    template["models"][HOSTILE[0]] = model
    for instance in template["instances"]:
        instance["model"] = HOSTILE[0]
    scenes = []
    for name in HOSTILE:
        path = os.path.join(work, name.replace("/", "_") + ".json")
        with open(path, "w") as f:
            json.dump(template, f)
        scenes.append(path)
    lines, page, junit = render_batch(a, scenes, work)
    chain = os.path.join(work, "chain.html")
    run([a.exe, "explain", scenes[0], "--html", chain])
    suite = os.path.join(work, "suite")  # a bench suite of one hostile-named scene
    os.makedirs(suite)
    shutil.copy(scenes[0], suite)
    bench = os.path.join(work, "bench.html")
    run([a.exe, "bench", "--scenes", suite, "--runs", "1", "--methods", "compose-f64,cpu-twin", "--html", bench, "-q"])
    driver = browser()
    try:
        for what, path in (("hostile batch", page), ("hostile chain", chain), ("hostile bench", bench)):
            open_page(driver, path)
            check_no_alert(driver, what)
            check(driver.execute_script("return document.scripts.length") == 0, what + ": the page has a <script> element")
            check(driver.execute_script("return document.querySelectorAll('[onerror]').length") == 0,
                  what + ": an element with onerror")
            check(driver.execute_script(
                      "return Array.from(document.querySelectorAll('b')).filter(b => b.textContent.startsWith('bold')).length") == 0,
                  what + ": a name's <b> became markup")
            check_images_load(driver, what)
            check_console(driver, what)
        open_page(driver, page)
        rows = rows_of(driver)
        check(sorted(r["scene"] for r in rows) == sorted(scenes), "hostile batch: names %s" % [r["scene"] for r in rows])
        check(all(r["shown"] == r["scene"] for r in rows), "hostile batch: a name is not shown as written")
        text = driver.execute_script("return document.body.textContent")
        for path in scenes:
            name = os.path.basename(path)[:-len(".json")]
            check(name in text, "hostile batch: %s is not shown as text" % name)
        open_page(driver, chain)
        text = driver.find_element(By.TAG_NAME, "body").text
        check(HOSTILE[0] in text, "hostile chain: the model's name is not shown as text")
        open_page(driver, bench)
        text = driver.execute_script("return document.body.textContent")
        check(HOSTILE[0] in text, "hostile bench: the scene's name is not shown as text")
    finally:
        driver.quit()
    xml = validate_junit(junit, a.source, "hostile")
    check(xml.count("<testcase ") == len(HOSTILE), "hostile: JUnit testcases")


def numbers(text):
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?", text)]


def close(a, b):
    return abs(a - b) <= 1e-5 * max(1.0, abs(b))


def case_chain(a):
    """explain --html on the README's scene and a lit one: every panel, every number as --json has it."""
    for scene, panels, shot in (("cgfs-transforms.json", 6, "page-chain.png"), ("lit-flat.json", 7, "page-chain-lit.png")):
        path = os.path.join(a.source, "scenes", scene)
        page = os.path.join(a.work, scene + ".html")
        run([a.exe, "explain", path, "--html", page])
        j = json.loads(run([a.exe, "explain", path, "--json", "--instance", "0"]).stdout)
        driver = browser(1300, 2200)
        try:
            open_page(driver, page)
            shown = driver.execute_script("return Array.from(document.querySelectorAll('figure.chain-panel')).map(f => [f.dataset.panel, f.querySelector('pre').textContent])")
            check(len(shown) == panels, "chain %s: %d panels, expected %d" % (scene, len(shown), panels))
            text = dict(shown)
            vertex = next((v for v in j["instances"][0]["vertices"] if v["inside_clip_volume"]), j["instances"][0]["vertices"][0])
            for panel, label, key in (("model", "V = ", "object"), ("world-top", "M_Model · V = ", "world"),
                                      ("camera", "M_Model · V = ", "camera"), ("ndc", "NDC = clip.xyz / w = ", "ndc"),
                                      ("canvas", "framebuffer (Vulkan: origin top-left, +y down) = ", "framebuffer")):
                line = next((l for l in text.get(panel, "").splitlines() if label in l), "")
                got = numbers(line.split(label)[-1])
                check(len(got) == len(vertex[key]) and all(close(g, w) for g, w in zip(got, vertex[key])),
                      "chain %s: %s shows %s, --json has %s" % (scene, panel, got, vertex[key]))
            for panel, name, rows in (("world-top", "M_Model =", j["instances"][0]["model_matrix"]),
                                      ("camera", "M_Camera =", j["camera_matrix"]),
                                      ("ndc", "M_Projection =", j["projection_matrix"]),
                                      ("canvas", "F = M_Projection · M_Camera · M_Model =", j["instances"][0]["mvp"])):
                block = text.get(panel, "").split(name)[-1].splitlines()[1:5]
                got = [numbers(l) for l in block]
                want = rows
                ok = len(got) == 4 and all(len(g) == 4 and all(abs(x - y) <= 1e-4 * max(1, abs(y)) for x, y in zip(g, w)) for g, w in zip(got, want))
                check(ok, "chain %s: %s on the page %s, --json %s" % (scene, name, got, want))
            pixel = [math.floor(vertex["framebuffer"][0]), math.floor(vertex["framebuffer"][1])]
            check("pixel (%d, %d)" % tuple(pixel) in text.get("canvas", ""), "chain %s: the pixel is not %s" % (scene, pixel))
            if panels == 7:
                light = vertex["light"]
                line = next((l for l in text.get("light", "").splitlines() if l.startswith("I = ")), "")
                check(numbers(line) and close(numbers(line)[0], light["intensity"]), "chain %s: I on the page %s" % (scene, line))
            check_console(driver, "chain " + scene)
            screenshot(driver, a.screenshots, shot)
        finally:
            driver.quit()


def case_bench(a):
    """bench --html and bench --scale --html: every plotted point is a --json number."""
    page = os.path.join(a.work, "bench.html")
    r = run([a.exe, "bench", "--only", "cgfs-transforms", "--runs", "1", "--scenes", os.path.join(a.source, "scenes"),
             "--html", page, "--json", "-q"])
    j = json.loads(r.stdout)
    driver = browser(1300, 1400)
    try:
        open_page(driver, page)
        points = driver.execute_script("""
          return Array.from(document.querySelectorAll('#vertex-chart circle.point')).map(c => ({
            series: c.closest('g.series').dataset.series, x: +c.dataset.x, y: +c.dataset.y}))""")
        want = [(row["method"], row["vertex_ms"] * 1e6 / row["vertices"], row["vertex_error_px"]) for row in j["rows"]
                if row["vertex_ms"] is not None and row["vertex_error_px"] is not None and row["vertices"]]
        check(len(points) == len(want), "bench: %d points, --json has %d rows with a vertex time" % (len(points), len(want)))
        for (method, x, y), p in zip(want, points):
            check(p["series"] == method and close(p["x"], x) and close(p["y"], y), "bench: point %s, --json %s" % (p, (method, x, y)))
        scene_points = driver.execute_script("return document.querySelectorAll('figure.scene-chart circle.point').length")
        check(scene_points == len(j["rows"]), "bench: %d per-scene points for %d rows" % (scene_points, len(j["rows"])))
        check_console(driver, "bench")
        screenshot(driver, a.screenshots, "page-bench.png")
    finally:
        driver.quit()
    page = os.path.join(a.work, "scale.html")
    r = run([a.exe, "bench", "--scale", "--counts", "1,8,64", "--runs", "1", "--html", page, "--json", "-q"])
    j = json.loads(r.stdout)
    driver = browser(1300, 1100)
    try:
        open_page(driver, page)
        series = driver.execute_script("""
          const s = {};
          document.querySelectorAll('#scale-chart g.series').forEach(g =>
            s[g.dataset.series] = Array.from(g.querySelectorAll('circle.point')).map(c => [+c.dataset.x, +c.dataset.y]));
          return s""")
        expected = {"lavapipe, instanced": lambda r: r["gpu_setup_ms"] + r["gpu_draw_ms"],
                    "lavapipe, F per draw": lambda r: r["gpu_per_draw_ms"],
                    "CPU twin": lambda r: r["twin_setup_ms"] + r["twin_draw_ms"],
                    "verifier": lambda r: r["verify_ms"]}
        for name, value in expected.items():
            want = [[row["instances"], value(row)] for row in j["rows"]]
            got = series.get(name, [])
            check(len(got) == len(want) and all(close(g[0], w[0]) and close(g[1], w[1]) for g, w in zip(got, want)),
                  "scale: %s plotted %s, --json %s" % (name, got, want))
        check_console(driver, "scale")
        screenshot(driver, a.screenshots, "page-scale.png")
    finally:
        driver.quit()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case", choices=["batch", "crashes", "thousand", "hostile", "chain", "bench"])
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--screenshots")
    a = parser.parse_args()
    a.exe = os.path.abspath(a.exe)
    if os.path.isdir(a.work):
        shutil.rmtree(a.work)
    os.makedirs(a.work)
    globals()["case_" + a.case](a)
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES), file=sys.stderr)
        sys.exit(1)
    print("%s: all checks passed" % a.case)


if __name__ == "__main__":
    main()
