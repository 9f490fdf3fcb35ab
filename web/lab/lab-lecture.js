// The lab's lecture menu and its memory (lab.js has the page's state and wiring): the
// lecture's figures and row experiments in one click, and the setup kept in the page's
// address, with undo, redo and Save PNG.
"use strict";

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
