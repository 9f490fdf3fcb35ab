// The lab's picture in the student's hands (lab.js has the page's state and wiring): the
// camera turned by dragging and moved by the wheel, the lights drawn over the picture and
// dragged, and the keys for the common toggles.
"use strict";

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
  if (c.projection_matrix) {  // column-major, as a captured GL frame gives it
    const m = c.projection_matrix, v = [e[0], e[1], e[2], 1];
    const clip = [0, 1, 3].map((r) => [0, 1, 2, 3].reduce((sum, k) => sum + m[4 * k + r] * v[k], 0));
    if (!(clip[2] > 1e-6)) return null;
    x = clip[0] / clip[2]; y = clip[1] / clip[2];
  } else if (c.projection === "orthographic") {
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
