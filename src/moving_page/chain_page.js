// The moving chain page's script: it wires the controls to the scene and draws what the embedded
// module computes. The module is twinraster's own C++ (the loader, the chain, explain's writers
// and the CPU twin) compiled to WebAssembly; every number and every pixel shown comes from it.
// This script computes none: it edits the scene file's JSON, hands its text to the module, and
// puts the panels, the picture and the traced vertex's numbers on the page.
//
// The test interface, window.twinrasterPage (for the page tests and the bench script):
//   ready                 a Promise, resolved once the module has drawn the scene's own state
//                         (rejected when the module cannot run here)
//   sceneText()           the scene as the module last received it: a scene file's text
//   setControl(id, value) sets control `id` (an element id) to `value` and fires the event a
//                         user's input fires; returns a Promise resolved once that state is drawn
//   lastUpdateMs          milliseconds of the last update: the module's work and the drawing
//   pictureRgbaBase64()   the picture shown, RGBA8, top row first, in base64 ("" when none)
//   explainJson()         explain --json's text for the state shown, which the module writes when
//                         asked (never on a change: a lit mesh's is megabytes)
//   controlIds()          the ids of every control, in page order (a number field's slider is
//                         its id + "-slider")
//   redrawMs(count)       the twin's draw alone for the state shown (tr_redraw), timed `count`
//                         times: an array of milliseconds
"use strict";

(() => {
  const byId = (id) => document.getElementById(id);
  const originalText = byId("twinraster-scene").textContent;
  const page = JSON.parse(byId("twinraster-page").textContent);
  const encoder = new TextEncoder();
  const decoder = new TextDecoder();

  let state = JSON.parse(originalText);  // the scene file, as the controls have edited it
  // The scene's own state goes to the module as the page carries it, byte for byte: JSON.stringify
  // would write a negative zero without its sign, and the own state must be the file's to the bit.
  const ownText = JSON.stringify(state, null, 2);
  let trace = { instance: page.instance, vertex: page.vertex };  // -1: explain's default
  let sentText = "";  // what the module last received
  let drawn = null;  // the last state the module drew, { text, trace }: sentText unless refused
  let lastPicture = null;  // { width, height, rgba }
  let rulesRefused = "";  // why the module cannot draw by the page's rules, or ""

  // ---- the module -------------------------------------------------------------------------

  function base64Bytes(text) {
    const binary = atob(text.replace(/\s+/g, ""));
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }

  // WASI imports, stubbed: the module reads no file and needs no clock; what it prints goes to the
  // console. Any call not listed answers ENOSYS (52).
  function wasiImports(compiled, memoryOf) {
    const view = () => new DataView(memoryOf().buffer);
    const known = {
      fd_write(fd, iovs, count, written) {
        let total = 0;
        let text = "";
        for (let i = 0; i < count; ++i) {
          const base = view().getUint32(iovs + 8 * i, true);
          const length = view().getUint32(iovs + 8 * i + 4, true);
          text += decoder.decode(new Uint8Array(memoryOf().buffer, base, length));
          total += length;
        }
        if (text) (fd === 2 ? console.warn : console.log)("twinraster module: " + text);
        view().setUint32(written, total, true);
        return 0;
      },
      proc_exit(code) {
        throw new Error("the module exited with code " + code);
      },
      environ_sizes_get(count, size) {
        view().setUint32(count, 0, true);
        view().setUint32(size, 0, true);
        return 0;
      },
      args_sizes_get(count, size) {
        view().setUint32(count, 0, true);
        view().setUint32(size, 0, true);
        return 0;
      },
      environ_get: () => 0,
      args_get: () => 0,
      clock_time_get(id, precision, time) {
        view().setBigUint64(time, BigInt(Math.round(performance.now() * 1e6)), true);
        return 0;
      },
      random_get(buffer, length) {
        crypto.getRandomValues(new Uint8Array(memoryOf().buffer, buffer, length));
        return 0;
      },
    };
    const imports = {};
    for (const entry of WebAssembly.Module.imports(compiled)) {
      if (entry.kind !== "function") continue;
      imports[entry.module] = imports[entry.module] || {};
      imports[entry.module][entry.name] = known[entry.name] || (() => 52);
    }
    return imports;
  }

  let compiledModule = null;
  let module = null;  // { exports, memory, messageAddress }

  function readText(pointer, size) {
    return decoder.decode(new Uint8Array(module.memory.buffer, pointer, size));
  }

  // The module's message after a refusal; after a trap its size is read from the instance if it
  // still answers, else up to the first NUL of its fixed buffer.
  function moduleMessage() {
    try {
      return readText(module.exports.tr_message(), module.exports.tr_message_size());
    } catch (error) {
      const bytes = new Uint8Array(module.memory.buffer, module.messageAddress, 4096);
      const end = bytes.indexOf(0);
      return decoder.decode(bytes.subarray(0, end < 0 ? bytes.length : end));
    }
  }

  async function instantiate() {
    let memory = null;
    const instance = await WebAssembly.instantiate(compiledModule, wasiImports(compiledModule, () => memory));
    memory = instance.exports.memory;
    if (instance.exports._initialize) instance.exports._initialize();
    module = { exports: instance.exports, memory, messageAddress: instance.exports.tr_message() };
    // The page's bound on a canvas side, and the module's own where it states one.
    if (module.exports.tr_max_canvas) page.canvas_max = Math.min(page.canvas_max, module.exports.tr_max_canvas());
    const refused = module.exports.tr_set_rules(...page.rules.arguments);
    rulesRefused = refused === 0 ? "" : moduleMessage() || "the module cannot follow these rules";
    if (rulesRefused) {
      // Never another device's picture under these rules' name: no picture, and why.
      byId("twinraster-twin").querySelector("figcaption").textContent =
        "No picture: the browser cannot draw by " + page.rules.text + " (" + rulesRefused + "). " +
        "It draws by lavapipe's rules, which need no flushing of denormals: " +
        "write the page with explain --html FILE --device lavapipe.";
    }
  }

  // Calls the module's export `name` (tr_update or tr_explain) on a scene text and a trace
  // ({ instance, vertex }). Returns null, or the module's message when it refused (it throws
  // inside, which reaches here as a trap).
  function callWithScene(name, text, at) {
    const bytes = encoder.encode(text);
    const pointer = module.exports.tr_alloc(bytes.length);
    new Uint8Array(module.memory.buffer, pointer, bytes.length).set(bytes);
    try {
      module.exports[name](pointer, bytes.length, at.instance, at.vertex);
      return null;
    } catch (error) {
      return moduleMessage() || String(error);
    } finally {
      try {
        module.exports.tr_free(pointer);
      } catch (ignored) {
        // a trapped instance is replaced whole: its memory goes with it
      }
    }
  }

  // One state through the module: its panels, the traced vertex and the picture, or `refusal`.
  function compute(text) {
    const refusal = callWithScene("tr_update", text, trace);
    if (refusal !== null) return { refusal };
    const e = module.exports;
    const width = e.tr_picture_width();
    const height = e.tr_picture_height();
    const rgba = new Uint8ClampedArray(module.memory.buffer, e.tr_picture(), width * height * 4).slice();
    return {
      panels: readText(e.tr_panels(), e.tr_panels_size()),
      trace: readText(e.tr_trace(), e.tr_trace_size()),
      picture: { width, height, rgba },
    };
  }

  // explain --json's text for the state drawn; asked for by tests and scripts only (it is
  // megabytes for a lit mesh), so never on a change.
  function explainJson() {
    if (drawn === null) return "";
    const refusal = callWithScene("tr_explain", drawn.text, drawn.trace);
    if (refusal !== null) throw new Error("explain JSON refused: " + refusal);
    return readText(module.exports.tr_explain_json(), module.exports.tr_explain_json_size());
  }

  // ---- drawing ------------------------------------------------------------------------------

  function setStatus(text) {
    byId("twinraster-status").textContent = text;
  }

  function showPicture(picture) {
    const canvas = byId("twinraster-picture");
    if (rulesRefused) {
      canvas.hidden = true;
      return;
    }
    canvas.hidden = false;
    canvas.width = picture.width;
    canvas.height = picture.height;
    canvas.getContext("2d").putImageData(new ImageData(picture.rgba, picture.width, picture.height), 0, 0);
  }

  function numbers(list) {
    return "(" + list.map((x) => (x === null ? "none" : Number(x).toPrecision(6))).join(", ") + ")";
  }

  // The traced vertex as the module gives it: the first instance shown and the vertex its trace
  // follows, in explain --json's words (explain_report::FollowedVertexJson).
  function showTrace(traceText) {
    const followed = JSON.parse(traceText);
    const v = followed && followed.vertex;
    byId("twinraster-trace").textContent = !v
      ? "no vertex to trace"
      : "instance " + followed.instance + ", vertex " + v.index + ": clip " + numbers(v.clip) +
        ", NDC " + numbers(v.ndc) + ", pixel " + numbers(v.framebuffer.slice(0, 2));
  }

  // ---- updates, one at a time, the last value winning ---------------------------------------

  let frameAsked = false;
  let running = false;  // an update is under way (a refusal re-instantiates the module: it awaits)
  let again = false;  // the state changed while it ran: one more update, with the last values
  let lastDone = -Infinity;  // when the last update ended (performance.now())
  let waiting = [];  // setControl's promises, settled once the state they set is drawn

  // A change is drawn at once while updates are quick (under half a frame: the browser sends a
  // drag's input events once a frame). After a slow update, the changes that follow within a
  // frame wait for the next animation frame, so that they coalesce into one update, the last
  // values winning. Either way at most one update is ever in flight.
  function scheduleUpdate() {
    if (running) {
      again = true;
      return;
    }
    if (frameAsked) return;
    frameAsked = true;
    const inBurst = performance.now() - lastDone < 16 && api.lastUpdateMs > 8;
    if (inBurst) requestAnimationFrame(runUpdate);
    else queueMicrotask(runUpdate);
  }

  async function runUpdate() {
    frameAsked = false;
    running = true;
    try {
      await update();
    } catch (error) {
      setStatus("The page failed: " + error);
    } finally {
      running = false;
      lastDone = performance.now();
    }
    if (again) {
      again = false;
      scheduleUpdate();
    } else {
      settle();
    }
  }

  function settle() {
    const done = waiting;
    waiting = [];
    for (const resolve of done) resolve();
  }

  async function update() {
    const start = performance.now();
    const edited = JSON.stringify(state, null, 2);
    const text = edited === ownText ? originalText : edited;
    const result = compute(text);
    sentText = text;
    if (result.refusal !== undefined) {
      setStatus("Refused: " + result.refusal + " (the picture is the last state drawn)");
      await instantiate();
      api.lastUpdateMs = performance.now() - start;
      return;
    }
    byId("twinraster-panels").innerHTML = result.panels;
    drawn = { text, trace: { ...trace } };
    lastPicture = result.picture;
    showPicture(result.picture);
    showTrace(result.trace);
    setStatus(rulesRefused ? "The picture is not drawn: " + rulesRefused : "");
    api.lastUpdateMs = performance.now() - start;
  }

  // ---- the controls -------------------------------------------------------------------------

  function getAt(object, path) {
    for (const key of path) {
      if (object === undefined || object === null) return undefined;
      object = object[key];
    }
    return object;
  }

  function setAt(object, path, value) {
    for (const key of path.slice(0, -1)) {
      if (object[key] === undefined || object[key] === null) object[key] = {};
      object = object[key];
    }
    object[path[path.length - 1]] = value;
  }

  // A range that holds the scene's own value with room either side.
  function around(value, span, lowest) {
    const reach = Math.max(span, Math.abs(value) * 2);
    return { min: Math.max(lowest, value - reach), max: value + reach };
  }

  function positive(value) {
    return { min: value / 20, max: value * 4 };
  }

  let controlSerial = 0;

  // A control's row, its id and its label, which names the control by that id.
  function labelledRow(label) {
    const id = "twinraster-control-" + ++controlSerial;
    const row = document.createElement("div");
    row.className = "twinraster-control";
    const name = document.createElement("label");
    name.htmlFor = id;
    name.textContent = label;
    return { id, row, name };
  }

  // A labelled slider and number field that move together; `set` writes the value into the scene.
  function numberControl(parent, label, value, range, step, set) {
    const { id, row, name } = labelledRow(label);
    const slider = document.createElement("input");
    slider.type = "range";
    slider.min = String(range.min);
    slider.max = String(range.max);
    slider.step = String(step);
    slider.value = String(value);
    slider.setAttribute("aria-label", label + " (slider)");
    const field = document.createElement("input");
    field.type = "number";
    field.id = id;
    field.step = "any";
    field.value = String(value);
    // `set` may answer the value it used instead (a bound applied): both then show that.
    const moved = (source, other) => () => {
      const number = Number(source.value);
      if (source.value === "" || !Number.isFinite(number)) return;
      const used = set(number);
      other.value = String(used === undefined ? number : used);
      if (used !== undefined && used !== number) source.value = String(used);
      scheduleUpdate();
    };
    slider.addEventListener("input", moved(slider, field));
    field.addEventListener("input", moved(field, slider));
    slider.id = id + "-slider";
    row.append(name, slider, field);
    parent.append(row);
    return { slider, field };
  }

  function choiceControl(parent, label, options, value, set) {
    const { id, row, name } = labelledRow(label);
    const select = document.createElement("select");
    select.id = id;
    for (const [optionValue, text] of options) {
      const option = document.createElement("option");
      option.value = optionValue;
      option.textContent = text;
      select.append(option);
    }
    select.value = value;
    select.addEventListener("input", () => set(select.value));
    row.append(name, select);
    parent.append(row);
    return select;
  }

  function group(parent, title) {
    const fieldset = document.createElement("fieldset");
    const legend = document.createElement("legend");
    legend.textContent = title;
    fieldset.append(legend);
    parent.append(fieldset);
    return fieldset;
  }

  const axes = ["x", "y", "z"];

  function vectorControls(parent, label, path, fallback, span, lowest) {
    const read = () => {
      const v = getAt(state, path);
      if (typeof v === "number") return [v, v, v];  // a scale written as one number
      return Array.isArray(v) ? v.slice() : fallback.slice();
    };
    read().forEach((value, i) => {
      numberControl(parent, label + " " + axes[i], value, around(value, span, lowest), 0.01, (x) => {
        const v = read();
        v[i] = x;
        setAt(state, path, v);
      });
    });
  }

  function axisName(axis) {
    return Array.isArray(axis) ? "[" + axis.join(", ") + "]" : String(axis);
  }

  // A rotation as written (one object or a list of them), each angle its own control; none
  // written: a rotation about y from 0, written into the scene only once moved.
  function rotationControls(parent, label, path) {
    const rotation = getAt(state, path);
    const steps = Array.isArray(rotation) ? rotation.map((r, i) => [...path, i]) : [path];
    for (const stepPath of steps) {
      const written = getAt(state, stepPath);
      const degrees = written ? Number(written.degrees) : 0;
      const about = written ? axisName(written.axis) : "y";
      const range = { min: Math.min(-180, degrees - 180), max: Math.max(180, degrees + 180) };
      numberControl(parent, label + " about " + about + " (degrees)", degrees, range, 0.5, (x) => {
        const r = getAt(state, stepPath);
        if (r) r.degrees = x;
        else setAt(state, stepPath, { axis: "y", degrees: x });
      });
    }
  }

  function cameraControls(parent) {
    const fieldset = group(parent, "Camera");
    if (state.camera && state.camera.eye) {
      vectorControls(fieldset, "eye", ["camera", "eye"], [0, 0, 0], 10, -Infinity);
      vectorControls(fieldset, "center", ["camera", "center"], [0, 0, 0], 10, -Infinity);
      return;
    }
    vectorControls(fieldset, "position", ["camera", "position"], [0, 0, 0], 10, -Infinity);
    rotationControls(fieldset, "rotation", ["camera", "rotation"]);
  }

  function copiesOf(written) {
    const count = written.grid && written.grid.count;
    return Array.isArray(count) ? count.reduce((a, b) => a * b, 1) : 1;
  }

  function transformControls(parent, index) {
    const base = ["instances", index, "transform"];
    const transform = getAt(state, base);
    if (Array.isArray(transform)) {
      transform.forEach((step, i) => {
        const at = [...base, i];
        if ("scale" in step) vectorControls(parent, "step " + i + " scale", [...at, "scale"], [1, 1, 1], 2, -Infinity);
        if ("rotation" in step) rotationControls(parent, "step " + i + " rotation", [...at, "rotation"]);
        if ("translation" in step) {
          vectorControls(parent, "step " + i + " translation", [...at, "translation"], [0, 0, 0], 10, -Infinity);
        }
      });
      return;
    }
    vectorControls(parent, "scale", [...base, "scale"], [1, 1, 1], 2, -Infinity);
    rotationControls(parent, "rotation", [...base, "rotation"]);
    vectorControls(parent, "translation", [...base, "translation"], [0, 0, 0], 10, -Infinity);
  }

  let chosenInstance = 0;

  function instanceControls(parent) {
    const fieldset = group(parent, "Instance");
    const options = state.instances.map((written, i) => {
      const copies = copiesOf(written);
      return [String(i), "instance " + i + " (model \"" + written.model + "\")" +
        (copies > 1 ? ", a grid of " + copies + " copies" : "")];
    });
    const transforms = document.createElement("div");
    choiceControl(fieldset, "instance to move", options, String(chosenInstance), (value) => {
      chosenInstance = Number(value);
      transforms.replaceChildren();
      transformControls(transforms, chosenInstance);
    });
    fieldset.append(transforms);
    transformControls(transforms, chosenInstance);
  }

  function viewControls(parent) {
    const fieldset = group(parent, "Viewport and depth");
    for (const [key, label] of [["width", "Vw"], ["height", "Vh"], ["distance", "d"]]) {
      const value = getAt(state, ["viewport", key]);
      numberControl(fieldset, "viewport " + label, value, positive(value), value / 200, (x) => {
        state.viewport[key] = x;
      });
    }
    for (const [key, fallback] of [["near", 0.1], ["far", 100]]) {
      const written = getAt(state, ["depth", key]);
      const value = written === undefined ? fallback : written;
      numberControl(fieldset, "depth " + key, value, positive(value), value / 200, (x) => {
        setAt(state, ["depth", key], x);
      });
    }
    const projection = getAt(state, ["viewport", "projection"]) || "perspective";
    choiceControl(fieldset, "projection", [["perspective", "perspective"], ["orthographic", "orthographic"]],
      String(projection).toLowerCase(), (value) => {
        state.viewport.projection = value;
        scheduleUpdate();
      });
  }

  // The scene's instances, grids' copies included, and the model of scene instance `i`.
  function sceneInstances() {
    return state.instances.reduce((sum, written) => sum + copiesOf(written), 0);
  }

  function modelOfSceneInstance(i) {
    for (const written of state.instances) {
      const copies = copiesOf(written);
      if (i < copies) return written.model;
      i -= copies;
    }
    return state.instances[0].model;
  }

  function traceControls(parent) {
    const fieldset = group(parent, "Traced vertex (-1: explain's choice, the first vertex in view)");
    // Without a traced instance, explain traces vertex V of every instance it shows (the first
    // page.explained_instances): V must be one each of their models has.
    const vertexBound = () => {
      const shown = trace.instance >= 0 ? [trace.instance] : [...Array(Math.min(page.explained_instances, sceneInstances())).keys()];
      return Math.min(...shown.map((i) => page.vertex_counts[modelOfSceneInstance(i)] || 1)) - 1;
    };
    let vertex = null;
    numberControl(fieldset, "traced instance", trace.instance, { min: -1, max: sceneInstances() - 1 }, 1, (x) => {
      trace.instance = Math.min(Math.max(Math.round(x), -1), sceneInstances() - 1);
      // Another instance may have another model: the vertex's bound follows it.
      vertex.slider.max = String(vertexBound());
      trace.vertex = Math.min(trace.vertex, vertexBound());
      vertex.field.value = vertex.slider.value = String(trace.vertex);
      return trace.instance;
    });
    vertex = numberControl(fieldset, "traced vertex", trace.vertex, { min: -1, max: vertexBound() }, 1, (x) => {
      trace.vertex = Math.min(Math.max(Math.round(x), -1), vertexBound());
      return trace.vertex;
    });
  }

  function canvasControls(parent) {
    const fieldset = group(parent, "Canvas (" + page.canvas_min + " to " + page.canvas_max + " pixels a side)");
    for (const key of ["width", "height"]) {
      const range = { min: page.canvas_min, max: page.canvas_max };
      numberControl(fieldset, "canvas " + key, state.canvas[key], range, 1, (x) => {
        state.canvas[key] = Math.min(page.canvas_max, Math.max(page.canvas_min, Math.round(x)));
        return state.canvas[key];
      });
    }
  }

  function buildControls() {
    controlSerial = 0;
    const parent = byId("twinraster-controls");
    parent.replaceChildren();
    cameraControls(parent);
    instanceControls(parent);
    viewControls(parent);
    traceControls(parent);
    canvasControls(parent);
  }

  // ---- save, reset, the test interface --------------------------------------------------------

  function save() {
    const url = URL.createObjectURL(new Blob([sentText], { type: "application/json" }));
    const link = document.createElement("a");
    link.href = url;
    link.download = page.name + "-state.json";
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 1000);
  }

  function reset() {
    state = JSON.parse(originalText);
    trace = { instance: page.instance, vertex: page.vertex };
    chosenInstance = 0;
    buildControls();
    scheduleUpdate();
  }

  function bytesBase64(bytes) {
    let binary = "";
    for (let i = 0; i < bytes.length; i += 0x8000) {
      binary += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    }
    return btoa(binary);
  }

  const api = {
    ready: null,
    lastUpdateMs: 0,
    sceneText: () => sentText,
    explainJson,
    pictureRgbaBase64: () => (lastPicture && !rulesRefused ? bytesBase64(lastPicture.rgba) : ""),
    controlIds: () => Array.from(byId("twinraster-controls").querySelectorAll("input, select"), (c) => c.id),
    redrawMs(count) {
      // The twin's draw alone, again for the state shown (tr_redraw), timed `count` times.
      const times = [];
      for (let i = 0; i < count; ++i) {
        const start = performance.now();
        if (module.exports.tr_redraw() !== 0) throw new Error("tr_redraw failed: " + moduleMessage());
        times.push(performance.now() - start);
      }
      return times;
    },
    setControl(id, value) {
      const control = byId(id);
      if (!control) return Promise.reject(new Error("no control " + id));
      control.value = String(value);
      const done = new Promise((resolve) => waiting.push(resolve));
      control.dispatchEvent(new Event("input", { bubbles: true }));
      scheduleUpdate();  // a value the control refuses still settles, with the state unchanged
      return done;
    },
  };
  window.twinrasterPage = api;

  async function start() {
    compiledModule = await WebAssembly.compile(base64Bytes(byId("twinraster-module").textContent));
    await instantiate();
    buildControls();
    byId("twinraster-save").addEventListener("click", save);
    byId("twinraster-reset").addEventListener("click", reset);
    byId("twinraster-moving").hidden = false;
    await update();
  }

  api.ready = start().catch((error) => {
    console.error("twinraster: the page does not move: " + error);
    throw error;
  });
})();
