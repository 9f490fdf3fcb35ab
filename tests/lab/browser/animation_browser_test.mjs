// `shadelab animate` makes an animation that plays in a browser: the lecture's spot cutoff as
// an animated PNG, shown by headless Chromium (Debian's, through playwright-core), whose
// picture changes while the page stays as it is, through the narrow cone and the wide one.
// Run by ctest (test animation_browser):
//   node animation_browser_test.mjs --cli PATH_TO_shadelab --source REPO_DIR --out OUTPUT_DIR
import { execFileSync } from "node:child_process";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { chromium } from "playwright-core";

import { check, finish, options } from "./harness.mjs";

const browserPath = process.env.CHROMIUM || "/usr/bin/chromium";
const { cli, source, out } = options("animation_browser_test.mjs", browserPath);
const apng = join(out, "cutoff-animation.png");
execFileSync(cli, ["animate", join(source, "scenes/lecture/10-spot-cutoff.json"), "--vary",
                   "lights[0].spot.cutoff=5:60", "--frames", "8", "--fps", "2", "--size", "64x64", "-o", apng]);
const dataUrl = `data:image/png;base64,${readFileSync(apng).toString("base64")}`;

const browser = await chromium.launch({ executablePath: browserPath, args: ["--no-sandbox"] });
try {
  const page = await browser.newPage();
  await page.setContent(`<img id="a" src="${dataUrl}">`);
  await page.waitForFunction(() => document.getElementById("a").complete);
  // What the browser shows, as screenshots of the image taken while it plays (a canvas would
  // only ever draw an animation's first frame), and the share of lit pixels in each.
  const shown = new Set();
  // (2 frames a second: every frame is caught even on a loaded machine; up to 20 s of it)
  const started = Date.now();
  while (Date.now() - started < 20000 && shown.size < 8) {
    shown.add((await page.locator("#a").screenshot()).toString("base64"));
    await page.waitForTimeout(100);
  }
  const shares = (await page.evaluate(async (shots) => {
    const out = [];
    for (const shot of shots) {
      const img = new Image();
      img.src = `data:image/png;base64,${shot}`;
      await img.decode();
      const c = document.createElement("canvas");
      c.width = img.naturalWidth, c.height = img.naturalHeight;
      const g = c.getContext("2d");
      g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      let lit = 0;
      for (let i = 0; i < d.length; i += 4) lit += d[i] > 128;
      out.push(lit / (d.length / 4));
    }
    return out;
  }, [...shown])).sort((x, y) => x - y);
  check((await page.evaluate(() => document.getElementById("a").naturalWidth)) === 64, "the browser decodes it (64 px wide)");
  check(shares.length >= 4, `the picture changes as it plays (${shares.length} different frames seen)`);
  check(shares[0] < 0.1 && shares[shares.length - 1] > 0.2,
        `a narrow cone and a wide one among them (lit shares ${shares[0].toFixed(3)} to ${shares[shares.length - 1].toFixed(3)})`);
} finally {
  await browser.close();
}
finish();
