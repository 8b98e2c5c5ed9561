// Renders shaders written by `shadetree emit --glsl` in headless
// Chromium's WebGL 2 (SwiftShader where there is no GPU), through the
// editor's own GlslCanvas, and writes each image as raw little-endian
// float RGBA, rows from the top: the GLSL tests compare them with the
// interpreter (tests/glsl_render_test.cpp).
//   node editor/tests/render_glsl.mjs JOBS.json
// JOBS.json: [{"shader": FILE, "width": W, "height": H, "frame": F,
//              "uniforms": [{"name", "type", "values"}], "output": FILE}]
// Prints one line per job: its output, or the compiler's log.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import puppeteer from "puppeteer-core";

const jobs = JSON.parse(readFileSync(process.argv[2], "utf8"));
const canvasModule = readFileSync(join(dirname(fileURLToPath(import.meta.url)), "..", "glsl_canvas.js"), "utf8");
const profile = mkdtempSync(join(tmpdir(), "shadetree-glsl-chromium-"));
const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         `--user-data-dir=${profile}`],
});
let failed = false;
try {
  const page = await browser.newPage();
  await page.setContent("<canvas></canvas>");
  await page.addScriptTag({ type: "module", content: `${canvasModule}\nwindow.GlslCanvas = GlslCanvas;` });
  await page.waitForFunction(() => window.GlslCanvas !== undefined);
  for (const job of jobs) {
    const result = await page.evaluate((job) => {
      const canvas = window.GlslCanvas.create(document.querySelector("canvas"));
      if (!canvas) return { error: "no WebGL 2" };
      if (!canvas.floats) return { error: "no EXT_color_buffer_float" };
      const log = canvas.compile(job.source);
      if (log) return { error: log };
      canvas.setUniforms(job.uniforms);
      const pixels = canvas.draw(job.width, job.height, job.frame ?? 0, { floats: true });
      return { pixels: Array.from(pixels) };
    }, { ...job, source: readFileSync(job.shader, "utf8") });
    if (result.error) {
      failed = true;
      console.log(`${job.shader}: ${result.error.replaceAll("\n", " ")}`);
      continue;
    }
    writeFileSync(job.output, Buffer.from(new Float32Array(result.pixels).buffer));
    console.log(job.output);
  }
} finally {
  await browser.close();
  rmSync(profile, { recursive: true, force: true });
}
process.exit(failed ? 1 : 0);
