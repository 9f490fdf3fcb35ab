// The lighting lab's page: the scene is a scene-file JSON object (docs/scene-format.md) that
// the controls edit in place; every render sends it to POST /api/render. Inputs name the
// value they edit with data-path (e.g. "lights[2].diffuse[0]"), the key path the server uses
// in its error messages, so an error lands next to its field. The page's other parts, loaded
// before this file: lab-hands.js (camera, lights in the picture, keys), lab-lecture.js
// (figures, rows, link, undo, Save PNG), lab-code.js (the editable code view).
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
  $("figure-caption").textContent = (linked || scene).caption || "";
  try {
    await loadScene(linked || scene);
  } catch (e) {  // a link whose scene the controls cannot show
    await loadScene(scene);
    showErrors([{ message: `the link's scene cannot be shown: ${e.message}` }]);
  }
}
start();
