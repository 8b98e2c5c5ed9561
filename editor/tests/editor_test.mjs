// The editor in headless Chromium (Debian's, driven by puppeteer-core),
// against a real `shadetree serve` of a copy of gallery graphs: open a
// graph and see its preview; drag a param slider and see the preview
// change with no compile; add a noise node and wire it in; wire a vec2
// into a vec3 input and see the checker's error on that input; save, and
// check the saved file with `shadetree check`. With a third argument, the
// screenshot of the editor with the graph opened (docs/editor.png).
//   node editor/tests/editor_test.mjs SHADETREE_BINARY SOURCE_DIR [SCREENSHOT.png]
import { spawn, spawnSync } from "node:child_process";
import { copyFileSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import assert from "node:assert/strict";
import puppeteer from "puppeteer-core";

const [binary, source, screenshot] = process.argv.slice(2);
const folder = mkdtempSync(join(tmpdir(), "shadetree-editor-test-"));
copyFileSync(join(source, "graphs", "marble.json"), join(folder, "marble.json"));

const server = spawn(binary, ["serve", folder], { stdio: ["ignore", "pipe", "pipe"] });
server.stderr.on("data", (data) => process.stderr.write(data));
const url = await new Promise((resolve, reject) => {
  let out = "";
  server.stdout.on("data", (data) => {
    out += data;
    const match = out.match(/open (http:\/\/\S+)/);
    if (match) resolve(match[1]);
  });
  server.on("exit", (code) => reject(new Error(`shadetree serve exited with ${code}`)));
});
const origin = new URL(url);
const stats = async () => (await fetch(`${origin.origin}/api/stats`, { headers: { "X-Shadetree-Token": origin.searchParams.get("token") } })).json();

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", `--user-data-dir=${join(folder, ".chromium")}`],
});
let failed = false;
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 760 });
  const errors = [];
  page.on("pageerror", (error) => errors.push(String(error)));
  await page.goto(url);
  await page.waitForFunction(() => window.shadetreeEditor && window.shadetreeEditor.state.previews > 0, { timeout: 20000 });
  const previewPixels = () => page.evaluate(() => {
    const data = document.getElementById("preview").getContext("2d").getImageData(0, 0, 256, 256).data;
    let sum = 0;
    for (let i = 0; i < data.length; i += 97) sum = (sum * 31 + data[i]) % 1000000007;
    return sum;
  });
  const before = await previewPixels();
  if (screenshot) await page.screenshot({ path: screenshot });
  assert.equal(await page.evaluate(() => window.shadetreeEditor.graph._nodes.length > 5), true, "the graph's nodes are on the canvas");
  console.log("opened marble.json: preview drawn");

  // Drag the "scale" slider with the mouse.
  const compilesBefore = (await stats()).compiles;
  const previewsBefore = await page.evaluate(() => window.shadetreeEditor.state.previews);
  const slider = await page.$('input[name="scale"]');
  const box = await slider.boundingBox();
  await page.mouse.move(box.x + 2, box.y + box.height / 2);
  await page.mouse.down();
  for (let step = 1; step <= 10; ++step) await page.mouse.move(box.x + step * 3, box.y + box.height / 2);
  await page.mouse.up();
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: 10000 }, previewsBefore);
  await new Promise((resolve) => setTimeout(resolve, 300));
  assert.notEqual(await previewPixels(), before, "the preview changed");
  assert.equal((await stats()).compiles, compilesBefore, "a param drag never recompiles");
  console.log("dragged the scale slider: preview changed, no compile");

  // Add a noise node and wire it into the stirring: mul.a = noise.
  await page.select("#palette", "noise");
  await page.click("#add-node");
  await page.evaluate(() => {
    const editor = window.shadetreeEditor;
    editor.connect("p", "out", "noise1", "p");
    editor.connect("noise1", "out", "stirred", "a");
  });
  await page.waitForFunction(() => window.shadetreeEditor.documentFromCanvas().nodes.some((n) => n.id === "stirred" && n.in.a === "noise1"));
  await page.waitForFunction(() => document.getElementById("status").textContent.endsWith(": ok"), { timeout: 10000 });
  console.log("added noise1 and wired it into stirred.a: the graph checks");

  // A vec2 into a vec3 input: the checker's error, on that input.
  await page.select("#palette", "uv");
  await page.click("#add-node");
  await page.evaluate(() => window.shadetreeEditor.connect("uv1", "out", "noise1", "p"));
  await page.waitForFunction(() => window.shadetreeEditor.state.lastError !== null, { timeout: 10000 });
  const error = await page.evaluate(() => window.shadetreeEditor.state.lastError);
  assert.equal(error.node, "noise1");
  assert.equal(error.input, "p");
  assert.match(error.message, /vec3/);
  assert.equal(await page.evaluate(() => window.shadetreeEditor.graph._nodes.find((v) => v.shadetreeId === "noise1").inputs[0].label), "p: vec3 ⚠");
  console.log(`wired uv1 (vec2) into noise1.p (vec3): ${error.text}`);

  // Back to a valid graph, save, and check the file.
  await page.evaluate(() => window.shadetreeEditor.connect("p", "out", "noise1", "p"));
  await page.waitForFunction(() => window.shadetreeEditor.state.lastError === null, { timeout: 10000 });
  assert.equal(await page.evaluate(() => window.shadetreeEditor.save()), true);
  const check = spawnSync(binary, ["check", join(folder, "marble.json")], { encoding: "utf8" });
  assert.equal(check.status, 0, check.stderr);
  const saved = JSON.parse(readFileSync(join(folder, "marble.json"), "utf8"));
  assert.equal(saved.nodes.find((n) => n.id === "stirred").in.a, "noise1");
  assert.notEqual(saved.params.scale.default, 6, "the dragged param value is saved");
  assert.ok(saved.functions.marble_color, "fields the editor does not show are kept");
  console.log("saved: shadetree check accepts the file");
  assert.deepEqual(errors, [], "no script errors");
} catch (error) {
  failed = true;
  console.error(error);
} finally {
  // Chromium can linger on close; it is not what is tested.
  await Promise.race([browser.close(), new Promise((resolve) => setTimeout(resolve, 3000))]);
  browser.process()?.kill("SIGKILL");
  const stopped = new Promise((resolve) => server.on("exit", resolve));
  server.kill("SIGTERM");
  const timeout = new Promise((resolve) => setTimeout(() => resolve("timeout"), 5000));
  if ((await Promise.race([stopped, timeout])) === "timeout") {
    console.error("shadetree serve did not stop on SIGTERM within 5 s");
    server.kill("SIGKILL");
    failed = true;
  }
  rmSync(folder, { recursive: true, force: true });
}
process.exit(failed ? 1 : 0);
