// A GL program's frame in the lab, in headless Firefox (Debian's firefox-esr over WebDriver BiDi,
// puppeteer-core): the lab half of capture_browser_test.mjs. A GLUT program's frame 2 kept by
// `shadelab run --capture-scene`, served by `shadelab serve`, shown as the program drew it and a
// pixel of its teapot explained. Run by ctest (platform.capture_lab_firefox):
//   node capture_firefox_test.mjs --cli SHADELAB --source REPO_DIR --glut GLUT_SCENE --out DIR
import { readFileSync } from "node:fs";
import { join } from "node:path";
import puppeteer from "puppeteer-core";

import { agreementInPage, captureFrame, check, checkSum, finish, options, pixelInPage, startServer } from "./harness.mjs";

const firefox = process.env.FIREFOX || "/usr/bin/firefox-esr";
const { cli, source, out } = options("capture_firefox_test.mjs", firefox);
const glut = process.argv[process.argv.indexOf("--glut") + 1];
const dir = join(out, "capture-firefox");
captureFrame(cli, glut, dir);

const { url, server } = await startServer(cli, source, join(dir, "frame.json"));
const browser = await puppeteer.launch({
  browser: "firefox", executablePath: firefox, headless: true, protocol: "webDriverBiDi",
  extraPrefsFirefox: { "network.proxy.type": 0, "network.dns.disableIPv6": true },
});
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 900 });
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(url);
  await page.waitForSelector("#images img");
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  check((await page.$eval("#figure-caption", (e) => e.textContent)).includes("captured by shadelab"),
    "the lab shows the capture's caption");
  const frame = `data:image/png;base64,${readFileSync(join(dir, "frame2.png")).toString("base64")}`;
  const agree = await page.evaluate(agreementInPage, frame);
  check(agree >= 0.99, `the lab's picture is the program's frame (${(agree * 100).toFixed(2)} % of pixels within 2/255)`);
  // The teapot (pixel 160, 120 of 320 x 240) in Phong shading, so that the sum is the pixel.
  await page.select("#shading", "phong");
  await page.waitForFunction(() => document.getElementById("status").textContent.startsWith("rendered"));
  await new Promise((r) => setTimeout(r, 600));
  const box = await (await page.$("#images img")).boundingBox();
  const at = { x: box.width * 160.5 / 320, y: box.height * 120.5 / 240 };
  await page.mouse.click(box.x + at.x, box.y + at.y);
  await page.waitForSelector("#explain-result");
  check((await page.$eval("#explain", (e) => e.textContent)).includes("draw 1"), "clicking the teapot explains the teapot's draw");
  checkSum(await page.$eval("#explain-result", (e) => e.textContent), await page.evaluate(pixelInPage, at));
  check(errors.length === 0, `no script errors${errors.length ? ": " + errors.join("; ") : ""}`);
  await page.screenshot({ path: join(out, "capture_lab_firefox.png") });
} finally {
  await browser.close();
  server.kill();
}
finish();
