#!/usr/bin/python3
"""Opens twinraster's pages in headless Chromium (Debian's chromium and chromium-driver, through
python3-selenium) and checks what a reader sees: every image loads, no console error, the numbers
equal the matching --json output, failures come first, a 1,000-scene report stays small and loads
its thumbnails lazily, and names from scene files are shown as text, never run as markup. Every
command must end with the one exit code its case produces, and every loop that judges rows checks
how many it judged. Saves the screenshots docs/pages.md shows. How fast the 1,000-scene report opens is
measured by scripts/bench-pages.py, not judged here.

Usage: check_pages.py CASE --exe TWINRASTER --source REPO --work DIR [--screenshots DIR]
CASE: batch, crashes, thousand, hostile, chain, bench."""
import argparse
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import time
import urllib.parse
import zlib

from selenium import webdriver
from selenium.common.exceptions import NoAlertPresentException
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

FAILURES = []

# twinraster's exit codes, as `twinraster render --help` lists them.
EXIT_CODES = {0: "done", 1: "the images differ", 2: "bad input or usage", 3: "no usable Vulkan device",
              4: "internal error", 5: "the Vulkan driver crashed or timed out", 6: "inconclusive"}


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("FAIL: " + message, file=sys.stderr)
    return condition


def exit_code_text(code):
    if code < 0:
        return "%d (killed by signal %d)" % (code, -code)
    return "%d (%s)" % (code, EXIT_CODES.get(code, "not a twinraster exit code"))


def run(args, env=None, expect=0, cwd=None):
    """Runs a command that must exit with exactly `expect`; any other code ends the case, since what
    it wrote is then not what the case checks."""
    full_env = dict(os.environ)
    full_env.update(env or {})
    r = subprocess.run(args, capture_output=True, text=True, env=full_env, cwd=cwd)
    if r.returncode != expect:
        sys.exit("FAIL: %s exited %s, this case expects %s\nstdout:\n%s\nstderr:\n%s"
                 % (" ".join(args), exit_code_text(r.returncode), exit_code_text(expect), r.stdout[-4000:], r.stderr[-4000:]))
    return r


def browser(width=1400, height=1000):
    options = Options()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--allow-file-access-from-files", "--window-size=%d,%d" % (width, height)):
        options.add_argument(a)
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"), options=options)


def followed_vertex(explain, vertex_asked):
    """The first instance's followed vertex in explain --json: the one asked for (its only vertex),
    else the first inside the clip volume, else vertex 0."""
    instance = explain["instances"][0]
    vertices = instance["vertices"]
    inside = [v for v in vertices if v["inside_clip_volume"]]
    chosen = vertices[0] if vertex_asked or not inside else inside[0]
    return {"instance": instance["index"], "vertex": chosen}


def png_rgba(path):
    """(width, height, RGBA bytes) of an 8-bit RGB or RGBA PNG, not interlaced: the ones twinraster writes."""
    data = open(path, "rb").read()
    check(data[:8] == b"\x89PNG\r\n\x1a\n", path + ": not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        sys.exit("FAIL: %s: a PNG this checker does not decode (depth %d, colour %d)" % (path, depth, colour))
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    pixels = b"".join(rows)
    if channels == 3:
        pixels = b"".join(pixels[i:i + 3] + b"\xff" for i in range(0, len(pixels), 3))
    return width, height, pixels


def open_page(driver, path):
    """Opens a page and waits until it is parsed and loaded: on a busy machine driver.get() has
    returned while the parser was still inside a page (a panel found without its text)."""
    start = time.monotonic()
    driver.get("file://" + os.path.abspath(path))
    seconds = time.monotonic() - start
    deadline = time.monotonic() + 60
    while driver.execute_script("return document.readyState") != "complete":
        if time.monotonic() > deadline:
            sys.exit("FAIL: %s did not finish loading in 60 s" % path)
        time.sleep(0.05)
    return seconds


def check_images_load(driver, what, expected):
    """Scrolls every <img> into view (they load lazily) and checks that each one decoded, and that
    there are `expected` of them: no broken image is no proof when there is no image at all."""
    images = driver.find_elements(By.TAG_NAME, "img")
    check(len(images) == expected, "%s: %d images, expected %d" % (what, len(images), expected))
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


CONSOLE_PROBE = "check_pages: console probe"


def check_console(driver, what):
    """No console error. An error of our own is logged first and must come back: a browser log that
    captures nothing would otherwise pass every page."""
    driver.execute_script("console.error(arguments[0])", CONSOLE_PROBE)
    log = driver.get_log("browser")
    probes = [e for e in log if CONSOLE_PROBE in e.get("message", "")]
    check(len(probes) == 1, "%s: the browser log did not capture a console.error, so it would miss the page's errors" % what)
    errors = [e for e in log if e.get("level") == "SEVERE" and e not in probes]
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


def thumbnails_of(j):
    """The images a report row shows for a --json line: each backend's image, the diff and the
    verifier's map (the report writes one for every judgement)."""
    drawn = sum(1 for b in j["backends"].values() if b and b["output"])
    return drawn + (j["diff"] is not None) + (j["verify"] is not None)


def check_failures_first(rows, what):
    order = ["error", "crashed", "differing", "inconclusive", "verified", "identical", "rendered"]
    ranks = [order.index(r["verdict"]) for r in rows]
    check(ranks == sorted(ranks), "%s: rows not in failures-first order: %s" % (what, [r["verdict"] for r in rows]))


def validate_junit(path, source, what):
    r = subprocess.run(["xmllint", "--noout", "--schema", os.path.join(source, "docs/schemas/junit.xsd"), path],
                       capture_output=True, text=True)
    check(r.returncode == 0, "%s: JUnit XML does not validate: %s" % (what, r.stderr[-2000:]))
    return open(path, encoding="utf-8").read()


def render_batch(a, scenes, work, expect, env=None, cwd=None):
    """Renders a batch with --report, --junit and --json; `expect` is the one exit code the batch
    must end with (the worst of its scenes')."""
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
    # Paths relative to the repository, as a user types them (and as the screenshot in docs/pages.md shows).
    scenes = [os.path.join("scenes", n) for n in names] + [os.path.relpath(broken, a.source)]
    # Exit 2: the unreadable scene is bad input, which outranks the inconclusive judgement's 6.
    lines, page, junit = render_batch(a, scenes, work, 2, {"GALLIUM_OVERRIDE_CPU_CAPS": "nosse"}, cwd=a.source)
    by_scene = {j["scene"]: j for j in lines}
    check(len(lines) == len(scenes), "batch: one JSON line per scene, the unreadable one's too, got %d" % len(lines))
    check(sorted(by_scene) == sorted(scenes), "batch: --json lines for %s, expected %s" % (sorted(by_scene), sorted(scenes)))
    unreadable = by_scene.get(scenes[-1], {})
    check(unreadable.get("verdict") == "error" and unreadable.get("exit_code") == 2,
          "batch: the unreadable scene's --json line says %s" % unreadable)
    drawn = [j for j in lines if j["verdict"] != "error"]

    driver = browser()
    try:
        open_page(driver, page)
        rows = rows_of(driver)
        check(len(rows) == len(scenes), "batch: %d rows for %d scenes" % (len(rows), len(scenes)))
        check_failures_first(rows, "batch")
        check(rows and rows[0]["scene"] == scenes[-1] and rows[0]["verdict"] == "error", "batch: the unreadable scene is not first")
        judged, unjudged = 0, []
        for row in rows:
            j = by_scene.get(row["scene"])
            check(j is not None and row["verdict"] == j["verdict"],
                  "batch: %s is %s on the page, %s in --json" % (row["scene"], row["verdict"], j and j["verdict"]))
            if j is None or j["verdict"] == "error":
                unjudged.append(row["scene"])  # nothing was drawn, compared or judged
                continue
            judged += 1
            want = "-" if j["differing_pixels"] is None else str(j["differing_pixels"])
            check(row["differing"] == want, "batch: %s differing px %s on the page, %s in --json" % (row["scene"], row["differing"], want))
            v = j["verify"]
            want = "-" if v is None else str(v["pixels"]["violations"])
            check(row["violations"] == want, "batch: %s violations %s on the page, %s in --json" % (row["scene"], row["violations"], want))
            expected = "identical" if j["differing_pixels"] == 0 else (v["verdict"].replace("passed", "verified").replace("failed", "differing") if v else "differing")
            check(row["verdict"] == expected, "batch: %s is %s on the page, %s by its --json" % (row["scene"], row["verdict"], expected))
        check(judged == len(scenes) - 1, "batch: %d rows matched a drawn scene's --json line, expected %d" % (judged, len(scenes) - 1))
        check(unjudged == [scenes[-1]], "batch: rows of scenes not drawn %s, expected only the unreadable %s" % (unjudged, scenes[-1]))
        verified = sum(1 for j in drawn if j["differing_pixels"] and j["verify"]["passed"])
        identical = sum(1 for j in drawn if j["differing_pixels"] == 0)
        inconclusive = sum(1 for j in drawn if j["differing_pixels"] and j["verify"]["verdict"] == "inconclusive")
        differing = sum(1 for j in drawn if j["differing_pixels"] and j["verify"]["verdict"] == "failed")
        check(verified + identical + inconclusive + differing == len(drawn),
              "batch: %d drawn scenes' --json lines, but %d identical, %d verified, %d inconclusive and %d differing"
              % (len(drawn), identical, verified, inconclusive, differing))
        check(inconclusive >= 1, "batch: no inconclusive judgement (hard/depth-ratio-1e-4 without SSE gives one)")
        check(verified >= 1, "batch: lavapipe without SSE made no difference to judge (the test needs one)")
        s = summary_of(driver)
        check(s.get("scenes") == str(len(scenes)), "batch: summary scenes %s" % s.get("scenes"))
        check(s.get("identical") == str(identical), "batch: summary identical %s, --json says %d" % (s.get("identical"), identical))
        check(s.get("verified") == str(verified), "batch: summary verified %s, --json says %d" % (s.get("verified"), verified))
        check(s.get("inconclusive") == str(inconclusive), "batch: summary inconclusive %s, --json says %d" % (s.get("inconclusive"), inconclusive))
        check(s.get("differing") == str(differing), "batch: summary differing %s, --json says %d" % (s.get("differing"), differing))
        check(s.get("crashed") == "0", "batch: summary crashed %s" % s.get("crashed"))
        check(s.get("errors") == "1", "batch: summary errors %s" % s.get("errors"))
        count = check_images_load(driver, "batch", sum(thumbnails_of(j) for j in lines))
        links = driver.execute_script("return Array.from(document.querySelectorAll('#scenes a')).map(a => a.href)")
        # Each thumbnail links to its full-size PNG; with no links, "none missing" would prove nothing.
        check(len(links) == count, "batch: %d links for %d thumbnails" % (len(links), count))
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
    lines, page, junit = render_batch(a, scenes, a.work, 5, {"TWINRASTER_TEST_GPU_FAULT": "abort"})
    gpu = [(j["scene"], j["backends"]["gpu"]["status"]) for j in lines]
    check(gpu == [(scene, "crashed") for scene in scenes], "crashes: --json gpu status %s, expected crashed for each of %s" % (gpu, scenes))
    driver = browser()
    try:
        open_page(driver, page)
        rows = rows_of(driver)
        check([r["verdict"] for r in rows] == ["crashed"] * len(scenes), "crashes: verdicts %s" % [r["verdict"] for r in rows])
        check(summary_of(driver).get("crashed") == str(len(scenes)), "crashes: summary crashed count")
        check_images_load(driver, "crashes", len(scenes))  # the twin's image, one per scene
        check_console(driver, "crashes")
    finally:
        driver.quit()
    xml = validate_junit(junit, a.source, "crashes")
    check(xml.count('<error type="crashed"') == len(scenes), "crashes: JUnit errors for crashed scenes")


THOUSAND = 1000


def render_thousand(a, work):
    """Renders THOUSAND copies of cgfs-transforms at 64 x 64, the camera moved between ten places, as
    one report; every scene is drawn and passes, so the batch exits 0. Returns render_batch's
    (lines, page, junit) and the seconds it took. scripts/bench-pages.py uses it too."""
    scenes_dir = os.path.join(work, "scenes")
    os.makedirs(scenes_dir, exist_ok=True)
    template = json.load(open(os.path.join(a.source, "scenes", "cgfs-transforms.json")))
    template["canvas"]["width"], template["canvas"]["height"] = 64, 64
    scenes = []
    for i in range(THOUSAND):
        path = os.path.join(scenes_dir, "s%04d.json" % i)
        template["camera"]["position"][0] = -3 + (i % 10) * 0.1
        with open(path, "w") as f:
            json.dump(template, f)
        scenes.append(path)
    start = time.monotonic()
    lines, page, junit = render_batch(a, scenes, work, 0)
    return lines, page, junit, time.monotonic() - start


def open_timed(driver, page):
    """Opens a page; returns the seconds until driver.get() returned and the milliseconds from
    navigation start to the end of the load event."""
    seconds = open_page(driver, page)
    load_ms = driver.execute_script("const t = performance.timing; return t.loadEventEnd - t.navigationStart")
    return seconds, load_ms


def case_thousand(a):
    """1,000 small scenes: the page stays under 2 MB, shows a row and its thumbnails for every scene,
    and loads them lazily. The time it takes to open is printed, not judged: under ctest -j other
    tests share the cores and a limit would flake; scripts/bench-pages.py measures it."""
    lines, page, junit, render_seconds = render_thousand(a, a.work)
    print("thousand: rendered %d scenes in %.1f s" % (THOUSAND, render_seconds))
    check(len(lines) == THOUSAND, "thousand: %d --json lines for %d scenes" % (len(lines), THOUSAND))
    size = os.path.getsize(page)
    print("thousand: index.html is %d bytes" % size)
    check(size < 2_000_000, "thousand: index.html is %d bytes, over 2 MB" % size)
    driver = browser()
    try:
        seconds, load_ms = open_timed(driver, page)
        print("thousand: page opened in %.2f s (load event after %d ms; measured, not judged)" % (seconds, load_ms))
        rows = rows_of(driver)
        check(len(rows) == THOUSAND, "thousand: %d rows" % len(rows))
        loaded = driver.execute_script("return Array.from(document.images).filter(i => i.complete && i.naturalWidth > 0).length")
        total = driver.execute_script("return document.images.length")
        thumbnails = sum(thumbnails_of(j) for j in lines)
        print("thousand: %d of %d thumbnails loaded before scrolling" % (loaded, total))
        check(total == thumbnails, "thousand: %d thumbnails on the page, --json has %d images" % (total, thumbnails))
        check(loaded < total, "thousand: every thumbnail loaded at once; they should load lazily")
        check_console(driver, "thousand")
    finally:
        driver.quit()
    xml = validate_junit(junit, a.source, "thousand")
    check(xml.count("<testcase ") == THOUSAND, "thousand: JUnit has %d testcases for %d scenes" % (xml.count("<testcase "), THOUSAND))


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
    lines, page, junit = render_batch(a, scenes, work, 0)
    check(sorted(j["scene"] for j in lines) == sorted(scenes), "hostile: --json lines for %s" % [j["scene"] for j in lines])
    chain = os.path.join(work, "chain.html")
    run([a.exe, "explain", scenes[0], "--html", chain])
    suite = os.path.join(work, "suite")  # a bench suite of one hostile-named scene
    os.makedirs(suite)
    shutil.copy(scenes[0], suite)
    bench = os.path.join(work, "bench.html")
    run([a.exe, "bench", "--scenes", suite, "--runs", "1", "--methods", "compose-f64,cpu-twin", "--html", bench, "-q"])
    driver = browser()
    try:
        # The batch page shows each scene's images; the others have none, so an <img> there was injected.
        for what, path, images in (("hostile batch", page, sum(thumbnails_of(j) for j in lines)),
                                   ("hostile chain", chain, 0), ("hostile bench", bench, 0)):
            open_page(driver, path)
            check_no_alert(driver, what)
            # The chain page that moves carries its own four: the scene, its data, the module, the script.
            own = ["twinraster-scene", "twinraster-page", "twinraster-module", "twinraster-script"] if path == chain else []
            scripts = driver.execute_script("return Array.from(document.scripts, s => s.id)")
            check(scripts in (own, []), what + ": the page has <script> elements of its own: %s" % scripts)
            check(driver.execute_script("return document.querySelectorAll('[onerror]').length") == 0,
                  what + ": an element with onerror")
            check(driver.execute_script(
                      "return Array.from(document.querySelectorAll('b')).filter(b => b.textContent.startsWith('bold')).length") == 0,
                  what + ": a name's <b> became markup")
            check_images_load(driver, what, images)
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
            shown = driver.execute_script("return Array.from(document.querySelectorAll('figure.chain-panel')).map(f => [f.dataset.panel, f.querySelector('pre') ? f.querySelector('pre').textContent : null])")
            check(all(t is not None for _, t in shown), "chain %s: panels without their text: %s" % (scene, [p for p, t in shown if t is None]))
            shown = [(p, t or "") for p, t in shown]
            check(len(shown) == panels, "chain %s: %d panels, expected %d" % (scene, len(shown), panels))
            text = dict(shown)
            check(len(text) == len(shown), "chain %s: a panel's name repeats: %s" % (scene, [p for p, _ in shown]))
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
    check(j["rows"], "bench: --json has no rows")
    driver = browser(1300, 1400)
    try:
        open_page(driver, page)
        points = driver.execute_script("""
          return Array.from(document.querySelectorAll('#vertex-chart circle.point')).map(c => ({
            series: c.closest('g.series').dataset.series, x: +c.dataset.x, y: +c.dataset.y}))""")
        want = [(row["method"], row["vertex_ms"] * 1e6 / row["vertices"], row["vertex_error_px"]) for row in j["rows"]
                if row["vertex_ms"] is not None and row["vertex_error_px"] is not None and row["vertices"]]
        timed = sum(1 for row in j["rows"] if row["vertex_ms"] is not None)
        # The twin's and lavapipe's rows time whole frames, with no vertex stage of their own; every other row is plotted.
        check(want and len(want) == timed, "bench: %d of the %d --json rows with a vertex time can be plotted" % (len(want), timed))
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
    counts = [row["instances"] for row in j["rows"]]
    check(counts == [1, 8, 64], "scale: --json rows for %s instances, expected 1, 8 and 64" % counts)
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
