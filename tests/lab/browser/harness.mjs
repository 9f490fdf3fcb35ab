// What both browser tests share: their command line, the checks' tally, the lab's server on a
// free port, and reading a pixel's colour and the explanation's sum from the page.
import { execFileSync, spawn } from "node:child_process";
import { existsSync, mkdirSync, rmSync } from "node:fs";
import { join } from "node:path";

export function options(script, browserPath) {
  const arg = (name) => {
    const i = process.argv.indexOf(name);
    return i > 0 ? process.argv[i + 1] : undefined;
  };
  const cli = arg("--cli"), source = arg("--source"), out = arg("--out") || ".";
  if (!cli || !source) {
    console.error(`usage: node ${script} --cli SHADELAB --source REPO_DIR [--out DIR]`);
    process.exit(2);
  }
  if (!existsSync(browserPath)) {
    console.error(`${script}: ${browserPath} not found (scripts/setup.sh installs it)`);
    process.exit(1);
  }
  mkdirSync(out, { recursive: true });
  return { cli, source, out };
}

let failures = 0;
export function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures += 1;
}
export function finish() {
  console.log(failures ? `${failures} check(s) failed` : "all checks passed");
  process.exit(failures ? 1 : 0);
}

// `shadelab serve [SCENE] --port 0`; resolves to { url, server } once it prints its address.
export function startServer(cli, source, scene) {
  const args = ["serve", ...(scene ? [scene] : []), "--port", "0"];
  const server = spawn(cli, args, { cwd: source, stdio: ["ignore", "pipe", "inherit"] });
  return new Promise((resolve, reject) => {
    let text = "";
    server.stdout.on("data", (d) => {
      text += d;
      const m = text.match(/http:\/\/[^\s]+/);
      if (m) resolve({ url: m[0], server });
    });
    server.on("exit", (code) => reject(new Error(`shadelab serve exited with ${code}`)));
    setTimeout(() => reject(new Error("shadelab serve did not start")), 20000);
  });
}

// Functions evaluated in the page (both drivers take a function and its arguments).
export async function imageKeyInPage() {
  const img = document.querySelector("#images img");
  const buf = new Uint8Array(await (await fetch(img.src)).arrayBuffer());
  let h = 0;
  for (const b of buf) h = (h * 31 + b) >>> 0;
  return `${buf.length}:${h}`;
}
export function pixelInPage({ x: cx, y: cy }) {
  const img = document.querySelector("#images img");
  const c = document.createElement("canvas");
  c.width = img.naturalWidth; c.height = img.naturalHeight;
  const g = c.getContext("2d");
  g.drawImage(img, 0, 0);
  const r = img.getBoundingClientRect();
  const x = Math.floor(cx / r.width * img.naturalWidth), y = Math.floor(cy / r.height * img.naturalHeight);
  return Array.from(g.getImageData(x, y, 1, 1).data.slice(0, 3));
}

// Checks that the explanation's clamped sum, "(r, g, b)/255", is the shown pixel's colour.
export function checkSum(explained, shown) {
  const m = explained && explained.match(/\((\d+), (\d+), (\d+)\)\/255/);
  const close = m && [1, 2, 3].every((k) => Math.abs(Number(m[k]) - shown[k - 1]) <= 2);
  check(!!close, `the explanation's sum (${m ? m.slice(1).join(", ") : "none"}) is the pixel's colour (${shown.join(", ")})`);
}

// A GLUT program's frame 2 kept as a scene (`shadelab run --capture-scene`) in `dir`, with the
// frame itself as frameN.png; returns what the command printed (`extra`: more options).
export function captureFrame(cli, glut, dir, extra = []) {
  rmSync(dir, { recursive: true, force: true });
  return execFileSync(cli, ["run", "--xvfb", "--frames", "2", "--capture", join(dir, "frame%d.png"),
    "--capture-scene", join(dir, "frame.json"), ...extra, "--", glut], { encoding: "utf8" });
}

// In the page: the share of pixels of the lab's picture within 2/255 of the image `src`.
export async function agreementInPage(src) {
  const read = async (s) => {
    const img = new Image();
    img.src = s;
    await img.decode();
    const c = document.createElement("canvas");
    c.width = img.naturalWidth, c.height = img.naturalHeight;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    return g.getImageData(0, 0, c.width, c.height).data;
  };
  const a = await read(src), b = await read(document.querySelector("#images img").src);
  if (a.length !== b.length) return 0;
  let close = 0;
  for (let i = 0; i < a.length; i += 4) {
    close += Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2])) <= 2;
  }
  return close / (a.length / 4);
}
