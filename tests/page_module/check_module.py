#!/usr/bin/python3
"""The browser module in headless Chromium (Debian's chromium and chromium-driver, through
python3-selenium), opened from a file:// page that embeds it (base64), without
--allow-file-access-from-files: every number and pixel it computes must equal the native build's.

Cases:
  scenes      for each shipped scene (OBJ meshes made data: URIs, glTF and the million cubes
              left out): tr_explain's JSON equals `twinraster explain SCENE --json` byte for
              byte, tr_update's trace is the vertex that JSON follows, its panels are those of
              `explain --html`, and its picture equals `render --backend cpu`, pixel for pixel;
              also with a traced instance and vertex; tr_redraw draws the same picture again.
  swiftshader SwiftShader's rules (denormals flushed) are refused with 1 and a message, and the
              module keeps drawing lavapipe's.
  refusals    a bad scene, a scene naming an OBJ file and a canvas over tr_max_canvas() trap with
              the problem in tr_message(), and a fresh instance works again.
  fmaf        tr_fmaf_check: the module's fmaf equals the exact reference on every triple, with
              the digest the native build's fmaf gives (fmaf_expected.txt).
The module's imports are wasi_snapshot_preview1's only; they are printed.

Usage: check_module.py CASE --wasm MODULE --exe TWINRASTER --source REPO --work DIR"""
import argparse
import base64
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pages"))
import check_pages as pages  # noqa: E402  (the page tests' shared checks and PNG reading)
from check_pages import FAILURES, check  # noqa: E402

from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.options import Options  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402


def run(args):
    r = subprocess.run(args, capture_output=True)
    if r.returncode != 0:
        sys.exit("FAIL: %s exited %d\n%s" % (" ".join(args), r.returncode, r.stderr.decode(errors="replace")[-3000:]))
    return r.stdout


# The test page: the module embedded, a fresh instance on demand, and one call per export the
# cases use. WASI's functions are stubbed as the product page stubs them: proc_exit throws,
# clock_time_get gives performance.now() in nanoseconds, the rest answer 52 (ENOSYS).
PAGE = """<!doctype html><meta charset="utf-8"><title>twinraster module check</title>
<script>
const moduleBase64 = "%s";
const moduleBytes = Uint8Array.from(atob(moduleBase64), c => c.charCodeAt(0));
let compiled = null, tr = null, messageAt = 0;
const decoder = new TextDecoder(), encoder = new TextEncoder();
const wasiCalls = {};
function wasiStubs(imports) {
  const stubs = {};
  for (const i of imports) {
    const count = () => { wasiCalls[i.name] = (wasiCalls[i.name] || 0) + 1; };
    if (i.name === "proc_exit") stubs[i.name] = code => { count(); throw new Error("proc_exit " + code); };
    else if (i.name === "clock_time_get") stubs[i.name] = (clock, precision, at) => {
      // The twin times its draw (libc++'s steady_clock): nanoseconds, which must succeed.
      count();
      new DataView(tr.memory.buffer).setBigUint64(at, BigInt(Math.round(performance.now() * 1e6)), true);
      return 0;
    };
    else stubs[i.name] = () => { count(); return 52; };
  }
  return stubs;
}
async function fresh() {
  compiled = compiled || await WebAssembly.compile(moduleBytes);
  const imports = WebAssembly.Module.imports(compiled);
  const instance = await WebAssembly.instantiate(compiled, {wasi_snapshot_preview1: wasiStubs(imports)});
  tr = instance.exports;
  if (tr._initialize) tr._initialize();
  messageAt = tr.tr_message();
  return imports.map(i => i.module + "." + i.name);
}
function text(at, size) { return decoder.decode(new Uint8Array(tr.memory.buffer, at, size)); }
function message() { return text(messageAt, tr.tr_message_size()); }
function base64Of(bytes) {
  let s = "";
  for (let i = 0; i < bytes.length; i += 32768) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 32768));
  return btoa(s);
}
function update(sceneText, instance, vertex) {
  const bytes = encoder.encode(sceneText);
  const at = tr.tr_alloc(bytes.length);
  new Uint8Array(tr.memory.buffer, at, bytes.length).set(bytes);
  try {
    const status = tr.tr_update(at, bytes.length, instance, vertex);
    const explained = tr.tr_explain(at, bytes.length, instance, vertex);
    tr.tr_free(at);
    return {status: status + explained, message: message(), json: text(tr.tr_explain_json(), tr.tr_explain_json_size()),
            trace: text(tr.tr_trace(), tr.tr_trace_size()),
            panels: text(tr.tr_panels(), tr.tr_panels_size()), width: tr.tr_picture_width(),
            height: tr.tr_picture_height(), picture: picture()};
  } catch (e) {
    return {trapped: e instanceof WebAssembly.RuntimeError, error: String(e), message: message()};
  }
}
function picture() {
  const size = tr.tr_picture_width() * tr.tr_picture_height() * 4;
  return base64Of(new Uint8Array(tr.memory.buffer, tr.tr_picture(), size));
}
</script>
<p>twinraster's browser module, checked.</p>
"""


def browser():
    options = Options()
    # No --allow-file-access-from-files: the page must work as a learner's browser opens it.
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
        options.add_argument(a)
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    return webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"), options=options)


def call(driver, script, *args):
    """Runs `script` (which may await) in the page and returns its value."""
    return driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "(async () => { " + script + " })().then(done, e => done({exception: String(e)}));", *args)


def fresh(driver):
    imports = call(driver, "return await fresh();")
    check(isinstance(imports, list) and all(i.startswith("wasi_snapshot_preview1.") for i in imports),
          "the module imports only WASI's functions: %s" % imports)
    return imports


NATIVE_RULES = []


def native_rules(a):
    """The rules `render --backend cpu` follows here, as tr_set_rules' arguments: lavapipe's, with
    FMA and the vector width of this machine's CPU path, Mesa 25's line rules from 25 on."""
    if not NATIVE_RULES:
        out = os.path.join(a.work, "rules.png")
        if os.path.exists(out):
            os.remove(out)
        twin = json.loads(run([a.exe, "render", os.path.join(a.source, "scenes", "cgfs-transforms.json"),
                               "--backend", "cpu", "-o", out, "--json"]))["twin_rules"]
        check(twin["rasterizer"] == "lavapipe", "the native twin follows %s, not lavapipe" % twin["rasterizer"])
        mesa25 = int(twin["mesa"].split(".")[0]) >= 25
        NATIVE_RULES.extend([0, 0, int("FMA" in twin["instruction_set"]), 0, int(mesa25), int(mesa25), 0,
                             int(twin["vector_bits"])])
        print("native rules: %s (%s)" % (NATIVE_RULES, twin["text"]))
    return NATIVE_RULES


def lavapipe_rules(driver, a):
    return call(driver, "return tr.tr_set_rules(...arguments[0]);", native_rules(a))


def inline_meshes(path, work):
    """The scene at `path` with each model's "obj" file given as a data: URI, written to `work`."""
    scene = json.load(open(path, encoding="utf-8"))
    for model in scene["models"].values():
        if "obj" in model:
            mesh = open(os.path.join(os.path.dirname(path), model["obj"]), "rb").read()
            model["obj"] = "data:model/obj;base64," + base64.b64encode(mesh).decode()
    inline = os.path.join(work, "inline-" + os.path.basename(path))
    text = json.dumps(scene, indent=1)
    with open(inline, "w", encoding="utf-8") as f:
        f.write(text)
    return inline, text


def case_scenes(driver, a):
    scenes = [s for s in sorted(os.listdir(os.path.join(a.source, "scenes"))) if s.endswith(".json")]
    checked = 0
    for name in scenes:
        path = os.path.join(a.source, "scenes", name)
        text = open(path, encoding="utf-8").read()
        if '"gltf"' in text or "million" in name:
            continue  # a glTF model, or a million instances
        if '"obj"' in text:
            # The page carries a scene's meshes inline: the OBJ files as data: URIs, in a scene file
            # the native build reads too.
            path, text = inline_meshes(path, a.work)
            name = os.path.basename(path)
        for instance, vertex, extra in ((-1, -1, []), (1, 3, ["--instance", "1", "--vertex", "3"])):
            native = subprocess.run([a.exe, "explain", path, "--json"] + extra, capture_output=True)
            if instance >= 0 and native.returncode == 2:
                continue  # a scene with one instance has no instance 1
            what = "%s (instance %d, vertex %d)" % (name, instance, vertex)
            check(native.returncode == 0, "%s: explain --json exited %d" % (what, native.returncode))
            got = call(driver, "return update(arguments[0], arguments[1], arguments[2]);", text, instance, vertex)
            if not check(got.get("status") == 0, "%s: tr_update failed: %s" % (what, str(got)[:300])):
                continue
            native_json = native.stdout.decode()
            # The page's scene is named "page" (page_module::kPageSceneName), the file's by its stem.
            named = got["json"].replace('"scene": "page"', '"scene": "%s"' % name[:-len(".json")], 1)
            check(named + "\n" == native_json, "%s: the module's explain JSON differs from explain --json" % what)
            check(json.loads(got["trace"]) == pages.followed_vertex(json.loads(native_json), vertex >= 0),
                  "%s: tr_trace is not the vertex explain --json follows: %s" % (what, got["trace"][:300]))
            native_page = run([a.exe, "explain", path, "--html", "-"] + extra).decode()
            check(len(got["panels"]) > 1000 and got["panels"] in native_page,
                  "%s: the module's panels are not those of explain --html" % what)
            png = os.path.join(a.work, name + ".png")
            if os.path.exists(png):
                os.remove(png)
            run([a.exe, "render", path, "--backend", "cpu", "-o", png])
            width, height, rgba = pages.png_rgba(png)
            picture = base64.b64decode(got["picture"])
            check((got["width"], got["height"]) == (width, height), "%s: picture size %sx%s, native %dx%d"
                  % (what, got["width"], got["height"], width, height))
            differing = sum(1 for i in range(0, min(len(rgba), len(picture)), 4) if rgba[i:i + 4] != picture[i:i + 4])
            check(len(picture) == len(rgba) and differing == 0,
                  "%s: %d pixels differ from render --backend cpu" % (what, differing))
            checked += 1
        redrawn = call(driver, "tr.tr_redraw(); return picture();")
        check(redrawn == got["picture"], "%s: tr_redraw drew another picture" % name)
    check(checked >= 10, "only %d scene states were compared" % checked)
    print("compared %d scene states with the native build" % checked)


def case_swiftshader(driver, a):
    refused = call(driver, "return [tr.tr_set_rules(1, 1, 0, 0, 0, 0, 0, 128), message()];")
    check(refused[0] == 1, "SwiftShader's rules were not refused: %s" % refused)
    check("denormals" in refused[1], "the refusal does not say why: %r" % refused[1])
    scene = open(os.path.join(a.source, "scenes", "cgfs-transforms.json"), encoding="utf-8").read()
    got = call(driver, "return update(arguments[0], -1, -1);", scene)
    check(got.get("status") == 0, "after the refusal the module no longer draws: %s" % got)


def case_refusals(driver, a):
    scene = json.load(open(os.path.join(a.source, "scenes", "cgfs-transforms.json"), encoding="utf-8"))
    bad = {"not JSON": ("{", "page"),
           "an unknown model": (json.dumps(dict(scene, instances=[{"model": "nothing"}])), "nothing"),
           "an OBJ file": (json.dumps(dict(scene, models={"cube": {"obj": "meshes/cube.obj"}})), "reads no file"),
           "a canvas over the limit": (json.dumps(dict(scene, canvas={"width": 4096, "height": 600})), "larger than"),
           "a vertex it lacks": (json.dumps(scene), "vertex")}
    limit = call(driver, "return tr.tr_max_canvas();")
    check(limit == 2048, "tr_max_canvas() is %s, docs/building.md says 2048" % limit)
    for what, (text, words) in bad.items():
        vertex = 99 if what == "a vertex it lacks" else -1
        got = call(driver, "return update(arguments[0], -1, arguments[1]);", text, vertex)
        check(got.get("trapped") is True, "%s: no trap: %s" % (what, str(got)[:300]))
        check(words in got.get("message", ""), "%s: the message %r does not say %r" % (what, got.get("message"), words))
        print("%s: %s" % (what, got.get("message")))
        fresh(driver)
        lavapipe_rules(driver, a)
        again = call(driver, "return update(arguments[0], -1, -1);", json.dumps(scene))
        check(again.get("status") == 0, "%s: a fresh instance does not draw: %s" % (what, str(again)[:300]))


def case_fmaf(driver, a):
    expected = open(os.path.join(a.source, "tests", "page_module", "fmaf_expected.txt")).read().strip()
    got = call(driver, "const n = tr.tr_fmaf_check(1, 1200000); return [n, message()];")
    print("module: " + str(got))
    check(got[0] == 0, "the module's fmaf differs from the exact reference on %s triples" % got[0])
    check(got[1].startswith(expected + ","), "the module's run %r is not the native run %r" % (got[1], expected))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case", choices=["scenes", "swiftshader", "refusals", "fmaf"])
    parser.add_argument("--wasm", required=True)
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--work", required=True)
    a = parser.parse_args()
    os.makedirs(a.work, exist_ok=True)
    module = open(a.wasm, "rb").read()
    page = os.path.join(a.work, "module-check.html")
    with open(page, "w", encoding="utf-8") as f:
        f.write(PAGE % base64.b64encode(module).decode())
    print("module: %d bytes, %d as base64" % (len(module), len(base64.b64encode(module))))
    driver = browser()
    try:
        driver.set_script_timeout(300)
        driver.get("file://" + os.path.abspath(page))
        print("imports: " + ", ".join(fresh(driver)))
        check(lavapipe_rules(driver, a) == 0, "lavapipe's rules were refused")
        {"scenes": case_scenes, "swiftshader": case_swiftshader, "refusals": case_refusals, "fmaf": case_fmaf}[a.case](driver, a)
        # What the module asked of WASI: nothing a case needs (every stub answers ENOSYS).
        print("WASI calls: %s" % call(driver, "return wasiCalls;"))
    finally:
        driver.quit()
    if FAILURES:
        sys.exit("%d failures" % len(FAILURES))
    print("ok")


if __name__ == "__main__":
    main()
