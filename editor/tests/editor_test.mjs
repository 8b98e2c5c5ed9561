// The editor in headless Chromium (Debian's, driven by puppeteer-core),
// against a real `shadetree serve` of a copy of gallery graphs: open a
// graph and see its preview and node thumbnails; drag a param slider and
// see the preview change with no compile; add a noise node and wire it in;
// wire a vec2 into a vec3 input and see the checker's error on that input;
// save, and check the saved file with `shadetree check`; show a function's
// body, drag a control point of its spline with the mouse and see the
// preview change, undo and redo it; export a PNG; save as a new file, and
// check it. With a third argument, the screenshot of the editor with the
// graph opened and its thumbnails drawn (docs/editor.png). Also: drag a
// node and undo the move; in the params panel, change a range (no
// compile), rename a param, add one and delete it, and see a delete of a
// param in use refused; and the curve the curve editor draws agrees with
// the server's spline, Catmull-Rom and linear; a volume opens as a draft
// refined to the full size, and its slider drag draws drafts, refined on
// a pause; a graph opened during a preview never shows the earlier
// graph's picture; a malformed file and one that is JSON but no graph are
// refused on open and Ctrl+S cannot write over them; a file changed on
// disk since it was opened is written over only when the user says so;
// leaving the page with
// unsaved edits asks first; every gallery file opened and saved unedited
// is written back byte for byte, and a changed param default changes one
// line of its file; constants typed into a node's unwired inputs (a float,
// a vec3) are previewed, undone, redone and saved as one line; the kind
// field changes a new graph's kind and back; a Ctrl+drag box selects the
// nodes in it. In a
// second Chromium with WebGL 2, marble is previewed on the page's GPU, a
// slider drag redraws it with no request to the server, and the server's
// preview of it agrees within a level of 255. First, the unit tests of the page's modules that need
// no browser (editor/tests/*_test.mjs but this one).
//   node editor/tests/editor_test.mjs SHADETREE_BINARY SOURCE_DIR [SCREENSHOT.png]
import { spawn, spawnSync } from "node:child_process";
import { copyFileSync, cpSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import assert from "node:assert/strict";
import puppeteer from "puppeteer-core";

const [binary, source, screenshot] = process.argv.slice(2);
const testStarted = performance.now();
const unitTests = readdirSync(join(source, "editor", "tests")).filter((name) => name.endsWith("_test.mjs") && name !== "editor_test.mjs");
const units = spawnSync(process.execPath, ["--test", "--test-reporter=dot", ...unitTests.map((name) => join(source, "editor", "tests", name))],
                        { encoding: "utf8" });
if (units.status !== 0) {
  console.error(units.stdout, units.stderr);
  process.exit(1);
}
console.log(`unit tests passed: ${unitTests.join(", ")}`);

const folder = mkdtempSync(join(tmpdir(), "shadetree-editor-test-"));
copyFileSync(join(source, "graphs", "marble.json"), join(folder, "marble.json"));
// Listed after marble.json, which the page opens first.
cpSync(join(source, "graphs"), join(folder, "roundtrip"), { recursive: true });
mkdirSync(join(folder, "wrong"));
writeFileSync(join(folder, "wrong", "broken.json"), "{\"format\": ");
const notAGraph = '{"format": "shadetree-graph", "version": 1, "name": "n", "kind": "texture", "nodes": [1], "outputs": {}}\n';
writeFileSync(join(folder, "wrong", "not_a_graph.json"), notAGraph);

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
const request = (path, options = {}) =>
  fetch(`${origin.origin}${path}`, { ...options, headers: { "X-Shadetree-Token": origin.searchParams.get("token") } });
const stats = async () => (await request("/api/stats")).json();

// How long a step waits for the server's answer to an edit (a preview, a
// check, a file opened). The suite runs this test beside the MPI and
// render tests on two cores, where a cold kernel compile and its draft can
// take seconds (10 s was once too few for a fireball preview after an
// edit); latency is measured and reported on its own lines, not here.
const serverWait = 30000;

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
  // Every dialog is logged: one the test does not answer blocks the page
  // (a spurious "changed on disk" did, once).
  page.on("dialog", (dialog) => console.log(`dialog ${dialog.type()}: ${dialog.message()}`));
  await page.goto(url);
  await page.waitForFunction(() => window.shadetreeEditor && window.shadetreeEditor.state.previews > 0, { timeout: 20000 });
  await page.evaluate(() => {
    window.previewChecksum = () => {
      const data = document.getElementById("preview").getContext("2d").getImageData(0, 0, 256, 256).data;
      let sum = 0;
      for (let i = 0; i < data.length; i += 97) sum = (sum * 31 + data[i]) % 1000000007;
      return sum;
    };
  });
  const previewPixels = () => page.evaluate(() => window.previewChecksum());
  // Litegraph finds the node under the pointer by the bounds it computes
  // when it draws a frame.
  const drawn = () => page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  // A point of node `id`'s title bar, in page pixels.
  const titlePoint = async (id) => {
    await drawn();
    return page.evaluate((id) => {
      const { canvas, viewOf } = window.shadetreeEditor;
      const view = viewOf(id);
      const [x, y] = canvas.ds.convertOffsetToCanvas([view.pos[0] + 40, view.pos[1] - 15]);
      const box = canvas.canvas.getBoundingClientRect();
      return [box.left + x, box.top + y];
    }, id);
  };
  // Drags param `name`'s slider with the mouse, 3 pixels a step.
  const dragSlider = async (name, steps, on = page) => {
    const slider = await on.$(`input[name="${name}"]`);
    await slider.scrollIntoView();
    const box = await slider.boundingBox();
    await on.mouse.move(box.x + 2, box.y + box.height / 2);
    await on.mouse.down();
    for (let step = 1; step <= steps; ++step) await on.mouse.move(box.x + 2 + step * 3, box.y + box.height / 2);
    await on.mouse.up();
  };
  // A slider dragged for a second as a fast hand does, an input event each
  // 120 Hz frame (sent in the page: puppeteer's mouse takes tens of ms a
  // move), and what the page measured meanwhile (editor.js recordLatency):
  // the median latency of the drag's value edits, from the edit to the
  // preview showing it, and the previews drawn per second of the drag.
  // Reported against the goals (30 ms, 30 per second), never
  // asserted: timings depend on the machine.
  const timedDrag = (name, on) => on.evaluate(async (name) => {
    const { state } = window.shadetreeEditor;
    state.latencies = [];
    state.drawTimes = [];
    const slider = document.querySelector(`input[name="${name}"]`);
    const [low, high, first] = [Number(slider.min), Number(slider.max), Number(slider.value)];
    const started = performance.now();
    for (let frame = 1; performance.now() - started < 1000; ++frame) {
      slider.value = String(low + ((first - low + frame * (high - low) / 400) % (high - low)));
      slider.dispatchEvent(new Event("input", { bubbles: true }));
      await new Promise((resolve) => setTimeout(resolve, 8));
    }
    const ended = performance.now();
    slider.dispatchEvent(new Event("change", { bubbles: true }));
    await new Promise((resolve) => setTimeout(resolve, 300));
    const values = state.latencies.filter((entry) => !entry.structural).map((entry) => entry.ms).sort((a, b) => a - b);
    const seconds = (ended - started) / 1000;
    return { median: values[Math.floor(values.length / 2)], count: values.length,
             perSecond: state.drawTimes.filter((at) => at >= started && at <= ended).length / seconds };
  }, name);
  const pressKeys = async (...keys) => {
    for (const key of keys) await page.keyboard.down(key);
    for (const key of keys.reverse()) await page.keyboard.up(key);
  };
  // Every status the page shows from now on (a preview's "ok" may replace
  // another at once), in window.statusesShown.
  const watchStatus = () => page.evaluate(() => {
    window.statusesShown = [];
    if (window.statusWatched) return;
    window.statusWatched = true;
    const status = document.getElementById("status");
    new MutationObserver(() => window.statusesShown.push(status.textContent))
      .observe(status, { childList: true, characterData: true, subtree: true });
  });
  // Ctrl+S, and the text of the file it saves, read once the page says it
  // saved it (saves write a temporary file and rename it).
  const saveWithKeys = async (path) => {
    await watchStatus();
    await pressKeys("Control", "s");
    await page.waitForFunction((path) => window.statusesShown.includes(`saved ${path}`), { timeout: 20000 }, path)
      .catch(async (error) => {
        throw new Error(`no "saved ${path}" among the statuses ${JSON.stringify(await page.evaluate(() => window.statusesShown))} (${error})`);
      });
    return readFileSync(join(folder, path), "utf8");
  };
  const settled = () => page.waitForFunction(() => !window.shadetreeEditor.history.take, { timeout: 20000 });
  const paramsOf = () => page.evaluate(() => window.shadetreeEditor.documentFromCanvas().params);
  const before = await previewPixels();
  assert.equal(await page.evaluate(() => window.shadetreeEditor.graph._nodes.length > 5), true, "the graph's nodes are on the canvas");
  console.log("opened marble.json: preview drawn");

  // Thumbnails come after the preview, one node at a time.
  await page.waitForFunction(() => {
    const { thumbnails, graphView } = window.shadetreeEditor;
    return thumbnails.pending === 0 && graphView.thumbnailsDrawn > 0;
  }, { timeout: 20000 });
  const pictured = await page.evaluate(() => [...window.shadetreeEditor.thumbnails.cache].filter(([, entry]) => entry.image).map(([key]) => key));
  assert.ok(pictured.includes("/turb"), `a thumbnail of turb (got ${pictured})`);
  if (screenshot) await page.screenshot({ path: screenshot });
  console.log(`thumbnails drawn on ${pictured.length} nodes`);

  // Drag the "scale" slider with the mouse.
  const compilesBefore = (await stats()).compiles;
  const previewsBefore = await page.evaluate(() => window.shadetreeEditor.state.previews);
  await dragSlider("scale", 10);
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: serverWait }, previewsBefore);
  await new Promise((resolve) => setTimeout(resolve, 300));
  assert.notEqual(await previewPixels(), before, "the preview changed");
  assert.equal((await stats()).compiles, compilesBefore, "a param drag never recompiles");
  console.log("dragged the scale slider: preview changed, no compile");

  // The same slider dragged for a second as a fast hand does, drawn by the
  // server (the GPU box off; this Chromium composites in software, as a
  // machine without a GPU does, where the page's WebGL 2 is SwiftShader's):
  // marble's full preview takes longer than a 60 Hz frame here, so the
  // drag draws half-size drafts and the pause after it the full size.
  // Undone after, so the value is the one above's.
  const draggedScale = await page.evaluate(() => window.shadetreeEditor.documentFromCanvas().params.scale.default);
  const gpuBox = await page.evaluate(() => window.shadetreeEditor.gpu.available && document.getElementById("gpu").checked);
  if (gpuBox) await page.click("#gpu");
  await page.waitForFunction(() => document.getElementById("preview-info").textContent.includes("CPU") &&
                                   window.shadetreeEditor.thumbnails.pending === 0, { timeout: 20000 });
  const serverDrag = await timedDrag("scale", page);
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === window.shadetreeEditor.state.previewSide &&
                                   window.shadetreeEditor.state.latencies.every((entry) => !entry.gpu),
                             { timeout: serverWait });
  if (gpuBox) await page.click("#gpu");
  await page.evaluate(() => window.shadetreeEditor.undo());
  assert.equal(await page.evaluate(() => window.shadetreeEditor.documentFromCanvas().params.scale.default), draggedScale,
               "undo takes back the timed drag in one step");
  assert.equal((await stats()).compiles, compilesBefore, "the timed drag never recompiled");
  console.log(`latency from the hand, marble's scale dragged, drawn by the server in a page without a GPU (goals: 30 ms, 30/s): ` +
              `median ${serverDrag.median?.toFixed(1)} ms, ${serverDrag.perSecond.toFixed(1)} previews/s`);

  // Drag node turb by its title: the move is a step of the history.
  await settled();
  const positionOf = (id) => page.evaluate((id) => [...window.shadetreeEditor.viewOf(id).pos], id);
  const turbBefore = await positionOf("turb");
  const stepBefore = await page.evaluate(() => window.shadetreeEditor.history.index);
  const grip = await titlePoint("turb");
  await page.mouse.move(grip[0], grip[1]);
  await page.mouse.down();
  for (let step = 1; step <= 6; ++step) await page.mouse.move(grip[0] + step * 10, grip[1] + step * 6);
  await page.mouse.up();
  await page.waitForFunction((n) => window.shadetreeEditor.history.index > n, { timeout: 20000 }, stepBefore);
  const turbMoved = await positionOf("turb");
  assert.notDeepEqual(turbMoved, turbBefore, "the drag moved turb");
  await pressKeys("Control", "z");
  assert.deepEqual(await positionOf("turb"), turbBefore, "undo puts turb back");
  await pressKeys("Control", "Shift", "z");
  assert.deepEqual(await positionOf("turb"), turbMoved, "redo moves it again");
  console.log(`dragged turb from ${turbBefore.map(Math.round)} to ${turbMoved.map(Math.round)}: undo put it back, redo moved it again`);

  // A new max for turbulence_amount in the params panel: its slider's
  // range changes, and only the uniform block (no compile).
  const compilesBeforeMax = (await stats()).compiles;
  const previewsBeforeMax = await page.evaluate(() => window.shadetreeEditor.state.previews);
  await page.click('button[title="edit param turbulence_amount"]');
  await page.click('input[name="turbulence_amount.max"]', { clickCount: 3 });
  await page.keyboard.type("50");
  await page.keyboard.press("Tab");
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: serverWait }, previewsBeforeMax);
  assert.equal(await page.$eval('input[name="turbulence_amount"]', (slider) => slider.max), "50");
  assert.equal((await paramsOf()).turbulence_amount.max, 50);
  assert.equal((await stats()).compiles, compilesBeforeMax, "a new max never recompiles");
  // A min above that max is refused in the panel, saying why.
  await page.click('input[name="turbulence_amount.min"]', { clickCount: 3 });
  await page.keyboard.type("60");
  await page.keyboard.press("Tab");
  assert.equal((await paramsOf()).turbulence_amount.min, 0, "the min is kept");
  const minRefusal = await page.$eval('input[name="turbulence_amount.min"]', (field) =>
    field.closest(".param-settings").querySelector(".param-message").textContent);
  assert.match(minRefusal, /must not be above max/);
  console.log("set turbulence_amount's max to 50 in the panel: the slider's max changed, no compile; a min of 60 refused");

  // Retype octaves as a float: turbulence's octaves input wants an int,
  // and the checker says so there; undo brings the int back.
  await page.click('button[title="edit param octaves"]');
  await page.select('select[name="octaves.type"]', "float");
  await page.waitForFunction(() => window.shadetreeEditor.state.errors[0]?.node === "turb", { timeout: serverWait });
  const retyped = await page.evaluate(() => window.shadetreeEditor.state.errors[0]);
  assert.equal(retyped.input, "octaves", retyped.text);
  assert.equal((await paramsOf()).octaves.type, "float");
  await pressKeys("Control", "z");
  await page.waitForFunction(() => window.shadetreeEditor.state.errors.length === 0, { timeout: serverWait });
  assert.equal((await paramsOf()).octaves.type, "int");
  await page.click('button[title="edit param octaves"]');  // closed again: the panel below stays in view
  console.log(`retyped octaves as float: ${retyped.text.replace(/^.*: node/, "node")}; undo made it an int again`);

  // Rename it: the main graph's reference follows.
  await page.click('input[name="turbulence_amount.name"]', { clickCount: 3 });
  await page.keyboard.type("stir");
  await page.keyboard.press("Tab");
  await page.waitForSelector('input[name="stir"]', { timeout: 20000 });
  const renamed = await page.evaluate(() => window.shadetreeEditor.documentFromCanvas());
  assert.deepEqual(Object.keys(renamed.params), ["scale", "stir", "octaves"], "the renamed param keeps its place");
  assert.equal(renamed.nodes.find((n) => n.id === "stirred").in.b, "$stir");
  await page.waitForFunction(() => document.getElementById("status").textContent.endsWith(": ok"), { timeout: serverWait });
  console.log("renamed turbulence_amount to stir: stirred.b reads $stir, the graph checks");

  // Add a param, delete it, and undo the delete; a param in use is not deleted.
  await page.type('input[name="new-param-name"]', "gain");
  await page.select('select[name="new-param-type"]', "float");
  await page.click(".param-adder button");
  await page.waitForSelector('input[name="gain"]', { timeout: 20000 });
  assert.deepEqual((await paramsOf()).gain, { type: "float", default: 0.5, min: 0, max: 1 });
  assert.ok(await page.evaluate(() => window.shadetreeEditor.graphView.boundaryView("sources").findOutputSlot("gain") >= 0),
            "the canvas's params node has gain");
  await settled();
  await page.click('button[title="edit param gain"]');
  await page.click('button[title="delete param gain"]');
  await page.waitForFunction(() => !document.querySelector('input[name="gain"]'), { timeout: 20000 });
  assert.equal((await paramsOf()).gain, undefined);
  await pressKeys("Control", "z");
  await page.waitForSelector('input[name="gain"]', { timeout: 20000 });
  await pressKeys("Control", "Shift", "z");
  await page.waitForFunction(() => !document.querySelector('input[name="gain"]'), { timeout: 20000 });
  await page.click('button[title="edit param scale"]');
  await page.click('button[title="delete param scale"]');
  const refusal = await page.$eval('input[name="scale.name"]', (field) => field.closest(".param").querySelector(".param-message").textContent);
  assert.match(refusal, /used by layer_x/);
  assert.ok((await paramsOf()).scale, "scale is kept");
  console.log(`added param gain, deleted it, undid and redid the delete; deleting scale: ${refusal}`);

  // Add a noise node and wire it into the stirring: mul.a = noise.
  await page.select("#palette", "noise");
  await page.click("#add-node");
  await page.evaluate(() => {
    const editor = window.shadetreeEditor;
    editor.connect("p", "out", "noise1", "p");
    editor.connect("noise1", "out", "stirred", "a");
  });
  await page.waitForFunction(() => window.shadetreeEditor.documentFromCanvas().nodes.some((n) => n.id === "stirred" && n.in.a === "noise1"));
  await page.waitForFunction(() => document.getElementById("status").textContent.endsWith(": ok"), { timeout: serverWait });
  console.log("added noise1 and wired it into stirred.a: the graph checks");

  // A vec2 into a vec3 input: the checker's error, on that input.
  await page.select("#palette", "uv");
  await page.click("#add-node");
  await page.evaluate(() => window.shadetreeEditor.connect("uv1", "out", "noise1", "p"));
  await page.waitForFunction(() => window.shadetreeEditor.state.errors.length > 0, { timeout: serverWait });
  const error = await page.evaluate(() => window.shadetreeEditor.state.errors[0]);
  assert.equal(error.node, "noise1");
  assert.equal(error.input, "p");
  assert.match(error.message, /vec3/);
  assert.equal(await page.evaluate(() => window.shadetreeEditor.graph._nodes.find((v) => v.shadetreeId === "noise1").inputs[0].label), "p: vec3 ⚠");
  console.log(`wired uv1 (vec2) into noise1.p (vec3): ${error.text}`);

  // A second fault, in turb, which no output reads since noise1 took its
  // place in stirred.a: shown too, in amber beside noise1's red.
  await page.evaluate(() => window.shadetreeEditor.connect("uv1", "out", "turb", "p"));
  await page.waitForFunction(() => window.shadetreeEditor.state.unreadErrors.length === 1, { timeout: serverWait });
  const shown = await page.evaluate(() => {
    const { state, graph } = window.shadetreeEditor;
    const view = (id) => graph._nodes.find((v) => v.shadetreeId === id);
    return { errors: state.errors.map((e) => `${e.node}.${e.input}`), unread: state.unreadErrors.map((e) => `${e.node}.${e.input}`),
             colors: [view("noise1").color, view("turb").color], label: view("turb").inputs.find((slot) => slot.name === "p").label };
  });
  assert.deepEqual(shown, { errors: ["noise1.p"], unread: ["turb.p"], colors: ["#8a2c2c", "#8a6a2c"], label: "p: vec3 ⚠" });
  assert.equal((await page.$eval("#diagnostic", (e) => e.textContent)).split("\n").length, 2);
  await page.evaluate(() => window.shadetreeEditor.connect("p", "out", "turb", "p"));
  await page.waitForFunction(() => window.shadetreeEditor.state.unreadErrors.length === 0, { timeout: serverWait });
  console.log("wired uv1 into turb.p, which no output reads: both faults shown, noise1's red and turb's amber");

  // Back to a valid graph, save, and check the file.
  await page.evaluate(() => window.shadetreeEditor.connect("p", "out", "noise1", "p"));
  await page.waitForFunction(() => window.shadetreeEditor.state.errors.length === 0, { timeout: serverWait });
  assert.equal(await page.evaluate(() => window.shadetreeEditor.save()), true);
  const check = spawnSync(binary, ["check", join(folder, "marble.json")], { encoding: "utf8" });
  assert.equal(check.status, 0, check.stderr);
  const saved = JSON.parse(readFileSync(join(folder, "marble.json"), "utf8"));
  assert.equal(saved.nodes.find((n) => n.id === "stirred").in.a, "noise1");
  assert.notEqual(saved.params.scale.default, 6, "the dragged param value is saved");
  assert.ok(saved.functions.marble_color, "fields the editor does not show are kept");
  console.log("saved: shadetree check accepts the file");

  // The spline is in function marble_color: show its body, click its
  // spline node, and drag a control point up in the side panel's curve.
  await page.select("#scope", "marble_color");
  await page.waitForFunction(() => window.shadetreeEditor.viewOf("ramp"));

  // Its inputs: add one (the file stays valid: the preview is drawn
  // again), retype it, be refused deleting one the body reads, delete it.
  const inputsOf = () => page.evaluate(() => window.shadetreeEditor.documentFromCanvas().functions.marble_color.inputs);
  const previewsBeforeInput = await page.evaluate(() => window.shadetreeEditor.state.previews);
  await page.type('input[name="new input name"]', "gain");
  await page.click('button[title^="add an input"]');
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: serverWait }, previewsBeforeInput);
  assert.deepEqual((await inputsOf()).gain, { type: "float", default: 0.5 });
  assert.equal(await page.evaluate(() => window.shadetreeEditor.state.errors.length), 0, "calls stay valid");
  assert.match(await page.$eval("#scope-signature", (e) => e.textContent), /gain/);
  await page.select('select[name="input gain.type"]', "vec2");
  assert.deepEqual((await inputsOf()).gain, { type: "vec2", default: [0.5, 0.5] });
  await page.click('button[title="delete input s"]');
  assert.match(await page.$eval(".input-message", (e) => e.textContent), /input s is read by unit/);
  assert.ok((await inputsOf()).s, "an input the body reads is kept");
  await page.click('button[title="delete input gain"]');
  assert.equal((await inputsOf()).gain, undefined);
  await page.waitForFunction(() => window.shadetreeEditor.viewOf("ramp"));
  console.log("marble_color: added input gain, retyped it, refused deleting s, deleted gain");
  const title = await titlePoint("ramp");
  await page.mouse.click(title[0], title[1]);
  await page.waitForSelector(".curve-editor canvas", { timeout: 20000 });
  const knotsBefore = await page.evaluate(() => JSON.stringify(window.shadetreeEditor.documentFromCanvas().functions.marble_color.nodes.find((n) => n.id === "ramp").knots));
  // Thumbnails come after the preview that the input edits started (so
  // none may be pending yet): wait for this one.
  const functionThumbnail = await page.waitForFunction(
    () => window.shadetreeEditor.thumbnails.cache.get("marble_color/ramp")?.image, { timeout: 20000 }).catch(() => null);
  assert.ok(functionThumbnail, "a thumbnail of the function's node ramp, at its call");
  // The picture to come back to is the full-size one: the input edits
  // above may still show a half-size draft, refined on their pause.
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === window.shadetreeEditor.state.previewSide,
                             { timeout: serverWait });
  const beforeDrag = await previewPixels();
  const previewsBeforeDrag = await page.evaluate(() => window.shadetreeEditor.state.previews);
  const curve = await (await page.$(".curve-editor canvas")).boundingBox();
  const knot = await page.evaluate(() => document.querySelector(".curve-editor canvas").curveEditor.pointOf(3, 0));
  await page.mouse.move(curve.x + knot[0], curve.y + knot[1]);
  await page.mouse.down();
  for (let step = 1; step <= 8; ++step) await page.mouse.move(curve.x + knot[0], curve.y + knot[1] - step * 8);
  await page.mouse.up();
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: serverWait }, previewsBeforeDrag);
  const knotsDragged = await page.evaluate(() => JSON.stringify(window.shadetreeEditor.documentFromCanvas().functions.marble_color.nodes.find((n) => n.id === "ramp").knots));
  assert.notEqual(knotsDragged, knotsBefore, "the drag moved a knot");
  await page.waitForFunction(() => window.shadetreeEditor.history.canUndo && !window.shadetreeEditor.history.take, { timeout: 20000 });
  await page.waitForFunction((sum) => window.shadetreeEditor.state.previews > 0 && window.previewChecksum() !== sum, { timeout: serverWait }, beforeDrag);
  console.log(`dragged spline knot 3 of marble_color.ramp: preview changed`);

  // Undo (Ctrl+Z) brings the knots and the picture back; redo (Ctrl+Shift+Z) the drag.
  const ramp = () => page.evaluate(() => JSON.stringify(window.shadetreeEditor.documentFromCanvas().functions.marble_color.nodes.find((n) => n.id === "ramp").knots));
  await page.keyboard.down("Control");
  await page.keyboard.press("z");
  await page.keyboard.up("Control");
  assert.equal(await ramp(), knotsBefore, "undo restores the knots");
  await page.waitForFunction((sum) => window.previewChecksum() === sum, { timeout: serverWait }, beforeDrag);
  await page.keyboard.down("Control");
  await page.keyboard.down("Shift");
  await page.keyboard.press("z");
  await page.keyboard.up("Shift");
  await page.keyboard.up("Control");
  assert.equal(await ramp(), knotsDragged, "redo repeats the drag");
  console.log("undo: the knots and the preview came back; redo: the drag again");

  // Export a PNG: the server's image file, offered as a download.
  await page.evaluate(() => {
    document.getElementById("export-width").value = 96;
    document.getElementById("export-height").value = 64;
  });
  await page.select("#export-format", "png");
  await page.click("#export");
  await page.waitForFunction(() => window.shadetreeEditor.state.lastExport, { timeout: 20000 });
  const exported = await page.evaluate(async () => {
    const { url, name, type } = window.shadetreeEditor.state.lastExport;
    const bytes = new Uint8Array(await (await fetch(url)).arrayBuffer());
    return { name, type, head: [...bytes.slice(0, 8)], download: document.getElementById("export-link").download };
  });
  assert.deepEqual(exported.head, [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a], "a PNG signature");
  assert.equal(exported.download, "marble.png");
  console.log(`exported ${exported.name} (${exported.type})`);

  // Save as: a name that exists is refused; a new one is written and opened.
  const saveAs = async (name) => {
    await page.click("#save-as");
    await page.click("#save-as-name", { clickCount: 3 });
    await page.keyboard.type(name);
    await page.keyboard.press("Enter");
  };
  // The refusal stays beside the name (a preview ending meanwhile may
  // rewrite the status line).
  await saveAs("marble");
  await page.waitForFunction(() => document.getElementById("save-as-error").value !== "", { timeout: 20000 });
  assert.match(await page.evaluate(() => document.getElementById("save-as-error").value), /exists/);
  await page.click("#save-as-cancel");
  await saveAs("marble_variant");
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "marble_variant.json", { timeout: 20000 });
  assert.equal(await page.evaluate(() => document.getElementById("graph-list").value), "marble_variant.json");
  const variant = spawnSync(binary, ["check", join(folder, "marble_variant.json")], { encoding: "utf8" });
  assert.equal(variant.status, 0, variant.stderr);
  const variantDoc = JSON.parse(readFileSync(join(folder, "marble_variant.json"), "utf8"));
  assert.equal(JSON.stringify(variantDoc.functions.marble_color.nodes.find((n) => n.id === "ramp").knots), knotsDragged);
  console.log("saved as marble_variant.json: shadetree check accepts it, with the dragged knot");

  // A volume: its first picture is a draft, refined to the full size; a
  // slider drag draws drafts, and a pause refines them too.
  // The server's drafts: the GPU box off, where headless Chromium offers
  // WebGL all the same (SwiftShader).
  copyFileSync(join(source, "graphs", "fireball.json"), join(folder, "fireball.json"));
  await page.evaluate(() => {
    const box = document.getElementById("gpu");
    if (!document.getElementById("gpu-label").hidden && box.checked) box.click();
  });
  // A slow volume opened: drafts, then its full preview streamed tile by
  // tile over them. When something new appeared in the preview is logged
  // in the page (each draw into its canvas), and the longest wait from
  // the open to the last tile is reported against the goal of
  // 500 ms, never asserted.
  copyFileSync(join(source, "graphs", "tribble.json"), join(folder, "tribble.json"));
  await page.evaluate(() => {
    window.previewDraws = [];
    const context = document.getElementById("preview").getContext("2d");
    for (const method of ["putImageData", "drawImage"]) {
      const original = context[method].bind(context);
      context[method] = (...args) => {
        window.previewDraws.push({ at: performance.now(), tile: method === "putImageData" && args[0].width < context.canvas.width });
        return original(...args);
      };
    }
    window.openedAt = performance.now();
    window.shadetreeEditor.open("tribble.json");
  });
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "tribble.json" && window.shadetreeEditor.state.drawnSide === 256 &&
                             document.getElementById("preview-info").textContent.startsWith("256x256 in"), { timeout: 120000 });
  const { gaps, tiles, drafts, total } = await page.evaluate(() => {
    const times = [window.openedAt, ...window.previewDraws.map((draw) => draw.at)];
    return {
      gaps: times.slice(1).map((at, i) => at - times[i]),
      tiles: window.previewDraws.filter((draw) => draw.tile).length,
      drafts: window.previewDraws.filter((draw) => !draw.tile).length,
      total: times.at(-1) - times[0],
    };
  });
  assert.ok(tiles >= 2, `tribble's full preview was streamed in tiles (${tiles} tile draws, ${drafts} others)`);
  console.log(`tribble.json opened: ${drafts} drafts, then ${tiles} tiles of the full preview streamed; ` +
              `the longest wait for something new ${Math.max(...gaps).toFixed(0)} ms (goal: 500 ms), the whole ${total.toFixed(0)} ms`);
  const previewsBeforeVolume = await page.evaluate(() => window.shadetreeEditor.state.previews);
  await page.evaluate(() => window.shadetreeEditor.open("fireball.json"));
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === 256, { timeout: 60000 });
  assert.ok(await page.evaluate(() => window.shadetreeEditor.state.previews) >= previewsBeforeVolume + 2,
            `opening draws a draft, then the full preview: ${await page.evaluate(() => document.getElementById("preview-info").textContent)}`);
  await dragSlider("scale", 6);
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide < 256, { timeout: serverWait, polling: 5 });
  const draftSide = await page.evaluate(() => window.shadetreeEditor.state.drawnSide);
  assert.match(await page.evaluate(() => document.getElementById("preview-info").textContent), /refining/);
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === 256, { timeout: 60000 });
  console.log(`fireball.json: a slider drag drew a ${draftSide}x${draftSide} draft, refined to 256x256 on the pause`);
  // Its frame slider spans its render.frames, and playing wraps at the last.
  const frameSlider = await page.$eval("#frame", (slider) => [slider.min, slider.max, slider.closest("#frame-row").hidden]);
  assert.deepEqual(frameSlider, ["0", "47", false], "fireball's frames 0 to 47 on the slider");
  await page.$eval("#frame", (slider) => { slider.value = "47"; slider.dispatchEvent(new Event("change")); });
  await page.click("#play");
  await page.waitForFunction(() => window.shadetreeEditor.state.frame === 0, { timeout: serverWait });
  await page.click("#play");
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === 256, { timeout: 60000 });
  console.log("fireball.json: the frame slider spans its render.frames, 0 to 47; playing from 47 went on at 0");

  // Five wheel notches over the preview dolly toward the fireball without
  // entering its bounds; "Reset view" goes back.
  // (Dispatched on the preview, which may lie below the page's fold.)
  await page.$eval("#preview", (element) => {
    for (let notch = 0; notch < 5; ++notch)
      element.dispatchEvent(new WheelEvent("wheel", { deltaY: -100, bubbles: true, cancelable: true }));
  });
  const cameraDistance = await page.evaluate(() => {
    const camera = window.shadetreeEditor.view.currentCamera();
    return Math.hypot(...camera.position.map((p, i) => p - camera.target[i]));
  });
  assert.ok(cameraDistance > 1.6 * Math.sqrt(3), `five notches left the camera outside the bounds (at ${cameraDistance.toFixed(2)})`);
  await page.waitForFunction(() => !document.getElementById("reset-view").disabled, { timeout: 20000 });
  await page.$eval("#reset-view", (button) => button.click());
  await page.waitForFunction(() => !window.shadetreeEditor.view.changed && window.shadetreeEditor.state.drawnSide === 256 &&
                             !document.getElementById("preview-info").textContent.includes("view moved"), { timeout: 60000 })
    .catch(async (error) => {
      throw new Error(`no full preview after Reset view: ${await page.evaluate(() => JSON.stringify({
        changed: window.shadetreeEditor.view.changed, side: window.shadetreeEditor.state.drawnSide,
        info: document.getElementById("preview-info").textContent }))} (${error})`);
    });
  console.log(`fireball.json: five wheel notches brought the camera from 4.2 to ${cameraDistance.toFixed(2)} of the target, outside the bounds`);

  // Opening a graph with a check error while the fireball's preview is on
  // its way: the fireball's picture is never drawn under the new name. The
  // preview request is held back until the other graph is open, so that
  // it is surely on its way then, and answered after.
  const typeError = JSON.parse(readFileSync(join(source, "graphs", "marble.json"), "utf8"));
  typeError.outputs.color = "no_such_node";
  writeFileSync(join(folder, "type_error.json"), JSON.stringify(typeError, null, 2));
  let held = null;
  const holdPreview = (request) => {
    if (!held && request.url().includes("/api/preview") && request.url().includes("slot=main")) held = request;
    else request.continue();
  };
  await page.setRequestInterception(true);
  page.on("request", holdPreview);
  await dragSlider("scale", 3);
  for (let wait = 0; !held; ++wait) {
    assert.ok(wait < 500, "the drag asked for a preview within 5 s");
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
  await page.evaluate(() => window.shadetreeEditor.open("type_error.json"));
  await held.continue().catch(() => {});  // the page may have given up on it
  await new Promise((resolve) => setTimeout(resolve, 1500));
  page.off("request", holdPreview);
  await page.setRequestInterception(false);
  assert.equal(await page.evaluate(() => window.shadetreeEditor.state.path), "type_error.json");
  assert.ok(await page.evaluate(() => document.getElementById("status").classList.contains("error")), "the check error shows");
  assert.equal(await previewPixels(), 0, "no earlier graph's picture in the preview");
  console.log("opened type_error.json during a fireball preview: its error shows, the fireball's picture does not");

  // Neither a malformed file nor JSON that is no graph becomes the
  // document: chosen in the list, each is refused, the open graph stays
  // open, and Ctrl+S writes that graph, not over the file chosen.
  await page.evaluate(() => window.shadetreeEditor.open("fireball.json"));
  // Refined to the full size, so that no later preview's status replaces the refusal's.
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "fireball.json" && window.shadetreeEditor.state.drawnSide === 256,
                             { timeout: 60000 });
  for (const [name, bytes] of [["broken.json", "{\"format\": "], ["not_a_graph.json", notAGraph]]) {
    await page.select("#graph-list", `wrong/${name}`);
    await page.waitForFunction((name) => document.getElementById("status").textContent.includes(`${name} is not a graph file`),
                               { timeout: 20000 }, name);
    assert.equal(await page.evaluate(() => window.shadetreeEditor.state.path), "fireball.json", "the open graph stays open");
    assert.equal(await page.evaluate(() => document.getElementById("graph-list").value), "fireball.json");
    const refusal = await page.evaluate(() => document.getElementById("status").textContent);
    await saveWithKeys("fireball.json");
    assert.equal(readFileSync(join(folder, "wrong", name), "utf8"), bytes, `${name} is untouched`);
    console.log(`${refusal}; Ctrl+S saved fireball.json and left ${name} untouched`);
  }
  await dragSlider("scale", 2);
  await settled();
  const leaving = await page.evaluate(() => {
    const event = new Event("beforeunload", { cancelable: true });
    window.dispatchEvent(event);
    return event.defaultPrevented;
  });
  assert.ok(leaving, "leaving the page with unsaved edits asks first");
  await saveWithKeys("fireball.json");
  const fireball = spawnSync(binary, ["check", join(folder, "fireball.json")], { encoding: "utf8" });
  assert.equal(fireball.status, 0, fireball.stderr);
  console.log("Ctrl+S after the refusals saved fireball.json, which checks; unsaved edits guard the page");

  // fireball.json changed by another program: Ctrl+S asks before writing
  // over it; no keeps the other program's text, yes writes the graph.
  const elsewhere = readFileSync(join(folder, "fireball.json"), "utf8").replace('"name"', '"doc": "edited elsewhere", "name"');
  writeFileSync(join(folder, "fireball.json"), elsewhere);
  await dragSlider("scale", 3);
  await settled();
  const answer = (accept) => new Promise((resolve) => page.once("dialog", async (dialog) => {
    const message = dialog.message();
    await (accept ? dialog.accept() : dialog.dismiss());
    resolve(message);
  }));
  await watchStatus();
  let asked = answer(false);
  await pressKeys("Control", "s");
  assert.match(await asked, /fireball\.json changed on disk since it was opened here/);
  await page.waitForFunction(() => window.statusesShown.some((text) => text.startsWith("not saved")), { timeout: 20000 });
  assert.equal(readFileSync(join(folder, "fireball.json"), "utf8"), elsewhere, "declined: the other program's text stays");
  asked = answer(true);
  const overwritten = await saveWithKeys("fireball.json");
  await asked;
  assert.ok(!overwritten.includes("edited elsewhere"), "confirmed: the graph shown is written");
  console.log("fireball.json changed on disk: Ctrl+S asked; declined, the file stayed; confirmed, the graph was written");

  // Every gallery file, chosen in the list and saved with Ctrl+S unedited,
  // is written back byte for byte.
  const roundTripStarted = performance.now();
  const gallery = readdirSync(join(source, "graphs")).filter((name) => name.endsWith(".json"));
  for (const name of gallery) {
    const path = `roundtrip/${name}`;
    await page.select("#graph-list", path);
    await page.waitForFunction((path) => window.shadetreeEditor.state.path === path, { timeout: serverWait }, path);
    assert.equal(await saveWithKeys(path), readFileSync(join(source, "graphs", name), "utf8"), `${path} byte for byte`);
  }
  console.log(`${gallery.length} gallery files opened and saved unedited: each byte for byte the same ` +
              `(${((performance.now() - roundTripStarted) / 1000).toFixed(1)} s)`);

  // One param default typed in its field: one line of the file changes.
  await page.select("#graph-list", "roundtrip/fireball.json");
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "roundtrip/fireball.json", { timeout: serverWait });
  await page.click('input[title="strength: exact value"]', { clickCount: 3 });
  await page.keyboard.type("1.25");
  await page.keyboard.press("Tab");
  const edited = (await saveWithKeys("roundtrip/fireball.json")).split("\n");
  const original = readFileSync(join(source, "graphs", "fireball.json"), "utf8").split("\n");
  assert.equal(edited.length, original.length);
  const changed = original.flatMap((line, i) => (line === edited[i] ? [] : [[line, edited[i]]]));
  assert.deepEqual(changed, [[
    '    "strength": {"type": "float", "default": 0.9, "min": 0, "max": 4, "doc": "how far turbulence pushes the surface in"},',
    '    "strength": {"type": "float", "default": 1.25, "min": 0, "max": 4, "doc": "how far turbulence pushes the surface in"},',
  ]]);
  console.log("fireball.json's strength set to 1.25 in its field and saved: that one line of the file changed");

  // Constants on unwired inputs, in the node panel: ball's radius (1.05
  // in the file) and its center (not in the file: the op's default, 0).
  await page.evaluate(() => window.shadetreeEditor.canvas.selectNode(window.shadetreeEditor.viewOf("ball")));
  await page.waitForSelector('input[name="ball.radius"]', { timeout: 20000 });
  assert.equal(await page.$eval('input[name="ball.radius"]', (field) => field.value), "1.05");
  assert.equal(await page.$('input[name="ball.p"]'), null, "a wired input has no field");
  assert.equal(await page.$eval('input[name="ball.center.1"]', (field) => `${field.value}|${field.placeholder}`), "|0");
  const ballInputs = () => page.evaluate(() => window.shadetreeEditor.documentFromCanvas().nodes.find((n) => n.id === "ball").in);
  const typeInto = async (name, text) => {
    await page.click(`input[name="${name}"]`, { clickCount: 3 });
    await page.keyboard.type(text);
  };
  const previewsBeforeRadius = await page.evaluate(() => window.shadetreeEditor.state.previews);
  await typeInto("ball.radius", "1.2");
  await page.keyboard.press("Tab");
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: serverWait }, previewsBeforeRadius);
  assert.deepEqual(await ballInputs(), { p: "scaled", radius: 1.2, softness: 0.9 });
  assert.equal(await page.evaluate(() => window.shadetreeEditor.viewOf("ball").inputs.find((slot) => slot.name === "radius").label),
               "radius: float = 1.2");
  for (const [component, text] of ["0", "0.2", "0"].entries()) await typeInto(`ball.center.${component}`, text);
  await page.keyboard.press("Tab");
  assert.deepEqual((await ballInputs()).center, [0, 0.2, 0]);
  await page.evaluate(() => document.activeElement.blur());
  await settled();
  await pressKeys("Control", "z");
  assert.equal((await ballInputs()).center, undefined, "undo takes the center away");
  await pressKeys("Control", "z");
  assert.equal((await ballInputs()).radius, 1.05, "and then the radius back");
  assert.equal(await page.$eval('input[name="ball.radius"]', (field) => field.value), "1.05", "the panel follows undo");
  await pressKeys("Control", "Shift", "z");
  await pressKeys("Control", "Shift", "z");
  await page.waitForFunction(() => window.shadetreeEditor.state.errors.length === 0 && window.shadetreeEditor.state.previews > 0,
                             { timeout: serverWait });
  const withConstants = (await saveWithKeys("roundtrip/fireball.json")).split("\n");
  const changedByConstants = original.flatMap((line, i) => (line === withConstants[i] ? [] : [withConstants[i]]));
  assert.deepEqual(changedByConstants, [
    '    "strength": {"type": "float", "default": 1.25, "min": 0, "max": 4, "doc": "how far turbulence pushes the surface in"},',
    '    {"id": "ball", "op": "sphere", "in": {"p": "scaled", "radius": 1.2, "softness": 0.9, "center": [0, 0.2, 0]}},',
  ]);
  console.log("ball's radius typed as 1.2 and its center as 0, 0.2, 0 in the node panel: previewed, undone, redone, saved as one line");

  // Promote to param: the radius's "$" makes a param of its value, which
  // the input reads and the Params panel edits; the picture stays.
  const beforePromotion = await page.evaluate(() => window.shadetreeEditor.state.previews);
  await page.click('button[name="promote ball.radius"]');
  const promoted = await page.evaluate(() => {
    const doc = window.shadetreeEditor.documentFromCanvas();
    return { param: window.shadetreeEditor.state.doc.params.ball_radius, radius: doc.nodes.find((n) => n.id === "ball").in.radius };
  });
  assert.deepEqual(promoted, { param: { type: "float", default: 1.2, min: 0, max: 2.4 }, radius: "$ball_radius" });
  await page.waitForSelector('#params input[name="ball_radius"]', { timeout: 20000 });
  assert.equal(await page.$('input[name="ball.radius"]'), null, "the input reads the param: no constant field");
  await page.waitForFunction((n) => window.shadetreeEditor.state.previews > n && window.shadetreeEditor.state.errors.length === 0,
                             { timeout: serverWait }, beforePromotion);
  await pressKeys("Control", "z");
  assert.equal((await ballInputs()).radius, 1.2, "undo takes the param away again");
  assert.equal(await page.evaluate(() => window.shadetreeEditor.state.doc.params.ball_radius), undefined);
  console.log("ball.radius promoted to the param $ball_radius (1.2, 0 to 2.4) and back by undo");

  // The curve editor draws the spline the server renders: uv.x through
  // a spline of colour knots, 16 x 1 pixels, whose centres are at x = (i + 0.5) / 16.
  const probe = {
    format: "shadetree-graph", version: 1, name: "spline_probe", kind: "texture",
    nodes: [
      { id: "st", op: "uv" },
      { id: "coords", op: "split", in: { v: "st" } },
      { id: "curve", op: "spline", in: { x: "coords.x" }, basis: "catmull-rom",
        knots: [[0.3, 0.8, 0.5], [0.2, 0.6, 0.4], [0.7, 0.3, 0.9], [0.4, 0.9, 0.1], [0.8, 0.2, 0.6], [0.5, 0.5, 0.3]] },
    ],
    outputs: { color: "curve" },
  };
  writeFileSync(join(folder, "spline_probe.json"), JSON.stringify(probe, null, 2));
  await page.evaluate(() => window.shadetreeEditor.open("spline_probe.json"));
  const curveTitle = await titlePoint("curve");
  await page.mouse.click(curveTitle[0], curveTitle[1]);
  await page.waitForSelector(".curve-editor canvas", { timeout: 20000 });
  for (const basis of ["catmull-rom", "linear"]) {
    await page.select(".curve-editor select", basis);
    const { drawn, doc } = await page.evaluate(() => {
      const editor = document.querySelector(".curve-editor canvas").curveEditor;
      const xs = Array.from({ length: 16 }, (_, i) => (i + 0.5) / 16);
      return { drawn: xs.map((x) => editor.valueAt(x)), doc: window.shadetreeEditor.documentFromCanvas() };
    });
    assert.equal(doc.nodes.find((n) => n.id === "curve").basis, basis);
    const response = await request("/api/preview?path=spline_probe.json&width=16&height=1", { method: "POST", body: JSON.stringify(doc) });
    assert.equal(response.status, 200, "the server renders the probe");
    const bytes = new Uint8Array(await response.arrayBuffer());
    let worst = 0;
    drawn.forEach((rgb, i) => rgb.forEach((value, c) => {
      worst = Math.max(worst, Math.abs(bytes[4 * i + c] - Math.min(1, Math.max(0, value)) * 255));
    }));
    assert.ok(worst <= 1.5, `the ${basis} curve drawn is within 1.5/255 of the server's (off by ${worst.toFixed(2)}/255)`);
    console.log(`spline_probe.json, ${basis}: the curve drawn agrees with the server's render at 16 x (within ${worst.toFixed(2)}/255)`);
  }
  // Duplicate (Ctrl+D, the canvas has the focus since the title was
  // clicked) keeps the spline's six knots, its basis and its input.
  await page.mouse.click(curveTitle[0], curveTitle[1]);
  await pressKeys("Control", "d");
  const curveNodes = await page.evaluate(() => window.shadetreeEditor.documentFromCanvas().nodes.filter((n) => n.op === "spline"));
  assert.equal(curveNodes.length, 2, "Ctrl+D added a spline");
  assert.deepEqual({ ...curveNodes[1], id: "curve" }, curveNodes[0], "the duplicate keeps knots, basis and wire");
  console.log(`Ctrl+D duplicated curve as ${curveNodes[1].id} with its ${curveNodes[1].knots.length} knots, basis and wire`);

  // Menus offer what the document keeps: no Clone, subgraphs, colours,
  // pins or titles; Add Node lists this document's functions only.
  const menus = await page.evaluate(async () => {
    const { canvas, viewOf } = window.shadetreeEditor;
    const { LiteGraph } = await import("/assets/node_modules/@comfyorg/litegraph/dist/litegraph.es.js");
    return { node: canvas.getNodeMenuOptions(viewOf("curve")).map((item) => item?.content).filter(Boolean),
             canvas: canvas.getCanvasMenuOptions().map((item) => item?.content).filter(Boolean),
             functions: Object.keys(LiteGraph.registered_node_types).filter((type) => type.startsWith("functions/")) };
  });
  assert.deepEqual(menus.node, ["Show in the preview", "Duplicate (Ctrl+D)", "Copy (Ctrl+C)", "Remove"]);
  assert.deepEqual(menus.canvas, ["Add Node", "Paste (Ctrl+V)", "Select all (Ctrl+A)", "Frame all (F)"]);
  assert.deepEqual(menus.functions, [], "marble's function marble_color is not offered in spline_probe.json");
  console.log(`menus: a node's ${menus.node.join(", ")}; the canvas's ${menus.canvas.join(", ")}`);

  // Any node's value in the big preview, from its menu, and the outputs
  // again: the node's picture is its thumbnail's at the preview's size.
  const menuChoice = (id, content) => page.evaluate((id, content) => {
    const { canvas, viewOf } = window.shadetreeEditor;
    canvas.getNodeMenuOptions(viewOf(id)).find((item) => item?.content === content).callback();
  }, id, content);
  // The outputs' picture once every edit so far is drawn.
  const outputsDrawn = () => page.waitForFunction(() => {
    const text = document.getElementById("preview-info").textContent;
    return window.shadetreeEditor.state.undrawnEdits.length === 0 && / in [0-9.]+ ms/.test(text) && !text.includes("node ");
  }, { timeout: 20000 });
  await outputsDrawn();
  const outputsPicture = await page.evaluate(() => Array.from(document.getElementById("preview").getContext("2d").getImageData(0, 0, 256, 256).data));
  await menuChoice("st", "Show in the preview");
  await page.waitForFunction(() => / in [0-9.]+ ms.*node "st"/.test(document.getElementById("preview-info").textContent), { timeout: 20000 });
  const nodePicture = await page.evaluate(() => Array.from(document.getElementById("preview").getContext("2d").getImageData(0, 0, 256, 256).data));
  assert.notDeepEqual(nodePicture, outputsPicture, "the node's value, not the outputs, in the preview");
  // uv: red grows to the right, green upward.
  const at = (x, y, c) => nodePicture[(y * 256 + x) * 4 + c];
  assert.ok(at(250, 128, 0) > 240 && at(5, 128, 0) < 15 && at(128, 5, 1) > 240 && at(128, 250, 1) < 15,
            "the preview shows uv's red and green ramps");
  assert.deepEqual((await page.evaluate(() => window.shadetreeEditor.canvas.getNodeMenuOptions(window.shadetreeEditor.viewOf("st"))
    .map((item) => item?.content)))[0], "Show the outputs in the preview");
  await menuChoice("st", "Show the outputs in the preview");
  await outputsDrawn();
  // (Drawn by the page's GPU or, where it was too slow, the server: one
  // level of 255 apart at most.)
  const outputsAgain = await page.evaluate(() => Array.from(document.getElementById("preview").getContext("2d").getImageData(0, 0, 256, 256).data));
  assert.ok(outputsAgain.every((value, i) => Math.abs(value - outputsPicture[i]) <= 1), "and the outputs again");
  console.log("spline_probe.json: node st (uv) shown in the preview from its menu, then the outputs again");

  // Hover docs: resting the pointer on a node's title shows its op's doc,
  // on an input the input's label, on the outputs node's input the kind's
  // contract for that output, all from /api/nodes.
  const library = await (await request("/api/nodes")).json();
  const hoverText = async ([x, y]) => {
    await page.mouse.move(x - 30, y - 30);
    await page.waitForSelector("#hover-doc", { hidden: true, timeout: 20000 });
    await page.mouse.move(x, y);
    await page.waitForSelector("#hover-doc:not([hidden])", { timeout: 20000 });
    return page.$eval("#hover-doc", (tip) => [tip.querySelector("strong").textContent, tip.querySelector("span").textContent]);
  };
  const inputPoint = (id, name) => page.evaluate((id, name) => {
    const { canvas, viewOf, graphView } = window.shadetreeEditor;
    const view = id === "#outputs" ? graphView.boundaryView("outputs") : viewOf(id);
    const [x, y] = canvas.ds.convertOffsetToCanvas(view.getConnectionPos(true, view.findInputSlot(name)));
    const box = canvas.canvas.getBoundingClientRect();
    return [box.left + x + 4, box.top + y];
  }, id, name);
  const onTitle = await hoverText(await titlePoint("curve"));
  assert.deepEqual(onTitle, ["curve (spline)", library.ops.find((op) => op.name === "spline").doc]);
  const onInput = await hoverText(await inputPoint("curve", "x"));
  assert.equal(onInput[0], "x: float");
  const onOutput = await hoverText(await inputPoint("#outputs", "color"));
  const colorContract = library.kinds.find((kind) => kind.name === "texture").outputs.find((output) => output.name === "color");
  assert.deepEqual(onOutput, [`color: ${colorContract.type}${colorContract.required ? "" : " (optional)"}`, colorContract.doc]);
  await page.mouse.move(5, 5);
  console.log(`hover docs: the spline node's op doc, its input x, and the outputs node's "color": ${onOutput[1]}`);

  // A graph from nothing, with the page's controls and keys only.
  const slotPoint = async (id, input, name) => {
    await drawn();
    return page.evaluate((id, input, name) => {
      const { canvas, viewOf, graphView } = window.shadetreeEditor;
      const view = id === "#outputs" ? graphView.boundaryView("outputs") : viewOf(id);
      const slot = input ? view.findInputSlot(name) : view.findOutputSlot(name);
      const [x, y] = canvas.ds.convertOffsetToCanvas(view.getConnectionPos(input, slot));
      const box = canvas.canvas.getBoundingClientRect();
      return [box.left + x, box.top + y];
    }, id, input, name);
  };
  const wire = async (from, output, to, input) => {
    const [a, b] = [await slotPoint(from, false, output), await slotPoint(to, true, input)];
    await page.mouse.move(a[0], a[1]);
    await page.mouse.down();
    for (let step = 1; step <= 5; ++step) await page.mouse.move(a[0] + (b[0] - a[0]) * step / 5, a[1] + (b[1] - a[1]) * step / 5);
    await page.mouse.up();
  };
  const addWithPalette = async (op) => {
    await page.select("#palette", op);
    await page.click("#add-node");
  };
  const newDoc = () => page.evaluate(() => window.shadetreeEditor.documentFromCanvas());
  // The duplicate is unsaved: New asks first.
  const discard = new Promise((resolve) => page.once("dialog", (dialog) => resolve(dialog.accept())));
  await page.select("#new-graph", "texture");
  await discard;
  await page.waitForFunction(() => window.shadetreeEditor.state.path === null && window.shadetreeEditor.state.doc.nodes.length === 0);
  assert.equal(await page.$eval('select[name="graph kind"]', (field) => field.value), "texture");
  await page.evaluate(() => { window.shadetreeEditor.state.latencies = []; });
  // The empty graph's check answers, above the fields, before they are clicked.
  await page.waitForFunction(() => document.getElementById("diagnostic").textContent.includes('"outputs" must be a non-empty object'),
                             { timeout: 20000 });
  await page.click('input[name="graph name"]', { clickCount: 3 });
  await page.keyboard.type("from_nothing");
  await page.type('textarea[name="graph doc"]', "turbulence, made in the editor");
  // Click an empty spot of the canvas: the first node goes there.
  const host = await (await page.$("#graph-canvas")).boundingBox();
  await page.mouse.click(host.x + 60, host.y + 80);
  await addWithPalette("P");
  await addWithPalette("turbulence");  // right of P, which is selected
  const [placeOfP, placeOfTurbulence] = await page.evaluate(() => ["P1", "turbulence1"].map((id) => [...window.shadetreeEditor.viewOf(id).pos]));
  assert.ok(placeOfTurbulence[0] > placeOfP[0] + 100, `turbulence1 lands right of P1 (${placeOfP}, ${placeOfTurbulence})`);
  await wire("P1", "out", "turbulence1", "p");
  await wire("turbulence1", "out", "#outputs", "color");
  await page.waitForFunction(() => window.shadetreeEditor.state.errors.length === 0 && window.shadetreeEditor.state.previews > 0,
                             { timeout: serverWait });
  const previewsBeforeUnread = await page.evaluate(() => window.shadetreeEditor.state.previews);
  // A node nothing reads, with an input missing: a warning on it, while
  // the preview and the thumbnails go on.
  await page.mouse.click(host.x + 60, host.y + 400);
  await addWithPalette("mul");
  await page.waitForFunction(() => window.shadetreeEditor.state.unreadErrors[0]?.node === "mul1", { timeout: serverWait });
  assert.equal(await page.evaluate(() => window.shadetreeEditor.state.errors.length), 0, "an unread node does not stop the preview");
  // The status follows the preview of what the outputs read.
  await page.waitForFunction(() => !document.getElementById("status").classList.contains("error"), { timeout: serverWait })
    .catch(async () => assert.fail(`the status is no error (${await page.$eval("#status", (element) => element.textContent)})`));
  assert.ok(await page.evaluate(() => window.shadetreeEditor.state.previews) >= previewsBeforeUnread, "the preview stays");
  // The read nodes' thumbnails are drawn; mul1's says why it has none.
  await page.waitForFunction(() => ["P1", "turbulence1", "mul1"].every((id) => window.shadetreeEditor.thumbnails.cache.has(`/${id}`)),
                             { timeout: serverWait });
  const thumbnailsWithUnread = await page.evaluate(() => Object.fromEntries(["P1", "turbulence1", "mul1"].map((id) => {
    const entry = window.shadetreeEditor.thumbnails.cache.get(`/${id}`);
    return [id, entry.image ? "image" : entry.why];
  })));
  assert.deepEqual(thumbnailsWithUnread, { P1: "image", turbulence1: "image", mul1: "missing input (it has no default)" });
  // Delete it with the key.
  const mulTitle = await titlePoint("mul1");
  await page.mouse.click(mulTitle[0], mulTitle[1]);
  await page.keyboard.press("Delete");
  assert.deepEqual((await newDoc()).nodes.map((n) => n.id), ["P1", "turbulence1"], "Delete removed mul1");
  console.log("new texture graph: P1 and turbulence1 added and wired into color; an unread mul1 warned and left the preview alone; Delete removed it");

  // The kind field: a volume gets bounds (and the checker asks for its
  // density), and back to a texture they go again.
  await page.mouse.click(host.x + 20, host.y + host.height - 20);  // no node selected: the graph's fields
  await page.select('select[name="graph kind"]', "volume");
  await page.waitForFunction(() => document.getElementById("diagnostic").textContent.includes("density"), { timeout: 20000 });
  assert.deepEqual((await newDoc()).render?.volume?.bounds, { min: [-1, -1, -1], max: [1, 1, 1] }, "a volume gets bounds");
  await page.select('select[name="graph kind"]', "texture");
  await page.waitForFunction(() => window.shadetreeEditor.state.errors.length === 0, { timeout: 20000 });
  assert.equal((await newDoc()).render, undefined, "a texture keeps no volume");
  // Ctrl+drag draws a box: the nodes in it are selected.
  const [pTitle, turbulenceTitleBefore] = [await titlePoint("P1"), await titlePoint("turbulence1")];
  const boxFrom = [Math.min(pTitle[0], turbulenceTitleBefore[0]) - 40, Math.min(pTitle[1], turbulenceTitleBefore[1]) - 40];
  const boxTo = [Math.max(pTitle[0], turbulenceTitleBefore[0]) + 160, Math.max(pTitle[1], turbulenceTitleBefore[1]) + 120];
  await page.keyboard.down("Control");
  await page.mouse.move(...boxFrom);
  await page.mouse.down();
  await page.mouse.move(...boxTo, { steps: 8 });
  await page.mouse.up();
  await page.keyboard.up("Control");
  assert.deepEqual((await page.evaluate(() => window.shadetreeEditor.graphView.selectedIds())).sort(), ["P1", "turbulence1"],
                   "Ctrl+drag selected the nodes in its box");
  await page.mouse.click(host.x + 20, host.y + host.height - 20);  // and a click on the canvas none
  console.log("kind field: volume added bounds and asked for a density, texture took them away; a Ctrl+drag box selected P1 and turbulence1");

  // Copy and paste with the wires between the copied nodes; a constant
  // typed in the node panel goes along.
  // (A click right after the canvas's deselecting one can land before
  // litegraph has laid the node out again: it is clicked until selected.)
  for (let attempt = 0; !(await page.$('input[name="turbulence1.octaves"]')); ++attempt) {
    assert.ok(attempt < 5, "a click on turbulence1's title selects it");
    const turbulenceTitle = await titlePoint("turbulence1");
    await page.mouse.click(turbulenceTitle[0], turbulenceTitle[1]);
    await page.waitForSelector('input[name="turbulence1.octaves"]', { timeout: 2000 }).catch(() => {});
  }
  await page.click('input[name="turbulence1.octaves"]', { clickCount: 3 });
  await page.keyboard.type("3");
  await page.keyboard.press("Tab");
  await page.mouse.click(host.x + 20, host.y + host.height - 20);  // the canvas takes the focus
  await pressKeys("Control", "a");
  await pressKeys("Control", "c");
  await page.mouse.move(host.x + 300, host.y + 300);
  await pressKeys("Control", "v");
  const pasted = await newDoc();
  assert.deepEqual(pasted.nodes.slice(2), [{ id: "P2", op: "P" }, { id: "turbulence2", op: "turbulence", in: { p: "P2", octaves: 3 } }]);
  console.log("Ctrl+A, Ctrl+C, Ctrl+V: P2 and turbulence2 pasted, wired to each other, octaves 3 kept");
  await pressKeys("Control", "z");
  assert.deepEqual((await newDoc()).nodes.slice(1), [{ id: "turbulence1", op: "turbulence", in: { p: "P1", octaves: 3 } }],
                   "undo takes the paste away, not the octaves typed before");

  // Drag P1 somewhere, save (Ctrl+S asks for a name), check the file, open
  // it again: the places are the ones left.
  const gripP = await titlePoint("P1");
  await page.mouse.move(gripP[0], gripP[1]);
  await page.mouse.down();
  for (let step = 1; step <= 4; ++step) await page.mouse.move(gripP[0] + step * 5, gripP[1] + step * 20);
  await page.mouse.up();
  await settled();
  const placesBefore = await page.evaluate(() => Object.fromEntries(["P1", "turbulence1"].map((id) => [id, [...window.shadetreeEditor.viewOf(id).pos].map(Math.round)])));
  await pressKeys("Control", "s");
  await page.waitForSelector("#save-as-name", { visible: true });
  await page.click("#save-as-name", { clickCount: 3 });
  await page.keyboard.type("from_nothing");
  await page.keyboard.press("Enter");
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "from_nothing.json", { timeout: 20000 });
  const made = spawnSync(binary, ["check", join(folder, "from_nothing.json")], { encoding: "utf8" });
  assert.equal(made.status, 0, made.stderr);
  const madeDoc = JSON.parse(readFileSync(join(folder, "from_nothing.json"), "utf8"));
  assert.equal(madeDoc.name, "from_nothing");
  assert.equal(madeDoc.doc, "turbulence, made in the editor");
  assert.deepEqual(madeDoc.outputs, { color: "turbulence1" });
  assert.deepEqual({ P1: madeDoc.layout.nodes.P1, turbulence1: madeDoc.layout.nodes.turbulence1 }, placesBefore);
  await page.evaluate(() => window.shadetreeEditor.open("marble.json"));
  await page.evaluate(() => window.shadetreeEditor.open("from_nothing.json"));
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "from_nothing.json" && window.shadetreeEditor.viewOf("P1"));
  assert.deepEqual(await page.evaluate(() => Object.fromEntries(["P1", "turbulence1"].map((id) => [id, [...window.shadetreeEditor.viewOf(id).pos].map(Math.round)]))),
                   placesBefore, "the places survive save and reopen");
  console.log(`saved as from_nothing.json: shadetree check accepts it; P1 at ${placesBefore.P1} and turbulence1 at ${placesBefore.turbulence1} when opened again`);

  // `shadetree render` of `file` at width x height against the preview's
  // pixels, both as 8-bit sRGB: the largest difference of a channel.
  const renderedAgainstPreview = async (file, width, height) => {
    const rendered = join(folder, file.replace(/\.json$/, ".png"));
    const render = spawnSync(binary, ["render", join(folder, file), "-o", rendered, "--size", `${width}x${height}`], { encoding: "utf8" });
    assert.equal(render.status, 0, render.stderr);
    const renderedPixels = await page.evaluate(async (png) => {
      const image = new Image();
      image.src = `data:image/png;base64,${png}`;
      await image.decode();
      const canvas = document.createElement("canvas");
      canvas.width = image.width;
      canvas.height = image.height;
      const context = canvas.getContext("2d");
      context.drawImage(image, 0, 0);
      return Array.from(context.getImageData(0, 0, image.width, image.height).data);
    }, readFileSync(rendered).toString("base64"));
    const previewedPixels = await page.evaluate(([w, h]) => Array.from(document.getElementById("preview").getContext("2d").getImageData(0, 0, w, h).data),
                                                [width, height]);
    assert.equal(renderedPixels.length, previewedPixels.length, "the render is the preview's size");
    let largest = 0;
    for (let i = 0; i < renderedPixels.length; ++i) largest = Math.max(largest, Math.abs(renderedPixels[i] - previewedPixels[i]));
    return { largest, previewedPixels };
  };
  // It renders as previewed: `shadetree render` of the saved file at the
  // preview's size against the preview's pixels, both as 8-bit sRGB.
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === 256 &&
                             window.shadetreeEditor.state.path === "from_nothing.json" &&
                             document.getElementById("status").textContent.includes("from_nothing.json: ok"), { timeout: 20000 });
  const { largest: renderLargest, previewedPixels } = await renderedAgainstPreview("from_nothing.json", 256, 256);
  assert.ok(renderLargest <= 1, `from_nothing.json renders as previewed (largest difference ${renderLargest} of 255)`);
  assert.ok(new Set(previewedPixels).size > 32, "the preview shows the turbulence, not a blank");
  console.log(`from_nothing.json: shadetree render draws what the preview showed (largest difference ${renderLargest} of 255; ` +
              `${await page.$eval("#preview-info", (element) => element.textContent)})`);
  // Structural edits (nodes added, wired, deleted, a constant typed) of
  // the graph made from nothing, each drawn by the server after its check
  // and compile: reported against the goal of 100 ms.
  const structural = await page.evaluate(() => window.shadetreeEditor.state.latencies
    .filter((entry) => entry.structural).map((entry) => entry.ms).sort((a, b) => a - b));
  console.log(`latency from the hand, structural edits of from_nothing.json (goal: 100 ms): median ` +
              `${structural[Math.floor(structural.length / 2)]?.toFixed(1)} ms, slowest ${structural.at(-1)?.toFixed(1)} ms over ${structural.length} edits`);

  // The preview takes the export's shape: typed 640 x 360, it is 256x144
  // and shows what `shadetree render --size 256x144` renders.
  for (const [field, value] of [["#export-width", "640"], ["#export-height", "360"]]) {
    await page.click(field, { clickCount: 3 });
    await page.keyboard.type(value);
  }
  await page.waitForFunction(() => {
    const canvas = document.getElementById("preview");
    return canvas.width === 256 && canvas.height === 144 && window.shadetreeEditor.state.drawnSide === 256 &&
           document.getElementById("preview-info").textContent.startsWith("256x144");
  }, { timeout: 20000 });
  const shaped = await renderedAgainstPreview("from_nothing.json", 256, 144);
  assert.ok(shaped.largest <= 1, `a 16:9 preview renders as previewed (largest difference ${shaped.largest} of 255)`);
  // Dragging the splitter 100 px left makes the preview's long side 356,
  // kept for the next page; dragged back, 256 again.
  const splitter = await (await page.$("#panel-splitter")).boundingBox();
  const dragSplitter = async (from, to) => {
    await page.mouse.move(from, splitter.y + 100);
    await page.mouse.down();
    await page.mouse.move(to, splitter.y + 100, { steps: 4 });
    await page.mouse.up();
  };
  const middle = splitter.x + splitter.width / 2;
  await dragSplitter(middle, middle - 100);
  await page.waitForFunction(() => {
    const canvas = document.getElementById("preview");
    return canvas.width === 356 && canvas.height === 200 && window.shadetreeEditor.state.drawnSide === 356;
  }, { timeout: 20000 });
  assert.equal(await page.evaluate(() => localStorage.getItem("shadetree.previewSide")), "356");
  const larger = await renderedAgainstPreview("from_nothing.json", 356, 200);
  assert.ok(larger.largest <= 1, `the larger preview renders as previewed (largest difference ${larger.largest} of 255)`);
  await dragSplitter(middle - 100, middle);
  for (const field of ["#export-width", "#export-height"]) {
    await page.click(field, { clickCount: 3 });
    await page.keyboard.type("512");
  }
  await page.waitForFunction(() => window.shadetreeEditor.state.drawnSide === 256 && document.getElementById("preview").height === 256,
                             { timeout: 20000 });
  console.log("the preview took the export's 16:9 shape (256x144) and a 356 px long side from the splitter, each as rendered");

  // Frame all (F) brings ocean's 127 nodes into the canvas.
  await page.evaluate(() => window.shadetreeEditor.open("roundtrip/ocean.json"));
  await page.waitForFunction(() => window.shadetreeEditor.state.path === "roundtrip/ocean.json");
  await page.mouse.click(host.x + 5, host.y + 5);
  await page.mouse.wheel({ deltaY: -2000 });
  await page.keyboard.press("f");
  const outside = await page.evaluate(() => {
    const { canvas, graph, graphView } = window.shadetreeEditor;
    const [width, height] = graphView.viewSize();
    return graph._nodes.filter((v) => {
      const [x0, y0] = canvas.ds.convertOffsetToCanvas(v.pos);
      const [x1, y1] = canvas.ds.convertOffsetToCanvas([v.pos[0] + v.size[0], v.pos[1] + v.size[1]]);
      return x0 < 0 || y0 < 0 || x1 > width || y1 > height;
    }).length;
  });
  assert.equal(outside, 0, "every node of ocean in sight after F");
  console.log(`ocean.json: F framed all ${await page.evaluate(() => window.shadetreeEditor.graph._nodes.length)} nodes`);
  // The minimap: hidden while every node is in sight, shown once zoomed
  // in; a click on its top left corner brings the view there.
  await drawn();
  assert.equal(await page.$eval("#minimap", (map) => map.hidden), true, "no minimap with the whole graph in sight");
  // Zoomed to 1 on the graph's middle, the view lies inside the graph:
  // the map is the graph's box.
  await page.evaluate(() => {
    const { canvas, graphView } = window.shadetreeEditor;
    const [x0, y0, x1, y1] = graphView.bounds();
    canvas.ds.scale = 1;
    graphView.centreOn([(x0 + x1) / 2, (y0 + y1) / 2]);
  });
  await page.waitForSelector("#minimap:not([hidden])", { timeout: 20000 });
  const map = await page.$eval("#minimap", (element) => { const box = element.getBoundingClientRect(); return [box.left, box.top]; });
  await page.mouse.click(map[0] + 3, map[1] + 3);
  await drawn();
  const centre = await page.evaluate(() => {
    const { canvas, graphView } = window.shadetreeEditor;
    const [width, height] = graphView.viewSize();
    const box = graphView.bounds();
    const [x, y] = canvas.ds.convertCanvasToOffset([width / 2, height / 2]);
    return [x - box[0], y - box[1], box[2] - box[0], box[3] - box[1]];
  });
  // 3 pixels into a map 160 pixels long: within 4 of them.
  const near = Math.max(centre[2], centre[3]) * 4 / 160;
  assert.ok(Math.abs(centre[0]) < near && Math.abs(centre[1]) < near,
            `the view centred near the graph's top left corner: ${centre.map(Math.round)}`);
  console.log(`ocean.json zoomed to 1: the minimap shows, and a click on its corner centred the view ${centre.slice(0, 2).map(Math.round)} from the graph's top left`);

  // Texture previews on the page's own GPU, in a second Chromium whose page
  // is composited on its GPU (ANGLE's SwiftShader): the one above
  // (--disable-gpu) composites in software, though it has WebGL 2 too.
  const gpuBrowser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync",
           `--user-data-dir=${join(folder, ".chromium-gpu")}`],
  });
  try {
    const gpuPage = await gpuBrowser.newPage();
    await gpuPage.setViewport({ width: 1280, height: 760 });
    gpuPage.on("pageerror", (error) => errors.push(String(error)));
    // Requests for the preview: thumbnails (node=) stay on the server.
    const requests = [];
    gpuPage.on("request", (request) => {
      const requested = new URL(request.url());
      if (requested.pathname.startsWith("/api/") && !requested.searchParams.has("node")) requests.push(requested.pathname);
    });
    const info = () => gpuPage.$eval("#preview-info", (element) => element.textContent);
    const pixels = () => gpuPage.evaluate(() => Array.from(document.getElementById("preview").getContext("2d").getImageData(0, 0, 256, 256).data));
    await gpuPage.goto(url);
    // SwiftShader draws on the CPU, slower than the server marches a
    // volume and, on a loaded machine, than the page would wait for: the
    // page is told to wait for its GPU however long it takes, except where
    // the test makes it give up (below).
    await gpuPage.evaluate(async () => {
      await window.shadetreeEditor.ready;
      window.shadetreeEditor.gpu.longestDrawMs = Infinity;
      await window.shadetreeEditor.open("marble.json");
    });
    await gpuPage.waitForFunction(() => /in [0-9.]+ ms \(GPU: WebGL 2\)/.test(document.getElementById("preview-info").textContent), { timeout: 20000 })
      .catch(async (error) => { throw new Error(`no GPU preview of marble.json: ${await info()} (${error})`); });
    await gpuPage.waitForFunction(() => window.shadetreeEditor.thumbnails.pending === 0 && window.shadetreeEditor.graphView.thumbnailsDrawn > 0,
                                  { timeout: 20000 });
    const gpuBefore = await pixels();
    const drawnBefore = await gpuPage.evaluate(() => window.shadetreeEditor.state.previews);
    requests.length = 0;
    await dragSlider("scale", 25, gpuPage);  // further than the drag above, whose value marble.json was saved with
    await gpuPage.waitForFunction((n) => window.shadetreeEditor.state.previews > n, { timeout: serverWait }, drawnBefore);
    // The drag's last value drawn, and the thumbnails asked for after the pause.
    await new Promise((resolve) => setTimeout(resolve, 500));
    await gpuPage.waitForFunction(() => window.shadetreeEditor.thumbnails.pending === 0, { timeout: 20000 });
    const asked = [...requests];
    const drawnByDrag = (await gpuPage.evaluate(() => window.shadetreeEditor.state.previews)) - drawnBefore;
    assert.deepEqual(asked, [], "a param drag drawn on the GPU asks the server nothing");
    assert.notDeepEqual(await pixels(), gpuBefore, "the GPU preview changed with the param");
    assert.match(await info(), /GPU: WebGL 2/);
    const gpuDrag = await timedDrag("scale", gpuPage);
    await gpuPage.waitForFunction(() => window.shadetreeEditor.thumbnails.pending === 0, { timeout: 20000 });
    const gpuAfter = await pixels();
    // The same picture from the server's JIT: the GPU box off.
    await gpuPage.click("#gpu");
    await gpuPage.waitForFunction(() => document.getElementById("preview-info").textContent.includes("CPU"), { timeout: 20000 });
    const cpu = await pixels();
    let largest = 0;
    for (let i = 0; i < cpu.length; ++i) largest = Math.max(largest, Math.abs(cpu[i] - gpuAfter[i]));
    assert.ok(largest <= 1, `GPU and CPU previews of marble within one level of 255 (largest difference ${largest})`);
    console.log(`marble.json on the page's GPU: a slider drag drew ${drawnByDrag} previews with no request to the server; ` +
                `the server's preview differs by at most ${largest} of 255`);
    // The same drag drawn by the server (the GPU box is off).
    const cpuDrag = await timedDrag("scale", gpuPage);
    const figure = (drag) => `median ${drag.median?.toFixed(1)} ms, ${drag.perSecond.toFixed(1)} previews/s`;
    console.log(`latency from the hand, marble's scale dragged (goals: 30 ms, 30/s): on the page's GPU ${figure(gpuDrag)}; ` +
                `from the server ${figure(cpuDrag)}`);
    // A volume marched by the GPU (the GLSL marcher) against the server's
    // full preview (the GPU box is off now): fireball has no shadows, so
    // both march the same samples, but the server's rays end once they let
    // through less than 1/64 and take the rest to be as bright as what they
    // met (the GLSL marcher is the reference one, `--shadows exact`; see
    // extrapolated_termination in render/volume_driver.h). That moves a
    // pixel by at most 1/64 of the fireball's brightest colour, 1.4: 5.6 of 255.
    const previewsBeforeFireball = await gpuPage.evaluate(() => window.shadetreeEditor.state.previews);
    await gpuPage.evaluate(() => window.shadetreeEditor.open("fireball.json"));
    // Its first picture is a draft, then the full one.
    const fullCpuPreview = (before) => {
      const { state } = window.shadetreeEditor;
      const text = document.getElementById("preview-info").textContent;
      return state.previews >= before + 2 && state.drawnSide === 256 && text.includes("CPU") && !text.includes("refining");
    };
    await gpuPage.waitForFunction(fullCpuPreview, { timeout: 60000 }, previewsBeforeFireball)
      .catch(async (error) => { throw new Error(`no full CPU preview of fireball.json: ${await info()} (${error})`); });
    const fireballCpu = await pixels();
    await gpuPage.click("#gpu");
    await gpuPage.waitForFunction(() => /in [0-9.]+ ms \(GPU: WebGL 2\)/.test(document.getElementById("preview-info").textContent), { timeout: 60000 })
      .catch(async (error) => { throw new Error(`no GPU preview of fireball.json: ${await info()} (${error})`); });
    const fireballGpu = await pixels();
    let fireballLargest = 0, fireballSum = 0;
    for (let i = 0; i < fireballCpu.length; ++i) {
      const difference = Math.abs(fireballCpu[i] - fireballGpu[i]);
      fireballLargest = Math.max(fireballLargest, difference);
      fireballSum += difference;
    }
    assert.ok(fireballLargest <= 6, `GPU and CPU previews of fireball within 6 levels of 255 (largest difference ${fireballLargest})`);
    assert.ok(fireballSum / fireballCpu.length <= 1, `GPU and CPU previews of fireball within one level of 255 on average (mean ${fireballSum / fireballCpu.length})`);
    assert.ok(new Set(fireballGpu).size > 64, "the fireball is drawn, not a blank");
    console.log(`fireball.json on the page's GPU: differs from the server's by at most ${fireballLargest} of 255 ` +
                `(mean ${(fireballSum / fireballCpu.length).toFixed(4)}); ${await info()}`);
    // A slow shader is refined from drafts, each shown as it comes (forced
    // here by a budget of 0 ms): the same picture in the end.
    const redrawOnGpu = async () => {
      await gpuPage.click("#gpu");
      await gpuPage.waitForFunction(() => document.getElementById("preview-info").textContent.includes("CPU"), { timeout: 60000 });
      await gpuPage.click("#gpu");
    };
    await gpuPage.evaluate(() => { window.shadetreeEditor.gpu.budgetMs = 0; });
    await redrawOnGpu();
    await gpuPage.waitForFunction(() => /in [0-9.]+ ms \(GPU: WebGL 2\)/.test(document.getElementById("preview-info").textContent), { timeout: 60000 });
    const sides = await gpuPage.evaluate(() => window.shadetreeEditor.gpu.sides);
    assert.deepEqual(sides, [32, 64, 128, 256], "refined from a 32x32 draft");
    assert.deepEqual(await pixels(), fireballGpu, "the refinement ends with the same picture");
    // One the page's GPU would take too long to draw is left to the server
    // (forced here by a longest draw of 0 ms), which says why.
    await gpuPage.evaluate(() => Object.assign(window.shadetreeEditor.gpu, { longestDrawMs: 0 }));
    await redrawOnGpu();
    await gpuPage.waitForFunction(() => document.getElementById("preview-info").textContent.includes("would take about"), { timeout: 60000 })
      .catch(async (error) => { throw new Error(`no server preview of a slow shader: ${await info()} (${error})`); });
    assert.match(await info(), /CPU/);
    console.log(`fireball.json: refined by the page's GPU from drafts of ${sides.join(", ")} to the same pixels; a shader too slow for the GPU ` +
                `is drawn by the server: ${await info()}`);
  } finally {
    await Promise.race([gpuBrowser.close(), new Promise((resolve) => setTimeout(resolve, 3000))]);
    gpuBrowser.process()?.kill("SIGKILL");
  }

  assert.deepEqual(errors, [], "no script errors");
  console.log(`editor test: ${((performance.now() - testStarted) / 1000).toFixed(1)} s`);
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
