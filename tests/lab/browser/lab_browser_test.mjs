// Browser tests of the lighting lab in headless Chromium (Debian's, through playwright-core):
// the page as a student uses it. Run by ctest (test lab_browser):
//   node lab_browser_test.mjs --cli PATH_TO_shadelab --source REPO_DIR --out OUTPUT_DIR
// Exit status 0 when every check passes; a screenshot of the page is saved in OUTPUT_DIR.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";

import { check, checkSum, finish, imageKeyInPage, options, pixelInPage, startServer } from "./harness.mjs";

const browserPath = process.env.CHROMIUM || "/usr/bin/chromium";
const { cli, source, out } = options("lab_browser_test.mjs", browserPath);
const { url, server } = await startServer(cli, source);

const browser = await chromium.launch({
  executablePath: browserPath,
  args: ["--no-sandbox", "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"],
});
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 950 }, acceptDownloads: true });
  page.on("pageerror", (e) => check(false, `no script error (${e.message})`));
  await page.goto(url);
  await page.waitForSelector("#images img");
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));

  // The bytes of the image shown, to tell one picture from another.
  const imageKey = () => page.evaluate(imageKeyInPage);
  check((await page.locator("#lights tbody tr:not(.details)").count()) === 9, "the lecture's nine lights are listed");

  // 1. A light's colour changes the picture.
  const before = await imageKey();
  const red = page.locator('[data-path="lights[6].diffuse[0]"]').first();
  await red.fill("0");
  await red.dispatchEvent("input");
  // The new picture arrives after a render of unknown length (a sanitizer build takes
  // seconds): poll for it, up to 30 s, rather than trusting the status line, which may still
  // read "rendered" from the picture before.
  let after = before;
  for (let waited = 0; after === before && waited < 30000; waited += 100) {
    await page.waitForTimeout(100);
    after = await imageKey();
  }
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check(after !== before, "changing light 6's red changes the image");

  // 2. Compare mode shows flat, Gouraud and Phong side by side.
  await page.locator("#compare").check();
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 3);
  const captions = await page.locator("#images figcaption").allTextContents();
  check(captions.join(",") === "flat,gouraud,phong", `compare mode shows three images (${captions.join(", ")})`);
  await page.locator("#compare").uncheck();
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 1);

  // 3. Clicking the (Phong-shaded) sphere explains the pixel, and the sum is its colour.
  const img = page.locator("#images img").first();
  await img.click({ position: { x: 200, y: 190 } });
  await page.waitForSelector("#explain-result");
  const explained = await page.locator("#explain-result").textContent();
  checkSum(explained, await page.evaluate(pixelInPage, { x: 200, y: 190 }));
  check((await page.locator("#explain table tbody tr").count()) >= 9 + 3, "every light has its row in the explanation");

  // 4. An invalid value is reported next to its field.
  await page.locator("#lights tbody tr:not(.details)").first().locator("button", { hasText: "more" }).click();
  const cutoff = page.locator('input[type=number][data-path="lights[0].spot.cutoff"]');
  await cutoff.fill("120");
  await cutoff.dispatchEvent("change");
  await page.waitForSelector(".field-error");
  const error = await page.locator('[data-path="lights[0].spot.cutoff"] + .field-error').first().textContent();
  check(/out of range/.test(error || ""), `the error is next to the field: "${error}"`);

  // 5. Show code gives OpenGL calls for the same settings.
  await page.locator("#show-code").click();
  const code = await page.locator("#code").inputValue();
  check(code.includes("glLightfv(GL_LIGHT8, GL_DIFFUSE") && code.includes("glMaterialf(GL_FRONT, GL_SHININESS"),
        "show code lists the GL calls");
  await cutoff.fill("30");  // a valid setup again (step 4 left an error)
  await cutoff.dispatchEvent("change");
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  await page.locator("#show-code").click();  // shown again: the code of the setup as it is now
  await page.locator("#show-code").click();

  // 5b. The code can be edited: light 6's diffuse red in its array, the shininess in its call;
  // a line the view does not understand is listed with its line number and changes nothing.
  const edited = (await page.locator("#code").inputValue())
    .replace(/(\/\* light 6 \*\/\n.*\n\s*GLfloat diffuse\[\] = \{)[^,]*/, "$10.250f")
    .replace(/glMaterialf\(GL_FRONT, GL_SHININESS, [^)]*\)/, "glMaterialf(GL_FRONT, GL_SHININESS, 64)")
    .replace("glEnable(GL_LIGHTING);", "glEnable(GL_LIGHTING);\nglFrobnicate(1);");
  const beforeEdit = await imageKey();
  await page.locator("#code").fill(edited);
  await page.waitForFunction(() => document.querySelector('input[data-path="lights[6].diffuse[0]"]').value === "0.25");
  const shininessNow = await page.locator('input.num[data-path="objects[0].material.shininess"]').inputValue();
  const codeErrors = await page.locator("#code-errors").textContent();
  check(shininessNow === "64" && /^line \d+: not understood: "glFrobnicate\(1\);"/.test(codeErrors),
        `editing the code sets the values (light 6 red 0.25, shininess ${shininessNow}) and lists the bad line (${codeErrors.split("(")[0].trim()})`);
  let afterEdit = beforeEdit;
  for (let waited = 0; afterEdit === beforeEdit && waited < 30000; waited += 100) {
    await page.waitForTimeout(100);
    afterEdit = await imageKey();
  }
  check(afterEdit !== beforeEdit, "and the picture follows");
  const sceneText = JSON.parse(await page.locator("#scene-text").inputValue());
  sceneText.objects[0].material.shininess = 12;
  await page.locator("#scene-text").fill(JSON.stringify(sceneText, null, 2));
  await page.waitForFunction(() => document.querySelector('input.num[data-path="objects[0].material.shininess"]').value === "12");
  await page.locator("#scene-text").fill("{ \"lights\": [");
  await page.waitForFunction(() => document.getElementById("scene-errors").textContent.startsWith("the scene file:"));
  check((await page.locator('input.num[data-path="objects[0].material.shininess"]').inputValue()) === "12",
        "the scene file edits the setup too, and a broken one is reported and changes nothing");
  await page.locator("#show-code").click();

  // 6. Share and keep: the setup in the address, undo and redo, a picture saved at a size.
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  const shininess = page.locator('input.num[data-path="objects[0].material.shininess"]');
  const shininessBefore = await shininess.inputValue();
  // The setup so far is a step of its own once the controls have been still for 400 ms (the
  // address then holds it): wait for that, so that undo returns to it.
  await page.waitForFunction((v) => sceneFromAddress().objects[0].material.shininess === Number(v), shininessBefore);
  await shininess.fill("77");
  await shininess.dispatchEvent("change");
  await page.waitForFunction(() => { const s = sceneFromAddress(); return s && s.objects[0].material.shininess === 77; });
  const link = await page.evaluate(() => location.href);
  const second = await browser.newPage({ viewport: { width: 1400, height: 950 } });
  await second.goto(link);
  await second.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check((await second.locator('input.num[data-path="objects[0].material.shininess"]').inputValue()) === "77",
        "a link opens the same setup (shininess 77)");
  await second.close();
  await page.locator("#undo").click();
  await page.waitForFunction((v) => document.querySelector('input.num[data-path="objects[0].material.shininess"]').value === v,
                             shininessBefore);
  check(await page.evaluate(() => sceneFromAddress().objects[0].material.shininess !== 77), "undo restores the setup and the link");
  await page.locator("#redo").click();
  await page.waitForFunction(() => document.querySelector('input.num[data-path="objects[0].material.shininess"]').value === "77");
  check(true, "redo applies it again");
  await page.locator("#save-width").fill("320");
  await page.locator("#save-height").fill("200");
  await page.locator("#save-samples").selectOption("1");
  const [download] = await Promise.all([page.waitForEvent("download"), page.locator("#save-picture").click()]);
  const saved = readFileSync(await download.path());
  check(saved.readUInt32BE(16) === 320 && saved.readUInt32BE(20) === 200 && download.suggestedFilename() === "lab-320x200.png",
        `save picture downloads a 320 x 200 PNG (${download.suggestedFilename()}, ${saved.readUInt32BE(16)} x ${saved.readUInt32BE(20)})`);

  // 7. The lecture in one click: a figure from the menu, then a row with its slider and strip.
  await page.locator("#figure").selectOption("10-spot-cutoff.json");
  await page.waitForFunction(() => document.querySelectorAll("#lights tbody tr:not(.details)").length === 1);
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check((await page.locator("#figure-caption").textContent()).startsWith("Figure 10"), "a figure opens with its caption");
  const rowIndex = await page.locator("#row option", { hasText: "Spot cutoff" }).getAttribute("value");
  await page.locator("#row").selectOption(rowIndex);
  await page.waitForFunction(() => !document.getElementById("row-controls").hidden);
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  const cutoffField = 'input[type=number][data-path="lights[0].spot.cutoff"]';
  check((await page.locator(cutoffField).inputValue()) === "50", "a row opens at its first value (cutoff 50)");
  const wide = await imageKey();
  await page.locator("#row-value").evaluate((e) => { e.value = "3"; e.dispatchEvent(new Event("input", { bubbles: true })); });
  let narrow = wide;
  for (let waited = 0; narrow === wide && waited < 30000; waited += 100) {
    await page.waitForTimeout(100);
    narrow = await imageKey();
  }
  check(narrow !== wide && (await page.locator(cutoffField).inputValue()) === "20" &&
        (await page.locator("#row-label").textContent()) === "cutoff = 20",
        "dragging the row's slider sets the value (cutoff 20) and changes the picture");
  await page.locator("#row-strip").check();
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 4);
  const rowCaptions = await page.locator("#images figcaption").allTextContents();
  check(rowCaptions.join(",") === "cutoff = 50,cutoff = 40,cutoff = 30,cutoff = 20",
        `the whole row side by side (${rowCaptions.join(", ")})`);
  await page.locator("#row-strip").uncheck();

  // 8. The dark theme, chosen in the header, kept for the next visit.
  const background = () => page.evaluate(() => getComputedStyle(document.body).backgroundColor);
  const light = await background();
  await page.locator("#theme").selectOption("dark");
  const dark = await background();
  await page.screenshot({ path: join(out, "lab_browser_dark.png") });
  await page.reload();
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check(light === "rgb(245, 246, 248)" && dark === "rgb(22, 24, 28)" && (await background()) === dark,
        `the dark theme darkens the page and stays after a reload (${light} -> ${dark})`);
  await page.locator("#theme").selectOption("light");
  await page.locator("#row").selectOption(rowIndex);
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));

  // 9. The camera by hand: a drag turns it around the target, the wheel moves it away; keys.
  await page.locator("#row-strip").uncheck();
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 1);
  await page.locator("#images img").first().click({ position: { x: 20, y: 20 } });  // explain a pixel...
  await page.waitForFunction(() => !document.getElementById("explain").hidden);
  await page.locator("body").click({ position: { x: 5, y: 5 } });
  await page.keyboard.press("e");  // ...and hide it with E
  check(await page.locator("#explain").isHidden(), "key E hides the explanation");
  const eye0 = await page.evaluate(() => state.scene.camera.eye.slice());
  const picture0 = await imageKey();
  const box = await page.locator("#images img").first().boundingBox();
  // (from a corner: the light's dot at the centre would be dragged instead)
  await page.mouse.move(box.x + box.width / 4, box.y + box.height * 0.8);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 4 + 80, box.y + box.height * 0.8 - 30, { steps: 8 });
  await page.mouse.up();
  const eye1 = await page.evaluate(() => state.scene.camera.eye.slice());
  const dist = (e) => Math.hypot(e[0], e[1], e[2]);  // the figures look at the origin
  check(Math.abs(eye1[0] - eye0[0]) > 0.5 && Math.abs(dist(eye1) - dist(eye0)) < 0.01,
        `dragging the picture turns the camera around its target (eye ${eye0.join(",")} -> ${eye1.join(",")})`);
  let picture1 = picture0;
  for (let waited = 0; picture1 === picture0 && waited < 30000; waited += 100) {
    await page.waitForTimeout(100);
    picture1 = await imageKey();
  }
  check(picture1 !== picture0, "and the picture follows");
  check(await page.locator("#explain").isHidden(), "a drag is not a click (no explanation)");
  const box2 = await page.locator("#images img").first().boundingBox();
  await page.mouse.move(box2.x + box2.width / 2, box2.y + box2.height / 2);
  await page.mouse.wheel(0, 400);
  await page.waitForTimeout(200);
  const eye2 = await page.evaluate(() => state.scene.camera.eye.slice());
  check(dist(eye2) > dist(eye1) + 0.5, `the wheel moves the camera away (distance ${dist(eye1).toFixed(2)} -> ${dist(eye2).toFixed(2)})`);
  await page.locator("body").click({ position: { x: 5, y: 5 } });
  await page.keyboard.press("3");
  check((await page.locator("#shading").inputValue()) === "phong", "key 3 sets Phong shading");
  await page.keyboard.press("c");
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 3);
  const compared = await page.locator("#compare").isChecked();
  await page.keyboard.press("c");
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 1);
  check(compared && !(await page.locator("#compare").isChecked()), "key C turns the comparison on and off");

  // 10. The lights in the picture: figure 10's spot light, 2 units in front of the wall on the
  // camera's axis, is drawn at the picture's centre; dragging its dot moves it sideways.
  const before10 = await imageKey();
  await page.locator("#figure").selectOption("10-spot-cutoff.json");  // the camera as the figure has it
  for (let waited = 0; (await imageKey()) === before10 && waited < 30000; waited += 100) await page.waitForTimeout(100);
  await page.waitForFunction(() => document.querySelectorAll("#images svg.markers .handle").length === 1);
  const shown = await page.evaluate(() => {
    const img = document.querySelector("#images img"), dot = document.querySelector("#images svg.markers .handle");
    return { cx: Number(dot.getAttribute("cx")), cy: Number(dot.getAttribute("cy")), w: img.clientWidth, h: img.clientHeight };
  });
  check(Math.abs(shown.cx - shown.w / 2) < 1.5 && Math.abs(shown.cy - shown.h / 2) < 1.5,
        `the spot light is drawn where the camera sees it (${shown.cx}, ${shown.cy} in ${shown.w} x ${shown.h})`);
  check((await page.locator("#images svg.markers line").count()) === 3, "with its spot axis and cone");
  const lit0 = await imageKey();
  const dot = await page.locator("#images svg.markers .handle").boundingBox();
  await page.mouse.move(dot.x + dot.width / 2, dot.y + dot.height / 2);
  await page.mouse.down();
  await page.mouse.move(dot.x + dot.width / 2 + 40, dot.y + dot.height / 2, { steps: 6 });
  await page.mouse.up();
  const expected = 40 * (2 * 6 * Math.tan(Math.PI / 12)) / shown.h;  // 6 units from the eye, fovy 30
  const moved = Number(await page.locator('input[data-path="lights[0].position[0]"]').inputValue());
  check(Math.abs(moved - expected) < 0.02, `dragging the light 40 px moves it ${moved} (expected ${expected.toFixed(3)}) in its field`);
  let lit1 = lit0;
  for (let waited = 0; lit1 === lit0 && waited < 30000; waited += 100) {
    await page.waitForTimeout(100);
    lit1 = await imageKey();
  }
  check(lit1 !== lit0, "and the picture follows");

  // 11. At a projector's 1280 x 720 nothing overflows: the page, the light table, the
  // explanation of a pixel.
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.locator("#figure").selectOption("18-lighting-controls.json");
  await page.waitForFunction(() => document.querySelectorAll("#lights tbody tr:not(.details)").length === 9);
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  await page.locator("#images img").first().click({ position: { x: 200, y: 190 } });
  await page.waitForSelector("#explain-result");
  const overflow = await page.evaluate(() => ["#explain", "#lights", "#controls"].map((q) => {
    const e = document.querySelector(q);
    return e.scrollWidth - e.clientWidth;
  }).concat([document.documentElement.scrollWidth - document.documentElement.clientWidth]));
  check(overflow.every((d) => d <= 0), `nothing overflows at 1280 x 720 (${overflow.join(", ")} px too wide)`);
  await page.screenshot({ path: join(out, "lab_browser_1280x720.png") });

  const shot = join(out, "lab_browser.png");
  await page.screenshot({ path: shot, fullPage: false });
  console.log(`screenshot: ${shot}`);
} finally {
  await browser.close();
  server.kill();
}
finish();
