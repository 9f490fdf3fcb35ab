// The lighting lab in headless Firefox (Debian's firefox-esr, driven over WebDriver BiDi by
// puppeteer-core): the same checks as the Chromium test, so that the page is known to work in
// both. Run by ctest (test lab_firefox):
//   node lab_firefox_test.mjs --cli PATH_TO_shadelab --source REPO_DIR --out OUTPUT_DIR
import { spawn } from "node:child_process";
import { existsSync, mkdirSync } from "node:fs";
import { join } from "node:path";
import puppeteer from "puppeteer-core";

const arg = (name) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : undefined;
};
const cli = arg("--cli"), source = arg("--source"), out = arg("--out") || ".";
const firefox = process.env.FIREFOX || "/usr/bin/firefox-esr";
if (!cli || !source) {
  console.error("usage: node lab_firefox_test.mjs --cli SHADELAB --source REPO_DIR [--out DIR]");
  process.exit(2);
}
if (!existsSync(firefox)) {
  console.error(`lab_firefox: ${firefox} not found (scripts/setup.sh installs Debian's firefox-esr)`);
  process.exit(1);
}
mkdirSync(out, { recursive: true });

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures += 1;
}

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

  const imageKey = () => page.evaluate(async () => {
    const img = document.querySelector("#images img");
    const buf = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
    let h = 0;
    for (const b of buf) h = (h * 31 + b) >>> 0;
    return `${buf.length}:${h}`;
  });
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

  await page.evaluate(() => {
    document.querySelector("#lights tbody tr:not(.details) button").click();  // "more"
    const el = document.querySelector('input[type=number][data-path="lights[0].spot.cutoff"]');
    el.value = "120";
    el.dispatchEvent(new Event("change", { bubbles: true }));
  });
  await page.waitForSelector(".field-error");
  const error = await page.$eval('[data-path="lights[0].spot.cutoff"] + .field-error', (e) => e.textContent);
  check(/out of range/.test(error || ""), `the error is next to the field: "${error}"`);
  check(errors.length === 0, `no script errors${errors.length ? ": " + errors.join("; ") : ""}`);
  const shot = join(out, "lab_firefox.png");
  await page.screenshot({ path: shot });
  console.log(`screenshot: ${shot}`);
} finally {
  await browser.close();
  server.kill();
}
console.log(failures ? `${failures} check(s) failed` : "all checks passed");
process.exit(failures ? 1 : 0);
