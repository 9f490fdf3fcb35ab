// Browser tests of the lighting lab in headless Chromium (Debian's, through playwright-core):
// the page as a student uses it. Run by ctest (test lab_browser):
//   node lab_browser_test.mjs --cli PATH_TO_shadelab --source REPO_DIR --out OUTPUT_DIR
// Exit status 0 when every check passes; a screenshot of the page is saved in OUTPUT_DIR.
import { spawn } from "node:child_process";
import { existsSync, mkdirSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";

const arg = (name) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : undefined;
};
const cli = arg("--cli"), source = arg("--source"), out = arg("--out") || ".";
const browserPath = process.env.CHROMIUM || "/usr/bin/chromium";
if (!cli || !source) {
  console.error("usage: node lab_browser_test.mjs --cli SHADELAB --source REPO_DIR [--out DIR]");
  process.exit(2);
}
if (!existsSync(browserPath)) {
  console.error(`lab_browser: ${browserPath} not found (scripts/setup.sh installs Debian's chromium)`);
  process.exit(1);
}
mkdirSync(out, { recursive: true });

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures += 1;
}

// The server on a free port; its first line names it.
const server = spawn(cli, ["serve", "--port", "0"], { cwd: source, stdio: ["ignore", "pipe", "inherit"] });
const url = await new Promise((resolve, reject) => {
  let text = "";
  server.stdout.on("data", (d) => {
    text += d;
    const m = text.match(/http:\/\/[^\s]+/);
    if (m) resolve(m[0]);
  });
  server.on("exit", (code) => reject(new Error(`shadelab serve exited with ${code}`)));
  setTimeout(() => reject(new Error("shadelab serve did not start")), 20000);
});

const browser = await chromium.launch({
  executablePath: browserPath,
  args: ["--no-sandbox", "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"],
});
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 950 } });
  page.on("pageerror", (e) => check(false, `no script error (${e.message})`));
  await page.goto(url);
  await page.waitForSelector("#images img");
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));

  // The bytes of the image shown, to tell one picture from another.
  const imageKey = () => page.evaluate(async () => {
    const img = document.querySelector("#images img");
    const buf = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
    let h = 0;
    for (const b of buf) h = (h * 31 + b) >>> 0;
    return `${buf.length}:${h}`;
  });
  check((await page.locator("#lights tbody tr:not(.details)").count()) === 9, "the lecture's nine lights are listed");

  // 1. A light's colour changes the picture.
  const before = await imageKey();
  const red = page.locator('[data-path="lights[6].diffuse[0]"]').first();
  await red.fill("0");
  await red.dispatchEvent("input");
  await page.waitForFunction((b) => {
    const s = document.getElementById("status").textContent;
    return s.startsWith("rendered");
  }, before);
  await page.waitForTimeout(300);
  check((await imageKey()) !== before, "changing light 6's red changes the image");

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
  const m = explained.match(/\((\d+), (\d+), (\d+)\)\/255/);
  const shown = await page.evaluate(() => {
    const img = document.querySelector("#images img");
    const c = document.createElement("canvas");
    c.width = img.naturalWidth; c.height = img.naturalHeight;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    const r = img.getBoundingClientRect();
    const x = Math.floor(200 / r.width * img.naturalWidth), y = Math.floor(190 / r.height * img.naturalHeight);
    return Array.from(g.getImageData(x, y, 1, 1).data.slice(0, 3));
  });
  const close = m && [1, 2, 3].every((k) => Math.abs(Number(m[k]) - shown[k - 1]) <= 2);
  check(!!close, `the explanation's sum (${m ? m.slice(1).join(", ") : "none"}) is the pixel's colour (${shown.join(", ")})`);
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
  const code = await page.locator("#code").textContent();
  check(code.includes("glLightfv(GL_LIGHT8, GL_DIFFUSE") && code.includes("glMaterialf(GL_FRONT, GL_SHININESS"),
        "show code lists the GL calls");

  const shot = join(out, "lab_browser.png");
  await page.screenshot({ path: shot, fullPage: false });
  console.log(`screenshot: ${shot}`);
} finally {
  await browser.close();
  server.kill();
}
console.log(failures ? `${failures} check(s) failed` : "all checks passed");
process.exit(failures ? 1 : 0);
