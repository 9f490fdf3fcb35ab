// The lighting lab in headless Firefox (Debian's firefox-esr, driven over WebDriver BiDi by
// puppeteer-core): the same checks as the Chromium test, so that the page is known to work in
// both. Run by ctest (test lab_firefox):
//   node lab_firefox_test.mjs --cli PATH_TO_shadelab --source REPO_DIR --out OUTPUT_DIR
import { join } from "node:path";
import puppeteer from "puppeteer-core";

import { check, checkSum, finish, imageKeyInPage, options, pixelInPage, startServer } from "./harness.mjs";

const firefox = process.env.FIREFOX || "/usr/bin/firefox-esr";
const { cli, source, out } = options("lab_firefox_test.mjs", firefox);
const { url, server } = await startServer(cli, source);

const browser = await puppeteer.launch({
  browser: "firefox", executablePath: firefox, headless: true, protocol: "webDriverBiDi",
  // No network beyond loopback.
  extraPrefsFirefox: { "network.proxy.type": 0, "network.dns.disableIPv6": true },
});
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 950 });
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(url);
  await page.waitForSelector("#images img");
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check((await page.$$eval("#lights tbody tr:not(.details)", (r) => r.length)) === 9, "the lecture's nine lights are listed");

  const imageKey = () => page.evaluate(imageKeyInPage);
  const before = await imageKey();
  await page.evaluate(() => {
    const el = document.querySelector('[data-path="lights[6].diffuse[0]"]');
    el.value = "0";
    el.dispatchEvent(new Event("input", { bubbles: true }));
  });
  await page.waitForFunction(async (b) => {
    const img = document.querySelector("#images img");
    if (!img) return false;
    const buf = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
    let h = 0;
    for (const x of buf) h = (h * 31 + x) >>> 0;
    return `${buf.length}:${h}` !== b;
  }, { polling: 200, timeout: 10000 }, before).catch(() => {});
  check((await imageKey()) !== before, "changing light 6's red changes the image");

  await page.click("#compare");
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 3);
  const captions = await page.$$eval("#images figcaption", (f) => f.map((x) => x.textContent));
  check(captions.join(",") === "flat,gouraud,phong", `compare mode shows three images (${captions.join(", ")})`);
  await page.click("#compare");
  await page.waitForFunction(() => document.querySelectorAll("#images img").length === 1);

  const box = await (await page.$("#images img")).boundingBox();
  await page.mouse.click(box.x + 200, box.y + 190);
  await page.waitForSelector("#explain-result");
  const explained = await page.$eval("#explain-result", (e) => e.textContent);
  checkSum(explained, await page.evaluate(pixelInPage, { x: 200, y: 190 }));

  await page.evaluate(() => {
    document.querySelector("#lights tbody tr:not(.details) button").click();  // "more"
    const el = document.querySelector('input[type=number][data-path="lights[0].spot.cutoff"]');
    el.value = "120";
    el.dispatchEvent(new Event("change", { bubbles: true }));
  });
  await page.waitForSelector(".field-error");
  const error = await page.$eval('[data-path="lights[0].spot.cutoff"] + .field-error', (e) => e.textContent);
  check(/out of range/.test(error || ""), `the error is next to the field: "${error}"`);

  // Share and keep: the setup in the address, a second page opened from it, undo and redo.
  const setNumber = (path, value) => page.evaluate((p, v) => {
    const el = document.querySelector(`input[type=number][data-path="${p}"]`);
    el.value = v;
    el.dispatchEvent(new Event("change", { bubbles: true }));
  }, path, value);
  const shininessField = 'input.num[data-path="objects[0].material.shininess"]';
  await setNumber("lights[0].spot.cutoff", "30");  // a valid setup again
  const shininessBefore = await page.$eval(shininessField, (e) => e.value);
  await setNumber("objects[0].material.shininess", "77");
  await page.waitForFunction(() => { const s = sceneFromAddress(); return s && s.objects[0].material.shininess === 77; });
  const link = await page.evaluate(() => location.href);
  const second = await browser.newPage();
  await second.goto(link);
  await second.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check((await second.$eval(shininessField, (e) => e.value)) === "77", "a link opens the same setup (shininess 77)");
  await second.close();
  await page.click("#undo");
  await page.waitForFunction((f, v) => document.querySelector(f).value === v, {}, shininessField, shininessBefore);
  check(await page.evaluate(() => sceneFromAddress().objects[0].material.shininess !== 77), "undo restores the setup and the link");
  await page.click("#redo");
  await page.waitForFunction((f) => document.querySelector(f).value === "77", {}, shininessField);
  check(true, "redo applies it again");

  // A lecture figure from the menu.
  await page.evaluate(() => {
    const menu = document.getElementById("figure");
    menu.value = "10-spot-cutoff.json";
    menu.dispatchEvent(new Event("change", { bubbles: true }));
  });
  await page.waitForFunction(() => document.querySelectorAll("#lights tbody tr:not(.details)").length === 1);
  check((await page.$eval("#figure-caption", (e) => e.textContent)).startsWith("Figure 10"), "a figure opens with its caption");

  // The light in the picture, where the camera sees it (figure 10: at the centre), dragged.
  await page.waitForFunction(() => {
    const dot = document.querySelector("#images svg.markers .handle"), img = document.querySelector("#images img");
    return dot && Math.abs(Number(dot.getAttribute("cx")) - img.clientWidth / 2) < 1.5;
  }, { timeout: 30000 });
  const dot = await (await page.$("#images svg.markers .handle")).boundingBox();
  await page.mouse.move(dot.x + dot.width / 2, dot.y + dot.height / 2);
  await page.mouse.down();
  await page.mouse.move(dot.x + dot.width / 2 + 40, dot.y + dot.height / 2, { steps: 6 });
  await page.mouse.up();
  const lightX = Number(await page.$eval('input[data-path="lights[0].position[0]"]', (e) => e.value));
  check(Math.abs(lightX - 0.322) < 0.02, `dragging the light's dot moves the light (x ${lightX})`);

  // The camera by hand: a drag away from the light turns it around the target.
  await page.waitForFunction(() => {
    const img = document.querySelector("#images img");
    return img && img.complete && document.getElementById("status").textContent.startsWith("rendered");
  });
  await new Promise((r) => setTimeout(r, 300));
  const img = await (await page.$("#images img")).boundingBox();
  await page.mouse.move(img.x + img.width / 4, img.y + img.height * 0.8);
  await page.mouse.down();
  await page.mouse.move(img.x + img.width / 4 + 80, img.y + img.height * 0.8 - 30, { steps: 8 });
  await page.mouse.up();
  const eye = await page.evaluate(() => state.scene.camera.eye.slice());
  check(Math.abs(eye[0]) > 0.5 && Math.abs(Math.hypot(...eye) - 8) < 0.01, `dragging the picture turns the camera (eye ${eye.join(",")})`);

  // The code view edits the setup.
  await page.click("#show-code");
  await page.evaluate(() => {
    const code = document.getElementById("code");
    code.value = code.value.replace(/glMaterialf\(GL_FRONT, GL_SHININESS, [^)]*\)/, "glMaterialf(GL_FRONT, GL_SHININESS, 33)");
    code.dispatchEvent(new Event("input", { bubbles: true }));
  });
  await page.waitForFunction(() => document.querySelector('input.num[data-path="objects[0].material.shininess"]').value === "33",
                             { timeout: 10000 }).catch(() => {});
  check((await page.$eval('input.num[data-path="objects[0].material.shininess"]', (e) => e.value)) === "33",
        "editing the code sets the shininess");

  // The dark theme.
  await page.evaluate(() => { const t = document.getElementById("theme"); t.value = "dark"; t.dispatchEvent(new Event("change")); });
  check((await page.evaluate(() => getComputedStyle(document.body).backgroundColor)) === "rgb(22, 24, 28)", "the dark theme darkens the page");
  await page.screenshot({ path: join(out, "lab_firefox_dark.png") });
  await page.evaluate(() => { const t = document.getElementById("theme"); t.value = "light"; t.dispatchEvent(new Event("change")); });
  check(errors.length === 0, `no script errors${errors.length ? ": " + errors.join("; ") : ""}`);
  const shot = join(out, "lab_firefox.png");
  await page.screenshot({ path: shot });
  console.log(`screenshot: ${shot}`);
} finally {
  await browser.close();
  server.kill();
}
finish();
