// The lighting lab's page: the scene is a scene-file JSON object (docs/scene-format.md) that
// the controls edit in place; every render sends it to POST /api/render. Inputs name the
// value they edit with data-path (e.g. "lights[2].diffuse[0]"), the key path the server uses
// in its error messages, so an error lands next to its field.
"use strict";

const state = { scene: null, presets: [], objFiles: [], seq: 0, inflight: null, pending: false, tess: 32,
                undo: [], redo: [], figures: [], rows: [], row: null };

const $ = (id) => document.getElementById(id);
const clone = (v) => JSON.parse(JSON.stringify(v));

// ---- key paths ------------------------------------------------------------------------
function parsePath(path) {
  const parts = [];
  path.replace(/([^.[\]]+)|\[(\d+)\]/g, (_, key, index) => { parts.push(key !== undefined ? key : Number(index)); });
  return parts;
}
function getPath(obj, path) {
  return parsePath(path).reduce((o, k) => (o == null ? undefined : o[k]), obj);
}
function setPath(obj, path, value) {
  const parts = parsePath(path);
  let o = obj;
  for (let i = 0; i < parts.length - 1; ++i) {
    if (o[parts[i]] == null) o[parts[i]] = typeof parts[i + 1] === "number" ? [] : {};
    o = o[parts[i]];
  }
  o[parts[parts.length - 1]] = value;
}

// ---- the scene, with every value the controls show made explicit ----------------------
const LIGHT_DEFAULTS = (i) => ({
  position: [0, 0, 1, 0], ambient: [0, 0, 0, 1],
  diffuse: i === 0 ? [1, 1, 1, 1] : [0, 0, 0, 1], specular: i === 0 ? [1, 1, 1, 1] : [0, 0, 0, 1],
  attenuation: { constant: 1, linear: 0, quadratic: 0 },
  spot: { direction: [0, 0, -1], cutoff: 180, exponent: 0 }, enabled: true,
});
const MATERIAL_DEFAULTS = () => ({
  ambient: [0.2, 0.2, 0.2, 1], diffuse: [0.8, 0.8, 0.8, 1], specular: [0, 0, 0, 1],
  emission: [0, 0, 0, 1], shininess: 0, specular_model: "blinn",
});
function rgba(c, fallback) {
  const v = Array.isArray(c) ? c.slice() : fallback.slice();
  while (v.length < 4) v.push(v.length === 3 ? 1 : 0);
  return v;
}
function normalizeScene(scene) {
  const s = clone(scene);
  s.lights = (s.lights || []).map((l, i) => {
    const d = LIGHT_DEFAULTS(i);
    return {
      ...l,
      position: l.position || d.position, ambient: rgba(l.ambient, d.ambient),
      diffuse: rgba(l.diffuse, d.diffuse), specular: rgba(l.specular, d.specular),
      attenuation: { ...d.attenuation, ...(l.attenuation || {}) },
      spot: { ...d.spot, ...(l.spot || {}) }, enabled: l.enabled !== false,
    };
  });
  s.camera = { eye: [0, 0, 8], target: [0, 0, 0], up: [0, 1, 0], ...(s.camera || {}) };
  s.light_model = { ambient: [0.2, 0.2, 0.2, 1], local_viewer: false, two_side: false, ...(s.light_model || {}) };
  s.light_model.ambient = rgba(s.light_model.ambient, [0.2, 0.2, 0.2, 1]);
  if (!s.objects || !s.objects.length) s.objects = [{ name: "object", shape: "sphere" }];
  const o = s.objects[0];
  let m = o.material;
  if (typeof m === "string") m = (s.materials && s.materials[m]) || (state.presets.find((p) => p.name === m) || {}).material;
  const md = MATERIAL_DEFAULTS();
  m = { ...md, ...(m || {}) };
  for (const k of ["ambient", "diffuse", "specular", "emission"]) m[k] = rgba(m[k], md[k]);
  o.material = m;
  if (typeof o.shape === "string") o.shape = { type: o.shape };
  o.shading = o.shading || "gouraud";
  const sh = o.shape;
  state.tess = sh.stacks || sh.tessellation || sh.sides || sh.nx || state.tess || 16;
  return s;
}
// What is sent: values equal to OpenGL's defaults are left out where the format forbids them
// (attenuation on directional lights) or where they mean "none" (a 180-degree spot).
function sceneForRequest() {
  const s = clone(state.scene);
  s.lights = s.lights.map((l) => {
    const out = { ...l };
    const a = l.attenuation;
    if (l.position[3] === 0 || (a.constant === 1 && a.linear === 0 && a.quadratic === 0)) delete out.attenuation;
    if (l.spot.cutoff === 180) delete out.spot;
    return out;
  });
  return s;
}

// ---- controls ---------------------------------------------------------------------------
function numberInput(path, step = 0.05, min, max) {
  const i = document.createElement("input");
  i.type = "number"; i.step = step; i.dataset.path = path;
  if (min !== undefined) i.min = min;
  if (max !== undefined) i.max = max;
  return i;
}
function toHex(c) {
  const h = (v) => Math.round(Math.min(Math.max(Number(v) || 0, 0), 1) * 255).toString(16).padStart(2, "0");
  return "#" + h(c[0]) + h(c[1]) + h(c[2]);
}
// A colour: a picker and three number fields for R, G, B (all editing the same array).
function colourControl(name, path) {
  const div = document.createElement("div");
  div.className = "colour";
  const label = document.createElement("span");
  label.className = "name"; label.textContent = name;
  const picker = document.createElement("input");
  picker.type = "color"; picker.dataset.colour = path; picker.title = name;
  div.append(label, picker);
  for (let k = 0; k < 3; ++k) div.append(numberInput(`${path}[${k}]`, 0.05, 0, 1));
  return div;
}
function buildLights() {
  const body = $("lights").tBodies[0];
  body.innerHTML = "";
  state.scene.lights.forEach((l, i) => {
    const row = body.insertRow();
    row.insertCell().textContent = i;
    const on = document.createElement("input");
    on.type = "checkbox"; on.dataset.path = `lights[${i}].enabled`;
    row.insertCell().append(on);
    for (let k = 0; k < 3; ++k) row.insertCell().append(numberInput(`lights[${i}].diffuse[${k}]`, 0.05, 0));
    for (let k = 0; k < 3; ++k) row.insertCell().append(numberInput(`lights[${i}].position[${k}]`, 0.1));
    const w = document.createElement("select");
    w.dataset.path = `lights[${i}].position[3]`; w.title = "W: 1 positional, 0 directional";
    w.innerHTML = '<option value="1">1</option><option value="0">0</option>';
    row.insertCell().append(w);
    const cell = row.insertCell();
    const more = document.createElement("button");
    more.type = "button"; more.textContent = "more"; more.title = "colours, attenuation, spot";
    const remove = document.createElement("button");
    remove.type = "button"; remove.textContent = "×"; remove.title = "remove this light";
    remove.addEventListener("click", () => { state.scene.lights.splice(i, 1); buildLights(); refresh(); changed(); });
    cell.append(more, remove);
    const details = body.insertRow();
    details.className = "details"; details.hidden = true;
    const td = details.insertCell(); td.colSpan = 10;
    const grid = document.createElement("div");
    grid.className = "grid";
    const add = (name, ...els) => { const s = document.createElement("span"); s.textContent = name; const d = document.createElement("div"); d.append(...els); grid.append(s, d); };
    add("ambient", colourControl("", `lights[${i}].ambient`));
    add("diffuse", colourControl("", `lights[${i}].diffuse`));
    add("specular", colourControl("", `lights[${i}].specular`));
    add("attenuation kc kl kq", numberInput(`lights[${i}].attenuation.constant`, 0.05, 0),
        numberInput(`lights[${i}].attenuation.linear`, 0.05, 0), numberInput(`lights[${i}].attenuation.quadratic`, 0.01, 0));
    add("spot direction", numberInput(`lights[${i}].spot.direction[0]`, 0.1), numberInput(`lights[${i}].spot.direction[1]`, 0.1),
        numberInput(`lights[${i}].spot.direction[2]`, 0.1));
    const cutoff = document.createElement("input");
    cutoff.type = "range"; cutoff.min = 0; cutoff.max = 90; cutoff.step = 1; cutoff.dataset.path = `lights[${i}].spot.cutoff`;
    const noSpot = document.createElement("button");
    noSpot.type = "button"; noSpot.textContent = "no cone (180)";
    noSpot.addEventListener("click", () => { state.scene.lights[i].spot.cutoff = 180; refresh(); changed(); });
    add("spot cutoff", cutoff, numberInput(`lights[${i}].spot.cutoff`, 1, 0, 180), noSpot);
    const exponent = document.createElement("input");
    exponent.type = "range"; exponent.min = 0; exponent.max = 128; exponent.step = 1; exponent.dataset.path = `lights[${i}].spot.exponent`;
    add("spot exponent", exponent, numberInput(`lights[${i}].spot.exponent`, 1, 0, 128));
    td.append(grid);
    more.addEventListener("click", () => { details.hidden = !details.hidden; });
  });
}
function buildStatic() {
  const mat = $("material");
  mat.innerHTML = "";
  for (const k of ["ambient", "diffuse", "specular", "emission"]) mat.append(colourControl(k, `objects[0].material.${k}`));
  const lm = $("light-model");
  lm.innerHTML = "";
  lm.append(colourControl("global ambient", "light_model.ambient"));
  const shape = $("shape");
  shape.innerHTML = "";
  for (const s of ["teapot", "sphere", "torus", "cylinder", "cone", "cube", "wall"]) shape.add(new Option(s, s));
  for (const f of state.objFiles) shape.add(new Option(`${f} (OBJ)`, "obj:" + f));
  const preset = $("preset");
  preset.length = 1;
  for (const p of state.presets) preset.add(new Option(p.name, p.name));
}
// Shows the scene's values in every control.
function refresh() {
  for (const el of document.querySelectorAll("[data-path]")) {
    const v = getPath(state.scene, el.dataset.path);
    if (el.type === "checkbox") el.checked = !!v;
    else if (document.activeElement !== el) el.value = v === undefined ? "" : v;
  }
  for (const el of document.querySelectorAll("[data-colour]")) el.value = toHex(getPath(state.scene, el.dataset.colour));
  const sh = state.scene.objects[0].shape;
  $("shape").value = sh.type === "mesh" ? "obj:" + sh.file : sh.type;
  $("tessellation").value = state.tess;
  $("tessellation-range").value = Math.min(state.tess, 64);
}
function applyShape() {
  const v = $("shape").value, t = Math.max(1, Math.round(Number($("tessellation").value) || 1));
  state.tess = t;
  const o = state.scene.objects[0];
  if (v.startsWith("obj:")) o.shape = { type: "mesh", file: v.slice(4) };
  else if (v === "teapot") o.shape = { type: "teapot", tessellation: Math.min(t, 64) };
  else if (v === "sphere") o.shape = { type: "sphere", radius: 1.5, slices: 2 * t, stacks: t };
  else if (v === "torus") o.shape = { type: "torus", major_radius: 1.1, minor_radius: 0.45, sides: t, rings: 2 * t };
  else if (v === "cylinder") o.shape = { type: "cylinder", radius: 1, height: 2, slices: 2 * t, stacks: t };
  else if (v === "cone") o.shape = { type: "cone", radius: 1.2, height: 2, slices: 2 * t, stacks: t };
  else if (v === "cube") o.shape = { type: "cube", size: 2 };
  else if (v === "wall") o.shape = { type: "wall", width: 3, height: 3, nx: t, ny: t };
}

// ---- rendering --------------------------------------------------------------------------
function clearErrors() {
  for (const el of document.querySelectorAll(".field-error")) el.remove();
  for (const el of document.querySelectorAll(".invalid")) el.classList.remove("invalid");
  $("errors").textContent = "";
}
// Puts each error next to the control of its key path (or the closest enclosing one).
function showErrors(errors) {
  clearErrors();
  const loose = [];
  for (const e of errors) {
    let path = e.path || "", el = null;
    while (path && !(el = document.querySelector(`[data-path="${CSS.escape(path)}"]`))) {
      path = path.replace(/(\.[^.[\]]+|\[\d+\])$/, "");
    }
    if (!el) { loose.push(e.text || e.message); continue; }
    el.classList.add("invalid");
    const msg = document.createElement("span");
    msg.className = "field-error"; msg.textContent = `${e.path}: ${e.message}`;
    el.insertAdjacentElement("afterend", msg);
    const details = el.closest("tr.details");
    if (details) details.hidden = false;
  }
  $("errors").textContent = loose.join("\n");
}
// One picture: the scene as the controls have it, or a variant of it (another shading, a
// row's value).
async function renderOne(variant, signal) {
  const q = variant.shading ? `?shading=${variant.shading}` : "";
  const r = await fetch(`/api/render${q}`, { method: "POST", body: JSON.stringify(variant.scene || sceneForRequest()), signal,
                                            headers: { "Content-Type": "application/json" } });
  if (!r.ok) {
    let body = {};
    try { body = await r.json(); } catch (_) { body = { errors: [{ message: `HTTP ${r.status}` }] }; }
    const err = new Error("render failed"); err.body = body; throw err;
  }
  return { blob: await r.blob(), ms: Number(r.headers.get("X-Render-Ms")) };
}
// The newest request always wins: a render still running when the scene changes again is
// aborted, and its answer is dropped if it arrives anyway.
async function render() {
  const seq = ++state.seq;
  if (state.inflight) state.inflight.abort();
  const controller = new AbortController();
  state.inflight = controller;
  const variants = $("compare").checked ? ["flat", "gouraud", "phong"].map((m) => ({ shading: m, label: m }))
    : state.row && $("row-strip").checked ? rowVariants() : [{}];
  $("status").textContent = "rendering…";
  const started = performance.now();
  try {
    const results = await Promise.all(variants.map((v) => renderOne(v, controller.signal)));
    if (seq !== state.seq) return;
    clearErrors();
    const images = $("images");
    for (const old of images.querySelectorAll("img")) URL.revokeObjectURL(old.src);
    images.innerHTML = "";
    images.classList.toggle("strip", variants.length > 3);  // a row: side by side, smaller
    results.forEach((r, i) => {
      const fig = document.createElement("figure");
      const img = document.createElement("img");
      img.src = URL.createObjectURL(r.blob);
      const v = variants[i];
      img.alt = v.label || "render";
      img.dataset.shading = v.shading || state.scene.objects[0].shading;
      if (!v.scene) {
        img.addEventListener("click", (ev) => { if (!dragged) explain(ev, img); });
        enableOrbit(img);
        img.addEventListener("load", drawLights);
      }
      fig.append(img);
      if (v.label) { const c = document.createElement("figcaption"); c.textContent = v.label; fig.append(c); }
      images.append(fig);
    });
    const server = results.map((r) => r.ms.toFixed(1)).join(" / ");
    $("status").textContent = `rendered in ${server} ms (${(performance.now() - started).toFixed(0)} ms round trip)`;
  } catch (e) {
    if (e.name === "AbortError" || seq !== state.seq) return;
    $("status").textContent = "not rendered";
    showErrors((e.body && e.body.errors) || [{ message: String(e) }]);
  } finally {
    if (state.inflight === controller) state.inflight = null;
  }
}
let timer = null;
function changed() {
  record();
  if (!$("live").checked) return;
  clearTimeout(timer);
  timer = setTimeout(render, 30);
}

// ---- the camera in the student's hands ------------------------------------------------------
// Dragging the picture turns the camera around its target (left-right about the up axis,
// up-down about the screen's horizontal axis, short of the poles); the wheel moves it closer or
// farther. A press that moves less than 4 pixels stays a click (explain this pixel).
const vsub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const vadd = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const vscale = (a, k) => [a[0] * k, a[1] * k, a[2] * k];
const vdot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const vcross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const vlen = (a) => Math.sqrt(vdot(a, a));
const vnorm = (a) => { const l = vlen(a) || 1; return vscale(a, 1 / l); };
// v rotated by `angle` about the unit axis k (Rodrigues).
function rotate(v, k, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return vadd(vadd(vscale(v, c), vscale(vcross(k, v), s)), vscale(k, vdot(k, v) * (1 - c)));
}
let dragged = false;
function orbit(camera, startEye, dx, dy) {
  const up = vnorm(camera.up || [0, 1, 0]);
  let offset = vsub(startEye, camera.target);
  offset = rotate(offset, up, -dx * 0.01);
  const right = vnorm(vcross(up, offset));
  const turned = rotate(offset, right, dy * 0.01);
  const cos = vdot(vnorm(turned), up);
  if (Math.abs(cos) < 0.995) offset = turned;  // not over a pole
  camera.eye = vadd(camera.target, offset).map((v) => Math.round(v * 1000) / 1000);
}
function enableOrbit(img) {
  img.addEventListener("pointerdown", (ev) => {
    if (ev.button !== 0) return;
    const camera = state.scene.camera, startEye = camera.eye.slice(), x0 = ev.clientX, y0 = ev.clientY;
    dragged = false;
    const move = (e) => {
      const dx = e.clientX - x0, dy = e.clientY - y0;
      if (!dragged && Math.hypot(dx, dy) < 4) return;
      dragged = true;
      orbit(camera, startEye, dx, dy);
      changed();
    };
    const up = () => { window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up); };
    window.addEventListener("pointermove", move);
    window.addEventListener("pointerup", up);
    ev.preventDefault();
  });
  img.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    const camera = state.scene.camera, offset = vsub(camera.eye, camera.target);
    const d = Math.min(Math.max(vlen(offset) * Math.exp(ev.deltaY * 0.001), 0.5), 200);
    camera.eye = vadd(camera.target, vscale(vnorm(offset), d)).map((v) => Math.round(v * 1000) / 1000);
    changed();
  }, { passive: false });
  img.draggable = false;
}
// ---- the lights in the picture ---------------------------------------------------------------
// Each enabled light drawn over the picture where the camera sees it: a positional light as a
// dot in its diffuse colour (numbered), with its spot axis and cone; a directional light as an
// arrow from the centre toward it. Dragging a positional light's dot moves the light in the
// plane facing the camera at its depth; its fields follow.
function cameraBasis(camera) {
  const f = vnorm(vsub(camera.target, camera.eye));
  const side = vnorm(vcross(f, camera.up || [0, 1, 0]));
  return { f, side, up: vcross(side, f) };
}
// Eye coordinates of a point (w = 1) or a direction (w = 0) given in the light's space.
function toEye(light, v, w) {
  if (light.space === "eye") return v.slice(0, 3);
  const b = cameraBasis(state.scene.camera);
  const p = w ? vsub(v, state.scene.camera.eye) : v;
  return [vdot(b.side, p), vdot(b.up, p), -vdot(b.f, p)];
}
// Eye coordinates to CSS pixels over an image of w x h, or null behind the camera.
function toScreen(e, w, h) {
  const c = state.scene.camera, aspect = w / h;
  let x, y;
  if (c.projection === "orthographic") {
    const half = (c.ortho_height || 4) / 2;
    x = e[0] / (half * aspect); y = e[1] / half;
  } else {
    if (e[2] > -1e-3) return null;
    const t = Math.tan(((c.fovy || 30) * Math.PI) / 360);
    x = e[0] / -e[2] / (t * aspect); y = e[1] / -e[2] / t;
  }
  return [(x + 1) / 2 * w, (1 - y) / 2 * h];
}
// World (or eye) units per CSS pixel at eye depth z.
function unitsPerPixel(z, h) {
  const c = state.scene.camera;
  if (c.projection === "orthographic") return (c.ortho_height || 4) / h;
  return (2 * -z * Math.tan(((c.fovy || 30) * Math.PI) / 360)) / h;
}
const SVG = "http://www.w3.org/2000/svg";
function svgEl(name, attrs) {
  const el = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
  return el;
}
function drawLights() {
  for (const old of document.querySelectorAll("#images svg.markers")) old.remove();
  const img = document.querySelector("#images img");
  if (!img || !$("show-lights").checked || document.querySelectorAll("#images img").length !== 1 || !img.clientWidth) return;
  const w = img.clientWidth, h = img.clientHeight;
  const svg = svgEl("svg", { class: "markers", width: w, height: h, viewBox: `0 0 ${w} ${h}` });
  state.scene.lights.forEach((l, i) => {
    if (!l.enabled) return;
    const colour = toHex(l.diffuse.some((c) => c > 0.05) ? l.diffuse : [1, 1, 1]);
    const g = svgEl("g", { class: "light", "data-light": i });
    if (l.position[3] === 0) {  // directional: an arrow from the centre toward the light
      const d = toEye(l, l.position, 0), len = Math.hypot(d[0], d[1]);
      const ux = len > 1e-6 ? d[0] / len : 0, uy = len > 1e-6 ? -d[1] / len : 0;
      const x1 = w / 2 + ux * Math.min(w, h) * 0.42, y1 = h / 2 + uy * Math.min(w, h) * 0.42;
      g.append(svgEl("line", { x1: w / 2 + ux * 12, y1: h / 2 + uy * 12, x2: x1, y2: y1, stroke: colour, "stroke-width": 2, "stroke-dasharray": "4 3" }));
      g.append(svgEl("circle", { cx: x1, cy: y1, r: 7, fill: colour, stroke: "#000", "stroke-width": 1 }));
      const t = svgEl("text", { x: x1 + 9, y: y1 - 7 });
      t.textContent = `${i} (directional)`;
      g.append(t);
      svg.append(g);
      return;
    }
    const p = l.position.slice(0, 3).map((v) => v / l.position[3]);
    const e = toEye(l, p, 1), seen = toScreen(e, w, h);
    if (!seen) return;  // behind the camera
    // A light outside the picture is drawn as a ring on its edge, toward where it is.
    const inside = seen[0] >= 0 && seen[0] <= w && seen[1] >= 0 && seen[1] <= h;
    const at = inside ? seen : [Math.min(Math.max(seen[0], 8), w - 8), Math.min(Math.max(seen[1], 8), h - 8)];
    if (inside && l.spot.cutoff !== 180) {  // the spot's axis and the two sides of its cone
      const dir = vnorm(toEye(l, l.spot.direction, 0)), reach = 1.2;
      const side = vnorm(vcross(dir, [0, 0, 1])), k = vlen(side) > 1e-6 ? side : [1, 0, 0];
      for (const angle of [0, (l.spot.cutoff * Math.PI) / 180, (-l.spot.cutoff * Math.PI) / 180]) {
        const end = toScreen(vadd(e, vscale(rotate(dir, k, angle), reach)), w, h);
        if (end) g.append(svgEl("line", { x1: at[0], y1: at[1], x2: end[0], y2: end[1], stroke: colour, "stroke-width": angle ? 1 : 2, "stroke-dasharray": angle ? "3 3" : "" }));
      }
    }
    const dot = svgEl("circle", { cx: at[0], cy: at[1], r: 7, fill: inside ? colour : "none", stroke: inside ? "#000" : colour,
                                  "stroke-width": inside ? 1.5 : 3, class: "handle" });
    g.append(dot);
    const right = at[0] > w - 90;  // labels near the right edge go to the dot's left
    const t = svgEl("text", { x: right ? at[0] - 9 : at[0] + 9, y: Math.max(at[1] - 7, 12), "text-anchor": right ? "end" : "start" });
    t.textContent = inside ? String(i) : `${i} (outside)`;
    g.append(t);
    dot.addEventListener("pointerdown", (ev) => {
      ev.preventDefault();
      ev.stopPropagation();
      const x0 = ev.clientX, y0 = ev.clientY, start = l.position.slice(), upp = unitsPerPixel(e[2], h);
      const b = l.space === "eye" ? { side: [1, 0, 0], up: [0, 1, 0] } : cameraBasis(state.scene.camera);
      const move = (m) => {
        const delta = vadd(vscale(b.side, (m.clientX - x0) * upp), vscale(b.up, -(m.clientY - y0) * upp));
        const wgt = start[3];
        l.position = [start[0] + delta[0] * wgt, start[1] + delta[1] * wgt, start[2] + delta[2] * wgt, wgt]
          .map((v) => Math.round(v * 1000) / 1000);
        refresh();
        changed();
        drawLights();
      };
      const up = () => { window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up); };
      window.addEventListener("pointermove", move);
      window.addEventListener("pointerup", up);
    });
    svg.append(g);
  });
  img.parentElement.append(svg);
}

// Keys for the common toggles, outside the text fields: R render, L live, C compare,
// 1 / 2 / 3 flat / Gouraud / Phong, E hide the explanation.
function onShortcut(ev) {
  if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
  const el = document.activeElement;
  if (el && (el.tagName === "INPUT" || el.tagName === "SELECT" || el.tagName === "TEXTAREA")) return;
  const k = ev.key.toLowerCase();
  const toggle = (id) => { $(id).checked = !$(id).checked; $(id).dispatchEvent(new Event("change", { bubbles: true })); };
  if (k === "r") render();
  else if (k === "l") toggle("live");
  else if (k === "c") toggle("compare");
  else if (k === "e") $("explain").hidden = true;
  else if (k === "1" || k === "2" || k === "3") {
    state.scene.objects[0].shading = ["flat", "gouraud", "phong"][Number(k) - 1];
    refresh();
    changed();
  } else return;
  ev.preventDefault();
}

// ---- explain this pixel -----------------------------------------------------------------
const fmt = (c) => c.map((v) => v.toFixed(3)).join(", ");
const sw = (c) => `<span class="swatch" style="background:rgb(${c.slice(0, 3).map((v) => Math.round(Math.min(Math.max(v, 0), 1) * 255)).join(",")})"></span>`;
async function explain(ev, img) {
  const rect = img.getBoundingClientRect();
  const x = Math.floor((ev.clientX - rect.left) / rect.width * img.naturalWidth);
  const y = Math.floor((ev.clientY - rect.top) / rect.height * img.naturalHeight);
  const scene = sceneForRequest();
  scene.objects[0].shading = img.dataset.shading;
  const r = await fetch("/api/explain", { method: "POST", headers: { "Content-Type": "application/json" },
                                          body: JSON.stringify({ scene, x, y }) });
  const e = await r.json();
  const box = $("explain");
  box.hidden = false;
  if (!r.ok) { box.textContent = (e.errors || []).map((x) => x.text || x.message).join("\n"); return; }
  if (!e.hit) { box.innerHTML = `<b>Pixel (${x}, ${y})</b>: background ${sw(e.background)} (${fmt(e.background)})`; return; }
  const rows = [
    ["emission", e.emission], ["global ambient × material ambient", e.global_ambient],
  ];
  let html = `<b>Pixel (${x}, ${y})</b>: ${e.object}, ${e.back_face ? "back" : "front"} face, ` +
    `eye-space point (${fmt(e.position)}), normal (${fmt(e.normal)}).`;
  if (e.shading !== "phong") {
    html += ` <i>This object is ${e.shading}-shaded: its pixels interpolate colours computed at the vertices; below is the equation at this very point (what Phong shading shows).</i>`;
  }
  html += `<table><thead><tr><th>term</th><th>attenuation</th><th>spot</th><th>n·L</th><th>ambient</th><th>diffuse</th><th>specular</th></tr></thead><tbody>`;
  for (const [name, c] of rows) html += `<tr><td>${name}</td><td></td><td></td><td></td><td colspan="3">${sw(c)} ${fmt(c)}</td></tr>`;
  for (const t of e.lights) {
    html += `<tr><td>light ${t.light}</td><td>${t.attenuation.toFixed(3)}</td><td>${t.spot.toFixed(3)}</td>` +
      `<td>${t.n_dot_l.toFixed(3)}</td><td>${fmt(t.ambient)}</td><td>${fmt(t.diffuse)}</td><td>${fmt(t.specular)}</td></tr>`;
  }
  html += `<tr><td><b>sum</b></td><td></td><td></td><td></td><td colspan="3">${fmt(e.unclamped)}</td></tr>`;
  html += `<tr><td><b>clamped to [0, 1]</b></td><td></td><td></td><td></td><td colspan="3" id="explain-result">${sw(e.result)} ${fmt(e.result)} = (${e.result.slice(0, 3).map((v) => Math.round(v * 255)).join(", ")})/255</td></tr>`;
  html += "</tbody></table>";
  box.innerHTML = html;
}

// ---- code -------------------------------------------------------------------------------
function glCode() {
  const s = sceneForRequest(), f = (a) => a.map((v) => Number(v).toFixed(3) + "f").join(", ");
  const lines = ["/* The lab's settings as OpenGL 1.x calls (after gluLookAt for world-space lights). */",
    `GLfloat global_ambient[] = {${f(state.scene.light_model.ambient)}};`,
    "glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global_ambient);",
    `glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, ${state.scene.light_model.local_viewer ? "GL_TRUE" : "GL_FALSE"});`,
    `glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, ${state.scene.light_model.two_side ? "GL_TRUE" : "GL_FALSE"});`,
    "glEnable(GL_LIGHTING);"];
  state.scene.lights.forEach((l, i) => {
    const L = `GL_LIGHT${i}`;
    lines.push("", `{ /* light ${i} */`,
      `  GLfloat position[] = {${f(l.position)}}, ambient[] = {${f(l.ambient)}};`,
      `  GLfloat diffuse[] = {${f(l.diffuse)}}, specular[] = {${f(l.specular)}};`,
      `  glLightfv(${L}, GL_POSITION, position);`, `  glLightfv(${L}, GL_AMBIENT, ambient);`,
      `  glLightfv(${L}, GL_DIFFUSE, diffuse);`, `  glLightfv(${L}, GL_SPECULAR, specular);`,
      `  glLightf(${L}, GL_CONSTANT_ATTENUATION, ${l.attenuation.constant});`,
      `  glLightf(${L}, GL_LINEAR_ATTENUATION, ${l.attenuation.linear});`,
      `  glLightf(${L}, GL_QUADRATIC_ATTENUATION, ${l.attenuation.quadratic});`);
    if (l.spot.cutoff !== 180) {
      lines.push(`  GLfloat spot_direction[] = {${f(l.spot.direction)}};`,
        `  glLightfv(${L}, GL_SPOT_DIRECTION, spot_direction);`,
        `  glLightf(${L}, GL_SPOT_CUTOFF, ${l.spot.cutoff});`, `  glLightf(${L}, GL_SPOT_EXPONENT, ${l.spot.exponent});`);
    }
    lines.push(`  ${l.enabled ? "glEnable" : "glDisable"}(${L});`, "}");
  });
  const m = state.scene.objects[0].material, sh = s.objects[0].shape;
  lines.push("", `GLfloat mat_ambient[] = {${f(m.ambient)}}, mat_diffuse[] = {${f(m.diffuse)}};`,
    `GLfloat mat_specular[] = {${f(m.specular)}}, mat_emission[] = {${f(m.emission)}};`,
    "glMaterialfv(GL_FRONT, GL_AMBIENT, mat_ambient);", "glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_diffuse);",
    "glMaterialfv(GL_FRONT, GL_SPECULAR, mat_specular);", "glMaterialfv(GL_FRONT, GL_EMISSION, mat_emission);",
    `glMaterialf(GL_FRONT, GL_SHININESS, ${m.shininess});`,
    `glShadeModel(${state.scene.objects[0].shading === "flat" ? "GL_FLAT" : "GL_SMOOTH"});` +
      (state.scene.objects[0].shading === "phong" ? " /* Phong: per-pixel lighting, beyond GL 1.x */" : ""));
  const draw = { teapot: "glutSolidTeapot(1.0);", sphere: `glutSolidSphere(${sh.radius}, ${sh.slices}, ${sh.stacks});`,
    torus: `glutSolidTorus(${sh.minor_radius}, ${sh.major_radius}, ${sh.sides}, ${sh.rings});`,
    cone: `glutSolidCone(${sh.radius}, ${sh.height}, ${sh.slices}, ${sh.stacks});`, cube: `glutSolidCube(${sh.size});` };
  lines.push(draw[sh.type] || `/* draw the ${sh.type} */`);
  return lines.join("\n");
}

// ---- the lecture's figures and row experiments --------------------------------------------
// A row (scenes/lecture/rows.json) is one scene with one key taking several values; the
// slider moves the key through them, "show the whole row" renders them side by side.
function splitTopLevel(text) {
  const out = [];
  let cur = "", depth = 0, inString = false;
  for (let i = 0; i < text.length; ++i) {
    const c = text[i];
    if (inString) {
      if (c === "\\" && i + 1 < text.length) { cur += c + text[++i]; continue; }
      if (c === '"') inString = false;
    } else if (c === '"') inString = true;
    else if (c === "[" || c === "{") ++depth;
    else if (c === "]" || c === "}") --depth;
    else if (c === "," && depth === 0) { out.push(cur); cur = ""; continue; }
    cur += c;
  }
  out.push(cur);
  return out;
}
// A value as --set and --vary read it: JSON, or a bare word.
function valueOf(text) {
  try { return JSON.parse(text); } catch (_) { return text.trim(); }
}
function assign(scene, key, value) {
  if (key === "shading") { for (const o of scene.objects) o.shading = value; return; }
  setPath(scene, key, clone(value));
}
function rowVariants() {
  const r = state.row;
  return r.values.map((value, i) => {
    const scene = sceneForRequest();
    assign(scene, r.key, value);
    return { scene, label: r.labels[i] };
  });
}
async function fetchFigure(file) {
  const r = await fetch(`/api/figure/${encodeURIComponent(file)}`);
  if (!r.ok) throw new Error(`${file}: HTTP ${r.status}`);
  return r.json();
}
async function openFigure(file) {
  const scene = await fetchFigure(file);
  state.row = null;
  $("row").value = "";
  $("row-controls").hidden = true;
  $("figure-caption").textContent = scene.caption || "";
  await loadScene(scene);
}
async function openRow(index) {
  const row = state.rows[index];
  const scene = await fetchFigure(row.scene);
  for (const set of row.set || []) {
    const eq = set.indexOf("=");
    assign(scene, set.slice(0, eq), valueOf(set.slice(eq + 1)));
  }
  const vary = (row.vary || [])[0];
  $("figure").value = "";
  $("figure-caption").textContent = row.caption || scene.caption || "";
  if (!vary) {
    state.row = null;
    $("row-controls").hidden = true;
    await loadScene(scene);
    return;
  }
  const eq = vary.indexOf("=");
  const key = vary.slice(0, eq), texts = splitTopLevel(vary.slice(eq + 1));
  const short = key.replace(/^.*\./, "");
  state.row = { key, values: texts.map(valueOf),
                labels: (row.labels && row.labels.length === texts.length) ? row.labels : texts.map((t) => `${short} = ${t}`) };
  const slider = $("row-value");
  slider.max = texts.length - 1;
  slider.value = 0;
  $("row-key").textContent = short;
  $("row-label").textContent = state.row.labels[0];
  $("row-controls").hidden = false;
  assign(scene, key, state.row.values[0]);
  await loadScene(scene);
}
function onRowValue() {
  const i = Number($("row-value").value);
  assign(state.scene, state.row.key, state.row.values[i]);
  state.scene = normalizeScene(state.scene);  // a value may be a whole light or shape
  $("row-label").textContent = state.row.labels[i];
  buildLights();
  refresh();
  changed();
}
async function buildLecture() {
  const r = await fetch("/api/figures");
  if (!r.ok) return;
  const { figures, rows } = await r.json();
  state.figures = figures;
  state.rows = rows;
  for (const f of figures) {
    const o = new Option(f.file.replace(/\.json$/, ""), f.file);
    o.title = f.caption;
    $("figure").add(o);
  }
  rows.forEach((row, i) => $("row").add(new Option(row.title || row.name, String(i))));
  $("lecture").hidden = !figures.length;
}

// ---- share and keep ----------------------------------------------------------------------
// The whole setup travels in the page's address, as #scene= and the scene file's JSON in
// base64url (UTF-8), so a link reproduces it; undo and redo step through the setups the
// edits made (an edit is recorded once the controls are still for 400 ms).
function encodeScene(scene) {
  const bytes = new TextEncoder().encode(JSON.stringify(scene));
  let bin = "";
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}
function decodeScene(text) {
  const bin = atob(text.replace(/-/g, "+").replace(/_/g, "/"));
  return JSON.parse(new TextDecoder().decode(Uint8Array.from(bin, (c) => c.charCodeAt(0))));
}
function sceneFromAddress() {
  const m = /(?:^#|&)scene=([A-Za-z0-9_-]+)/.exec(location.hash);
  if (!m) return null;
  try { return decodeScene(m[1]); } catch (_) { return null; }
}
function updateAddress() {
  history.replaceState(null, "", `#scene=${encodeScene(sceneForRequest())}`);
  $("share-link").value = location.href;
}
function updateUndoButtons() {
  $("undo").disabled = state.undo.length < 2;
  $("redo").disabled = state.redo.length === 0;
}
let recordTimer = null;
function flushRecord() {
  clearTimeout(recordTimer);
  recordTimer = null;
  const now = JSON.stringify(state.scene);
  if (state.undo[state.undo.length - 1] === now) return;
  state.undo.push(now);
  if (state.undo.length > 200) state.undo.shift();
  state.redo = [];
  updateUndoButtons();
  updateAddress();
}
function record() {
  clearTimeout(recordTimer);
  recordTimer = setTimeout(flushRecord, 400);
}
async function restore(text) {
  clearTimeout(recordTimer);
  state.scene = JSON.parse(text);
  buildLights();
  refresh();
  updateUndoButtons();
  updateAddress();
  await render();
}
function undo() {
  if (recordTimer) flushRecord();  // an edit still settling is the step undone
  if (state.undo.length < 2) return;
  state.redo.push(state.undo.pop());
  restore(state.undo[state.undo.length - 1]);
}
function redo() {
  if (!state.redo.length) return;
  const next = state.redo.pop();
  state.undo.push(next);
  restore(next);
}
function onKey(ev) {
  if (!(ev.ctrlKey || ev.metaKey) || ev.altKey) return;
  const el = document.activeElement;
  if (el && (el.tagName === "TEXTAREA" || (el.tagName === "INPUT" && el.type === "text"))) return;
  const k = ev.key.toLowerCase();
  if (k === "z" && !ev.shiftKey) { ev.preventDefault(); undo(); }
  else if ((k === "z" && ev.shiftKey) || k === "y") { ev.preventDefault(); redo(); }
}
// The picture at the size and samples chosen, rendered by the server and downloaded as a PNG.
async function savePicture() {
  const scene = sceneForRequest();
  scene.image = { ...(scene.image || {}), width: Number($("save-width").value), height: Number($("save-height").value),
                  samples: Number($("save-samples").value) };
  $("status").textContent = "rendering the picture to save…";
  const r = await fetch("/api/render", { method: "POST", body: JSON.stringify(scene), headers: { "Content-Type": "application/json" } });
  if (!r.ok) {
    let body = {};
    try { body = await r.json(); } catch (_) { body = { errors: [{ message: `HTTP ${r.status}` }] }; }
    $("status").textContent = "not saved";
    showErrors(body.errors || []);
    return;
  }
  const a = document.createElement("a");
  a.href = URL.createObjectURL(await r.blob());
  a.download = `lab-${scene.image.width}x${scene.image.height}.png`;
  document.body.append(a);
  a.click();
  a.remove();
  $("status").textContent = `saved ${a.download}`;
}

// ---- code they can edit --------------------------------------------------------------------
// The code view's OpenGL calls are read back: a GLfloat array declared in a light's block (or
// at the top) and passed to glLightfv / glMaterialfv / glLightModelfv, glLightf, glMaterialf,
// glLightModeli, glEnable / glDisable of a light and glShadeModel set the values they name;
// a line that is none of these (or names an array not declared, a light the scene lacks, the
// wrong number of values) is listed with its error and changes nothing. The scene file below
// it is parsed as JSON.
let codeTimer = null;
function showCode() {
  $("code").value = glCode();
  $("scene-text").value = JSON.stringify(sceneForRequest(), null, 2);
  $("code-errors").textContent = "";
  $("scene-errors").textContent = "";
}
const NUMBER = "([-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?)f?";
function parseCode(text, scene) {
  const errors = [];
  let arrays = {}, outer = {};
  const colour = { AMBIENT: "ambient", DIFFUSE: "diffuse", SPECULAR: "specular", EMISSION: "emission" };
  const lightOf = (n, line) => {
    const i = Number(n);
    if (i >= scene.lights.length) { errors.push(`line ${line}: GL_LIGHT${i}: the scene has ${scene.lights.length} lights (GL_LIGHT0 to GL_LIGHT${scene.lights.length - 1})`); return null; }
    return scene.lights[i];
  };
  const arrayOf = (name, count, line) => {
    const a = arrays[name];
    if (!a) { errors.push(`line ${line}: ${name}: no GLfloat ${name}[] declared above`); return null; }
    if (a.length < count) { errors.push(`line ${line}: ${name}: expected ${count} values, got ${a.length}`); return null; }
    return a.slice(0, count);
  };
  text.split("\n").forEach((raw, k) => {
    const line = k + 1;
    let t = raw.replace(/\/\*.*?\*\//g, "").trim();
    if (!t) return;
    if (t === "{") { outer = arrays; arrays = { ...arrays }; return; }
    if (t === "}") { arrays = outer; return; }
    let m;
    if (/^GLfloat\s/.test(t)) {
      const decl = new RegExp(`(\\w+)\\[\\]\\s*=\\s*\\{([^}]*)\\}`, "g");
      let found = false;
      while ((m = decl.exec(t))) {
        found = true;
        const values = m[2].split(",").map((v) => v.trim()).filter((v) => v !== "");
        const numbers = values.map((v) => Number(v.replace(/f$/, "")));
        if (numbers.some((v) => !Number.isFinite(v))) { errors.push(`line ${line}: ${m[1]}: expected numbers, got {${m[2].trim()}}`); continue; }
        arrays[m[1]] = numbers;
      }
      if (!found) errors.push(`line ${line}: expected GLfloat name[] = {numbers, ...};`);
      return;
    }
    if ((m = /^glLightfv\(GL_LIGHT(\d+),\s*GL_(POSITION|AMBIENT|DIFFUSE|SPECULAR|SPOT_DIRECTION),\s*(\w+)\);$/.exec(t))) {
      const l = lightOf(m[1], line), v = arrayOf(m[3], m[2] === "SPOT_DIRECTION" ? 3 : 4, line);
      if (!l || !v) return;
      if (m[2] === "POSITION") l.position = v;
      else if (m[2] === "SPOT_DIRECTION") l.spot.direction = v;
      else l[colour[m[2]]] = v;
      return;
    }
    if ((m = new RegExp(`^glLightf\\(GL_LIGHT(\\d+),\\s*GL_(CONSTANT_ATTENUATION|LINEAR_ATTENUATION|QUADRATIC_ATTENUATION|SPOT_CUTOFF|SPOT_EXPONENT),\\s*${NUMBER}\\);$`).exec(t))) {
      const l = lightOf(m[1], line), v = Number(m[3]);
      if (!l) return;
      const where = { CONSTANT_ATTENUATION: ["attenuation", "constant"], LINEAR_ATTENUATION: ["attenuation", "linear"],
                      QUADRATIC_ATTENUATION: ["attenuation", "quadratic"], SPOT_CUTOFF: ["spot", "cutoff"], SPOT_EXPONENT: ["spot", "exponent"] }[m[2]];
      l[where[0]][where[1]] = v;
      return;
    }
    if ((m = /^glMaterialfv\(GL_FRONT(?:_AND_BACK)?,\s*GL_(AMBIENT|DIFFUSE|SPECULAR|EMISSION),\s*(\w+)\);$/.exec(t))) {
      const v = arrayOf(m[2], 4, line);
      if (v) scene.objects[0].material[colour[m[1]]] = v;
      return;
    }
    if ((m = new RegExp(`^glMaterialf\\(GL_FRONT(?:_AND_BACK)?,\\s*GL_SHININESS,\\s*${NUMBER}\\);$`).exec(t))) {
      scene.objects[0].material.shininess = Number(m[1]);
      return;
    }
    if ((m = /^glLightModelfv\(GL_LIGHT_MODEL_AMBIENT,\s*(\w+)\);$/.exec(t))) {
      const v = arrayOf(m[1], 4, line);
      if (v) scene.light_model.ambient = v;
      return;
    }
    if ((m = /^glLightModeli\(GL_LIGHT_MODEL_(LOCAL_VIEWER|TWO_SIDE),\s*GL_(TRUE|FALSE)\);$/.exec(t))) {
      scene.light_model[m[1] === "LOCAL_VIEWER" ? "local_viewer" : "two_side"] = m[2] === "TRUE";
      return;
    }
    if ((m = /^gl(Enable|Disable)\(GL_LIGHT(\d+)\);$/.exec(t))) {
      const l = lightOf(m[2], line);
      if (l) l.enabled = m[1] === "Enable";
      return;
    }
    if (/^glEnable\(GL_LIGHTING\);$/.test(t)) return;
    if ((m = /^glShadeModel\(GL_(FLAT|SMOOTH)\);$/.exec(t))) {
      const o = scene.objects[0];
      if (m[1] === "FLAT") o.shading = "flat";
      else if (o.shading === "flat") o.shading = "gouraud";
      return;
    }
    if (/^glutSolid\w+\(.*\);$/.test(t)) return;  // the shape: chosen with the Object controls
    errors.push(`line ${line}: not understood: "${t}" (expected a GLfloat array or a glLight*, glMaterial*, glLightModel*, glEnable/glDisable(GL_LIGHTi) or glShadeModel call)`);
  });
  return errors;
}
function applyCode() {
  const scene = clone(state.scene);
  const errors = parseCode($("code").value, scene);
  $("code-errors").textContent = errors.join("\n");
  state.scene = scene;
  $("scene-text").value = JSON.stringify(sceneForRequest(), null, 2);
  buildLights();
  refresh();
  changed();
}
function applySceneText() {
  let parsed;
  try {
    parsed = JSON.parse($("scene-text").value);
  } catch (e) {
    $("scene-errors").textContent = `the scene file: ${e.message}`;
    return;
  }
  $("scene-errors").textContent = "";
  state.scene = normalizeScene(parsed);
  $("code").value = glCode();
  buildLights();
  refresh();
  changed();
}

// ---- wiring ------------------------------------------------------------------------------
function onInput(ev) {
  const el = ev.target;
  if (el.dataset.colour) {
    const hex = el.value, c = getPath(state.scene, el.dataset.colour);
    for (let k = 0; k < 3; ++k) c[k] = parseInt(hex.slice(1 + 2 * k, 3 + 2 * k), 16) / 255;
    refresh(); changed(); return;
  }
  if (!el.dataset.path) return;
  let v;
  if (el.type === "checkbox") v = el.checked;
  else if (el.tagName === "SELECT" && !/^\d+$/.test(el.value)) v = el.value;
  else if (el.value.trim() === "") return;
  else v = Number(el.value);
  // An input the browser cannot read as a number still goes to the server as text, so that
  // the server's message explains what is wrong.
  if (typeof v === "number" && Number.isNaN(v)) v = el.value;
  setPath(state.scene, el.dataset.path, v);
  if (el.type === "range" || el.type === "checkbox" || el.tagName === "SELECT") refresh();
  changed();
}
async function loadScene(scene) {
  state.scene = normalizeScene(scene);
  $("explain").hidden = true;  // it explained a pixel of the scene before
  buildStatic();
  buildLights();
  refresh();
  state.undo = [JSON.stringify(state.scene)];
  state.redo = [];
  updateUndoButtons();
  updateAddress();
  await render();
}
async function start() {
  const [scene, presets, shapes] = await Promise.all([
    fetch("/api/scene").then((r) => r.json()), fetch("/api/presets").then((r) => r.json()),
    fetch("/api/shapes").then((r) => r.json())]);
  state.presets = presets;
  state.objFiles = shapes.obj_files || [];
  document.addEventListener("input", onInput);
  document.addEventListener("change", (ev) => { if (ev.target.type === "number") onInput(ev); });
  $("render").addEventListener("click", render);
  $("compare").addEventListener("change", render);
  $("add-light").addEventListener("click", () => {
    state.scene.lights.push(normalizeScene({ lights: [{ position: [0, 2, 4, 1], diffuse: [0.5, 0.5, 0.5, 1], specular: [0.5, 0.5, 0.5, 1] }] }).lights[0]);
    buildLights(); refresh(); changed();
  });
  $("shape").addEventListener("change", () => { applyShape(); changed(); });
  $("tessellation").addEventListener("change", () => { applyShape(); refresh(); changed(); });
  $("tessellation-range").addEventListener("input", () => {
    $("tessellation").value = $("tessellation-range").value;
    applyShape(); changed();
  });
  $("preset").addEventListener("change", () => {
    const p = state.presets.find((x) => x.name === $("preset").value);
    if (!p) return;
    Object.assign(state.scene.objects[0].material, clone(p.material));
    refresh(); changed();
  });
  $("show-code").addEventListener("click", () => {
    $("code-view").hidden = !$("code-view").hidden;
    if (!$("code-view").hidden) showCode();
  });
  $("code").addEventListener("input", (ev) => { ev.stopPropagation(); clearTimeout(codeTimer); codeTimer = setTimeout(applyCode, 250); });
  $("scene-text").addEventListener("input", (ev) => { ev.stopPropagation(); clearTimeout(codeTimer); codeTimer = setTimeout(applySceneText, 250); });
  $("download").addEventListener("click", () => {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([JSON.stringify(sceneForRequest(), null, 2)], { type: "application/json" }));
    a.download = "lab-scene.json";
    a.click();
  });
  $("load").addEventListener("change", async () => {
    const file = $("load").files[0];
    if (!file) return;
    try { await loadScene(JSON.parse(await file.text())); } catch (e) { showErrors([{ message: `${file.name}: ${e.message}` }]); }
  });
  $("figure").addEventListener("change", () => { if ($("figure").value) openFigure($("figure").value).catch((e) => showErrors([{ message: String(e) }])); });
  $("row").addEventListener("change", () => { if ($("row").value !== "") openRow(Number($("row").value)).catch((e) => showErrors([{ message: String(e) }])); });
  $("row-value").addEventListener("input", (ev) => { ev.stopPropagation(); onRowValue(); });
  $("row-strip").addEventListener("change", render);
  await buildLecture();
  // The theme: the system's ("auto") unless one is chosen; kept in this browser.
  const theme = localStorage.getItem("shadelab-theme") || "auto";
  $("theme").value = theme;
  if (theme !== "auto") document.documentElement.dataset.theme = theme;
  $("theme").addEventListener("change", () => {
    const t = $("theme").value;
    if (t === "auto") delete document.documentElement.dataset.theme;
    else document.documentElement.dataset.theme = t;
    localStorage.setItem("shadelab-theme", t);
  });
  $("show-lights").addEventListener("change", drawLights);
  window.addEventListener("resize", drawLights);
  $("undo").addEventListener("click", undo);
  $("redo").addEventListener("click", redo);
  document.addEventListener("keydown", onKey);
  document.addEventListener("keydown", onShortcut);
  $("copy-link").addEventListener("click", async () => {
    updateAddress();
    try { await navigator.clipboard.writeText(location.href); $("status").textContent = "link copied"; }
    catch (_) { $("share-link").select(); $("status").textContent = "link selected: copy it with Ctrl+C"; }
  });
  $("save-picture").addEventListener("click", savePicture);
  const linked = sceneFromAddress();
  try {
    await loadScene(linked || scene);
  } catch (e) {  // a link whose scene the controls cannot show
    await loadScene(scene);
    showErrors([{ message: `the link's scene cannot be shown: ${e.message}` }]);
  }
}
start();
