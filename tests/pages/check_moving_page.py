#!/usr/bin/python3
"""Opens the moving chain page (explain --html) in headless Chromium from file://, without
--allow-file-access-from-files (the flag that would hide a fetch of a sibling file), and holds what
the embedded module computes to the native executable, bit for bit: for the scene's own state and
for states reached by driving the page's controls (seeded, random), each saved with sceneText() as
a scene file and explained (explain --json) and drawn (render --backend cpu --threads 1) natively.
Every number of explain's JSON is compared as its float bits; the picture as RGBA bytes. Also: a
refused state shows the module's message and keeps the last picture; Save downloads the state;
Reset returns to the scene's own; every control is labelled and reachable by Tab, and a slider
moves with the arrow keys; SwiftShader's rules, which the browser cannot follow, give no picture
and say so; with JavaScript disabled the page shows exactly the static page.

Usage: check_moving_page.py CASE --exe TWINRASTER --source REPO --work DIR [--states N] [--seed S]
CASE: chapter (cgfs-transforms.json), lit (lit-gouraud.json), grid (a 10,000-instance grid
written here), nojs."""
import argparse
import base64
import json
import os
import random
import re
import shutil
import struct
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_pages as pages  # noqa: E402  (its checks, commands and page loading)
from check_pages import check, run  # noqa: E402

from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.options import Options  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402


def browser(javascript=True, width=1400, height=1000):
    """Headless Chromium as a learner opens a file: no file-access flag."""
    options = Options()
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
              "--window-size=%d,%d" % (width, height)):
        options.add_argument(a)
    if not javascript:
        options.add_experimental_option("prefs", {"profile.managed_default_content_settings.javascript": 2})
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"), options=options)
    driver.set_script_timeout(120)
    return driver


# ---- exact comparison --------------------------------------------------------------------------

def differences(want, got, where="", found=None):
    """Where two parsed JSON values differ: numbers by their double's bits (so -0.0 is not 0.0),
    integers as integers, keys and lengths exactly."""
    found = [] if found is None else found
    if len(found) >= 5:
        return found
    if isinstance(want, bool) or isinstance(got, bool) or want is None or got is None or isinstance(want, str):
        if want != got or type(want) is not type(got):
            found.append("%s: %r against %r" % (where, got, want))
    elif isinstance(want, (int, float)) and isinstance(got, (int, float)):
        if type(want) is not type(got) or struct.pack("<d", float(want)) != struct.pack("<d", float(got)) or want != got:
            found.append("%s: %r against %r" % (where, got, want))
    elif isinstance(want, dict) and isinstance(got, dict):
        if list(want) != list(got):
            found.append("%s: keys %s against %s" % (where, list(got), list(want)))
        for k in want:
            if k in got:
                differences(want[k], got[k], where + "." + k, found)
    elif isinstance(want, list) and isinstance(got, list):
        if len(want) != len(got):
            found.append("%s: %d entries against %d" % (where, len(got), len(want)))
        for i, (w, g) in enumerate(zip(want, got)):
            differences(w, g, "%s[%d]" % (where, i), found)
    else:
        found.append("%s: %r against %r" % (where, got, want))
    return found


def float_bits(matrix):
    """F as the renderers take it: each double rounded to float, as bits."""
    return [struct.unpack("<I", struct.pack("<f", x))[0] for row in matrix for x in row]


# ---- the page ----------------------------------------------------------------------------------

def wait_ready(driver, what):
    result = driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "if (!window.twinrasterPage) { done('no window.twinrasterPage'); return; }"
        "window.twinrasterPage.ready.then(() => done('ready'), (e) => done('failed: ' + e));")
    if result != "ready":
        sys.exit("FAIL: %s: the page did not get ready: %s" % (what, result))


def set_control(driver, control_id, value):
    driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "window.twinrasterPage.setControl(arguments[0], arguments[1]).then(() => done(true), (e) => done(String(e)));",
        control_id, value)


def page_state(driver):
    return driver.execute_script(
        "const p = window.twinrasterPage; return {scene: p.sceneText(), explain: p.explainJson(),"
        " picture: p.pictureRgbaBase64(), status: document.getElementById('twinraster-status').textContent,"
        " trace: document.getElementById('twinraster-trace').textContent,"
        " ms: p.lastUpdateMs};")


def controls(driver):
    return driver.execute_script("""
      return Array.from(document.querySelectorAll('#twinraster-controls input, #twinraster-controls select')).map(c => {
        const label = document.querySelector('label[for="' + c.id + '"]');
        const range = document.getElementById(c.id + '-slider') || c;  // a number field's bounds are its slider's
        return {id: c.id, type: c.tagName === 'SELECT' ? 'select' : c.type, min: range.min, max: range.max,
                label: label ? label.textContent : c.getAttribute('aria-label'), tab: c.tabIndex,
                group: c.closest('fieldset').querySelector('legend').textContent,
                options: c.tagName === 'SELECT' ? Array.from(c.options, o => o.value) : null};
      });""")


def trace_of(driver):
    """The traced instance and vertex the controls hold (-1: explain's default)."""
    found = {c["label"]: c["id"] for c in controls(driver) if c["type"] == "number"}
    return [int(float(driver.find_element(By.ID, found[name]).get_attribute("value")))
            for name in ("traced instance", "traced vertex")]


def compare_natively(a, driver, what, state_file, trace):
    """The page's state against the native executable: explain --json and render's PNG."""
    shown = page_state(driver)
    check(not shown["status"].startswith("Refused"), "%s: refused: %s" % (what, shown["status"]))
    with open(state_file, "w") as f:
        f.write(shown["scene"])
    args = [a.exe, "explain", state_file, "--json"]
    if trace[0] >= 0:
        args += ["--instance", str(trace[0])]
    if trace[1] >= 0:
        args += ["--vertex", str(trace[1])]
    native = json.loads(run(args).stdout)
    page = json.loads(shown["explain"])
    check(page.get("scene") == "page", "%s: the module's scene name is %r" % (what, page.get("scene")))
    native.pop("scene"), page.pop("scene", None)
    found = differences(native, page)
    check(not found, "%s: the page's explain JSON differs from explain --json: %s" % (what, found))
    for w, g in zip(native["instances"], page["instances"]):
        check(float_bits(w["mvp"]) == float_bits(g["mvp"]), "%s: F's float bits differ, instance %d" % (what, w["index"]))
    followed = pages.followed_vertex(native, trace[1] >= 0)
    line = "instance %d, vertex %d: clip (" % (followed["instance"], followed["vertex"]["index"])
    check(shown["trace"].startswith(line), "%s: the trace line %r does not start %r" % (what, shown["trace"], line))
    png = state_file[:-len(".json")] + ".png"
    run([a.exe, "render", state_file, "--backend", "cpu", "--threads", "1", "-o", png, "-q"])
    width, height, native_rgba = pages.png_rgba(png)
    rgba = base64.b64decode(shown["picture"])
    check(len(rgba) == width * height * 4, "%s: the page's picture has %d bytes, native %dx%d" % (what, len(rgba), width, height))
    if rgba != native_rgba and len(rgba) == len(native_rgba):
        differing = sum(1 for i in range(0, len(rgba), 4) if rgba[i:i + 4] != native_rgba[i:i + 4])
        check(False, "%s: %d pixels differ from render --backend cpu" % (what, differing))
    return shown["ms"]


def moving_page(a, scene_path, name):
    page = os.path.join(a.work, name + ".html")
    r = run([a.exe, "explain", scene_path, "--html", page])
    check(r.stderr == "", "%s: explain --html printed %r: the page does not move" % (name, r.stderr))
    return page


def pick_value(rng, control):
    if control["type"] == "select":
        return rng.choice(control["options"])
    low, high = float(control["min"]), float(control["max"])
    if control["label"].startswith(("traced", "canvas")):
        high = min(high, 640) if control["label"].startswith("canvas") else high
        return rng.randint(int(low), int(high))
    # A value as typed (a few digits) or as dragged; within the slider's range, which stays
    # inside the scene's domain (a positive d, near and far).
    return min(high, max(low, round(rng.uniform(low, high), rng.choice([1, 2, 3, 6]))))


CATEGORIES = ("Camera", "instance to move", "Instance", "viewport", "depth", "projection", "Traced", "Canvas")


def category_controls(all_controls, category):
    """The number fields and selects of one category (a slider is driven through its field's id
    + '-slider' half of the time)."""
    chosen = []
    for c in all_controls:
        if c["type"] == "range":
            continue
        if category in ("instance to move", "projection"):
            ok = c["label"] == category
        elif category in ("viewport", "depth"):
            ok = c["label"].startswith(category + " ")
        elif category == "Instance":
            ok = c["group"] == "Instance" and c["type"] == "number"
        else:
            ok = c["group"].startswith(category)
        if ok:
            chosen.append(c)
    return chosen


def drive(a, driver, name, states):
    rng = random.Random(a.seed)
    compared, refused, times = 0, 0, []
    seen = set()
    for step in range(states):
        category = CATEGORIES[step % len(CATEGORIES)]
        choices = category_controls(controls(driver), category)
        if not check(choices, "%s: no control for %s" % (name, category)):
            continue
        control = rng.choice(choices)
        target = control["id"]
        if control["type"] == "number" and rng.random() < 0.5:
            target += "-slider"  # as a drag would: the slider's own steps
        set_control(driver, target, pick_value(rng, control))
        seen.add(category)
        status = page_state(driver)["status"]
        if status.startswith("Refused"):
            print("%s state %d (%s): %s" % (name, step, control["label"], status))
            refused += 1
            continue
        times.append(compare_natively(a, driver, "%s state %d (%s)" % (name, step, control["label"]),
                                      os.path.join(a.work, "%s-state-%d.json" % (name, step)), trace_of(driver)))
        compared += 1
    check(seen == set(CATEGORIES), "%s: categories driven %s" % (name, sorted(seen)))
    check(compared >= states * 0.8, "%s: %d of %d states compared (%d refused)" % (name, compared, states, refused))
    times.sort()
    print("%s: %d states compared bit for bit, %d refused; update median %.1f ms" %
          (name, compared, refused, times[len(times) // 2] if times else float("nan")))


def check_controls_usable(driver, name):
    listed = controls(driver)
    unlabelled = [c["id"] for c in listed if not (c["label"] or "").strip()]
    check(not unlabelled, "%s: controls without a label: %s" % (name, unlabelled))
    untabbable = [c["id"] for c in listed if c["tab"] < 0]
    check(not untabbable, "%s: controls Tab skips: %s" % (name, untabbable))
    slider = next(c for c in listed if c["type"] == "range")
    before = page_state(driver)["scene"]
    driver.find_element(By.ID, slider["id"]).send_keys(Keys.ARROW_RIGHT)
    deadline = time.monotonic() + 30
    while page_state(driver)["scene"] == before and time.monotonic() < deadline:
        time.sleep(0.05)
    check(page_state(driver)["scene"] != before, "%s: the arrow key on %s changed nothing" % (name, slider["label"]))


def check_refusal_save_reset(a, driver, name, own):
    """A refused state keeps the last picture and says why; Save downloads the state shown; Reset
    returns to the scene's own state."""
    before = page_state(driver)
    distance = next(c for c in controls(driver) if c["label"] == "viewport d" and c["type"] == "number")
    set_control(driver, distance["id"], -1)
    after = page_state(driver)
    check(after["status"].startswith("Refused") and "distance" in after["status"],
          "%s: a negative d shows %r" % (name, after["status"]))
    check(after["picture"] == before["picture"], "%s: the refused state changed the picture" % name)
    set_control(driver, distance["id"], 1.25)
    check(page_state(driver)["status"] == "", "%s: the module did not come back after a refusal" % name)
    downloads = os.path.join(a.work, "downloads-" + name)
    os.makedirs(downloads)
    driver.execute_cdp_cmd("Browser.setDownloadBehavior", {"behavior": "allow", "downloadPath": downloads})
    driver.find_element(By.ID, "twinraster-save").click()
    saved = os.path.join(downloads, "%s-state.json" % name)
    deadline = time.monotonic() + 30
    while not os.path.exists(saved) and time.monotonic() < deadline:
        time.sleep(0.1)
    check(os.path.exists(saved) and open(saved).read() == page_state(driver)["scene"],
          "%s: Save did not download the state shown as %s" % (name, os.path.basename(saved)))
    driver.find_element(By.ID, "twinraster-reset").click()
    deadline = time.monotonic() + 30
    while page_state(driver)["scene"] != own["scene"] and time.monotonic() < deadline:
        time.sleep(0.05)
    back = page_state(driver)
    check(back["scene"] == own["scene"], "%s: Reset did not bring back the scene's own text" % name)
    check(back["picture"] == own["picture"] and back["explain"] == own["explain"],
          "%s: Reset did not bring back the scene's own picture and numbers" % name)


def check_scene(a, scene_path, name, states):
    page = moving_page(a, scene_path, name)
    size = os.path.getsize(page)
    print("%s: the page is %d bytes" % (name, size))
    driver = browser()
    try:
        pages.open_page(driver, page)
        wait_ready(driver, name)
        compare_natively(a, driver, name + " own state", os.path.join(a.work, name + "-own.json"), [-1, -1])
        own = page_state(driver)
        check(json.loads(own["scene"]) == json.loads(run([a.exe, "explain", scene_path, "--html", "-"]).stdout
                                                      .split('id="twinraster-scene">')[1].split("</script>")[0]),
              "%s: the page's own state is not the scene it carries" % name)
        check_controls_usable(driver, name)
        check_refusal_save_reset(a, driver, name, own)
        drive(a, driver, name, states)
        if name == "cgfs-transforms":
            screenshot_mid_drag(a, driver)
        pages.check_console(driver, name)
    finally:
        driver.quit()


def screenshot_mid_drag(a, driver):
    """The chapter scene as a learner drags the camera's rotation: the mouse is held on the slider,
    moved, and the page shot before it is let go. Also checks that the drag moved the state."""
    driver.find_element(By.ID, "twinraster-reset").click()
    time.sleep(0.5)
    before = page_state(driver)["scene"]
    camera = [c for c in controls(driver) if c["group"] == "Camera" and c["type"] == "range"]
    slider = driver.find_element(By.ID, camera[-1]["id"])
    driver.execute_script("arguments[0].scrollIntoView({block: 'start'}); window.scrollBy(0, -260);", slider)
    # Press on the thumb itself, where the scene's own value puts it, and drag a little way.
    thumb = driver.execute_script(
        "const s = arguments[0], r = s.getBoundingClientRect();"
        "return Math.round((s.value - s.min) / (s.max - s.min) * (r.width - 16) + 8 - r.width / 2);", slider)
    drag = ActionChains(driver).move_to_element_with_offset(slider, thumb, 0).click_and_hold()
    for _ in range(3):  # the slider spans its whole range in some 150 pixels: a few degrees each
        drag = drag.move_by_offset(2, 0).pause(0.1)
    drag.perform()
    time.sleep(0.5)
    check(page_state(driver)["scene"] != before, "the drag on %s did not move the scene" % camera[-1]["label"])
    pages.screenshot(driver, a.screenshots, "page-chain-moving.png")
    ActionChains(driver).release().perform()


def check_rules_refused(a, scene_path):
    """SwiftShader's rules flush denormals, which WebAssembly cannot: the page says so and draws
    no picture under their name, while the numbers still move."""
    page = os.path.join(a.work, "swiftshader.html")
    run([a.exe, "explain", scene_path, "--html", page, "--device", "swiftshader"])
    driver = browser()
    try:
        pages.open_page(driver, page)
        wait_ready(driver, "swiftshader")
        shown = page_state(driver)
        check(shown["picture"] == "", "swiftshader: the page shows a picture under SwiftShader's rules")
        check(driver.execute_script("return document.getElementById('twinraster-picture').hidden"),
              "swiftshader: the picture's canvas shows")
        caption = driver.find_element(By.CSS_SELECTOR, "#twinraster-twin figcaption").text
        check("No picture" in caption and "SwiftShader" in caption and "lavapipe" in caption,
              "swiftshader: the caption says %r" % caption)
        check(shown["status"].startswith("The picture is not drawn"), "swiftshader: the status says %r" % shown["status"])
        check(json.loads(shown["explain"])["instances"], "swiftshader: no numbers")
        pages.check_console(driver, "swiftshader")
    finally:
        driver.quit()


def case_chapter(a):
    scene = os.path.join(a.source, "scenes", "cgfs-transforms.json")
    check_scene(a, scene, "cgfs-transforms", a.states or 60)
    check_rules_refused(a, scene)


def case_lit(a):
    check_scene(a, os.path.join(a.source, "scenes", "lit-gouraud.json"), "lit-gouraud", a.states or 24)


def grid_scene(a):
    """The chapter's cube as a grid of 10,000 instances (25 x 20 x 20), written here."""
    scene = json.load(open(os.path.join(a.source, "scenes", "catlike-grid.json")))
    scene["comment"] = "A 10,000-instance grid of the chapter's cube (25 x 20 x 20), for the moving page's test and bench."
    scene["canvas"].update({"width": 400, "height": 300})
    scene["camera"]["position"] = [0, 1, -36]
    scene["instances"][0]["grid"]["count"] = [25, 20, 20]
    path = os.path.join(a.work, "grid-10000.json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=2)
    return path


def case_grid(a):
    check_scene(a, grid_scene(a), "grid-10000", a.states or 16)


def case_nojs(a):
    """JavaScript off: the page shows exactly the static page: the same pixels as the page with
    its moving section and scripts taken out, and the panels all there."""
    page = moving_page(a, os.path.join(a.source, "scenes", "cgfs-transforms.json"), "nojs")
    html = open(page).read()
    static = re.sub(r'<section id="twinraster-moving" hidden>.*?</section>\n', "", html, flags=re.S)
    static = re.sub(r"<script[^>]*>.*?</script>\n", "", static, flags=re.S)
    check(static != html and "<script" not in static, "nojs: the page's moving parts were not found")
    static_path = os.path.join(a.work, "static.html")
    with open(static_path, "w") as f:
        f.write(static)
    shots = []
    driver = browser(javascript=False, height=2400)
    try:
        for path in (page, static_path):
            driver.get("file://" + os.path.abspath(path))
            time.sleep(0.5)
            check(len(driver.find_elements(By.CSS_SELECTOR, "figure.chain-panel")) == 6, "nojs: %s lacks panels" % path)
            if path == page:
                check(not driver.find_element(By.ID, "twinraster-moving").is_displayed(), "nojs: the controls show")
            shots.append(driver.get_screenshot_as_png())
    finally:
        driver.quit()
    for path, shot in zip(("nojs-page.png", "nojs-static.png"), shots):
        with open(os.path.join(a.work, path), "wb") as f:
            f.write(shot)
    w1, h1, p1 = pages.png_rgba(os.path.join(a.work, "nojs-page.png"))
    w2, h2, p2 = pages.png_rgba(os.path.join(a.work, "nojs-static.png"))
    check((w1, h1) == (w2, h2) and p1 == p2, "nojs: without JavaScript the page does not look like the static page")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case", choices=["chapter", "lit", "grid", "nojs"])
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--states", type=int, default=0, help="states driven (default: per case)")
    parser.add_argument("--seed", type=int, default=40)
    parser.add_argument("--screenshots", help="save the mid-drag screenshot docs/chain.md shows here")
    a = parser.parse_args()
    a.exe = os.path.abspath(a.exe)
    if os.path.isdir(a.work):
        shutil.rmtree(a.work)
    os.makedirs(a.work)
    globals()["case_" + a.case](a)
    if pages.FAILURES:
        print("%d check(s) failed" % len(pages.FAILURES), file=sys.stderr)
        sys.exit(1)
    print("%s: all checks passed" % a.case)


if __name__ == "__main__":
    main()
