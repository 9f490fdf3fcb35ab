// The lab's code view (lab.js has the page's state and wiring): the settings as OpenGL 1.x
// calls and as a scene file, both editable.
"use strict";

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
