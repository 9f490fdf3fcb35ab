// A GL program's frame explained in the lab: `shadelab run --capture-scene` keeps frame 2 of a
// GLUT program (tests/platform/glut_scene.c: a lit teapot, torus, GLU sphere, cylinder and
// disk) as a scene file, `--explain` prints a pixel's lighting equation, `shadelab serve` opens
// the scene in the lab (headless Chromium through playwright-core), whose picture is the
// program's frame and whose click on the teapot explains that pixel. Run by ctest (capture_lab):
//   node capture_browser_test.mjs --cli SHADELAB --source REPO_DIR --glut GLUT_SCENE --out DIR
import { existsSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";

import { agreementInPage, captureFrame, check, checkSum, finish, options, pixelInPage, startServer } from "./harness.mjs";

const browserPath = process.env.CHROMIUM || "/usr/bin/chromium";
const { cli, source, out } = options("capture_browser_test.mjs", browserPath);
const glut = process.argv[process.argv.indexOf("--glut") + 1];
const dir = join(out, "capture");
const scene = join(dir, "frame.json");

// 1. The frame as a scene, and a pixel of the teapot explained on the command line.
const text = captureFrame(cli, glut, dir, ["--explain", "160,120"]);
console.log(text);
check(existsSync(scene) && existsSync(join(dir, "frame-1.obj")), "--capture-scene wrote the scene and its OBJ files");
check(/frame 2, pixel \(160, 120\): draw 1, gouraud shading, front face/.test(text), "--explain names the teapot's draw");
check(/light 0: attenuation 1\.000, spot 1\.000, N\.L 0\.\d+/.test(text) && /diffuse\s+0\.\d+/.test(text),
  "--explain prints light 0's terms");
const printed = text.match(/colour \(clamped to 0\.\.1\).*= \((\d+), (\d+), (\d+)\)/);
const shown = text.match(/the frame shows.*= \((\d+), (\d+), (\d+)\)/);
// The breakdown is the equation at the pixel (Phong); the frame interpolates vertex colours.
check(printed && shown && [1, 2, 3].every((k) => Math.abs(Number(printed[k]) - Number(shown[k])) <= 16),
  `the explained colour (${printed && printed.slice(1).join(", ")}) is near the frame's (${shown && shown.slice(1).join(", ")})`);
const parsed = JSON.parse(readFileSync(scene, "utf8"));
check(parsed.objects.length === 4 && parsed.lights.length === 1 && parsed.lights[0].space === "eye",
  "the scene has the program's four materials and its light, in eye space");
check(parsed.camera.fovy === 40 && parsed.camera.near === 1 && parsed.camera.far === 30,
  "gluPerspective(40, aspect, 1, 30) comes back as fovy 40, near 1, far 30");

// 2. The lab shows that frame and explains its pixels.
const { url, server } = await startServer(cli, source, scene);
const browser = await chromium.launch({ executablePath: browserPath, args: ["--no-sandbox"] });
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  await page.goto(url);
  await page.waitForFunction(() => {
    const img = document.querySelector("#images img");
    return img && img.complete && img.naturalWidth > 0;
  });
  check((await page.locator("#figure-caption").textContent()).includes("captured by shadelab"),
    "the lab shows the capture's caption");
  const size = await page.evaluate(() => {
    const img = document.querySelector("#images img");
    return [img.naturalWidth, img.naturalHeight];
  });
  check(size[0] === 320 && size[1] === 240, `the lab renders the frame's size (${size.join(" x ")})`);
  // The lab's picture against the program's frame 2, pixel by pixel.
  const frame = `data:image/png;base64,${readFileSync(join(dir, "frame2.png")).toString("base64")}`;
  const agree = await page.evaluate(agreementInPage, frame);
  check(agree >= 0.99, `the lab's picture is the program's frame (${(agree * 100).toFixed(2)} % of pixels within 2/255)`);
  // Click the teapot (pixel 160, 120 of 320 x 240), in Phong shading so that the sum is the pixel.
  await page.selectOption("#shading", "phong").catch(() => {});
  await page.waitForTimeout(600);
  const box = await page.locator("#images img").first().boundingBox();
  const at = { x: box.width * 160.5 / 320, y: box.height * 120.5 / 240 };
  await page.locator("#images img").first().click({ position: at });
  await page.waitForSelector("#explain-result");
  const explained = await page.locator("#explain").textContent();
  check(explained.includes("draw 1"), "clicking the teapot explains the teapot's draw");
  checkSum(await page.locator("#explain-result").textContent(), await page.evaluate(pixelInPage, at));
  await page.screenshot({ path: join(out, "capture_lab.png") });
} finally {
  await browser.close();
  server.kill();
}
finish();
