// Previews drawn by the page's own GPU through WebGL 2: the server writes
// the graph and its driver as GLSL once per structure (POST /api/glsl,
// render/glsl_shader.h: a texture's domain, an environment's panorama, a
// volume's ray march, a surface on its scene's analytic objects), and a
// param's new value is a uniform update and a draw, with no request. The
// server's render (the JIT) stays the fallback, for what the server cannot
// write as GLSL and where the browser has no WebGL 2, and the reference:
// the "GPU" box switches between them.
import { api, errorOf } from "./api.js";
import { GlslCanvas } from "./glsl_canvas.js";

// The kinds whose previews the GPU draws (POST /api/glsl).
export const gpuKinds = ["texture", "environment", "volume", "surface"];

// What a graph's shader depends on: the document but its params' values.
export function shaderKey(doc) {
  const params = Object.fromEntries(Object.entries(doc.params || {}).map(([name, { default: _, ...rest }]) => [name, rest]));
  return JSON.stringify({ ...doc, params });
}

// A uniform's values, from its param's default as the document holds it.
function uniformValues(doc, uniform) {
  const value = doc.params?.[uniform.param]?.default;
  const values = Array.isArray(value) ? value : [value];
  return Array.from({ length: uniform.components }, (_, c) => Number(values[Math.min(c, values.length - 1)] ?? 0));
}

export class GpuPreview {
  constructor() {
    this.canvas = GlslCanvas.create(document.createElement("canvas"));
    this.enabled = this.canvas !== null;
    this.key = null;        // of the shader compiled
    this.uniforms = [];
    this.drawMs = new Map(); // side -> what the shader's last draw of that side took
    // A draw that would take longer than this is refined from drafts (32x32,
    // then doubled), each shown as it is drawn, so that a slow shader (a
    // volume's march) never leaves the page long without a new picture.
    this.budgetMs = 100;
    // A draft whose next doubling would take longer than this on the page's
    // GPU leaves the preview to the server (a software GPU, SwiftShader,
    // marches tribble's 256x256 in about 80 s).
    this.longestDrawMs = 1000;
    this.sides = [];        // the sides of the last draw's drafts and picture
    this.refusedKey = null; // of a graph the server or the browser could not make a shader of
    this.error = null;      // and why
  }

  get available() { return this.canvas !== null; }

  // Whether `doc` (the preview's document) is drawn here.
  accepts(doc) {
    return this.enabled && gpuKinds.includes(doc.kind) && shaderKey(doc) !== this.refusedKey;
  }

  // Draws `doc` at long side `side` (dimsOf(side): its [width, height];
  // square unless given), frame `frame`, refined from drafts where
  // it would take longer than the budget: show(canvas) after each draft,
  // the canvas when the picture is drawn, null (this.error says why) for
  // the server to draw instead, or undefined if stale() turned true
  // between drafts (a newer edit).
  async draw(doc, side, frame, pathQuery, { dimsOf = (s) => [s, s], show = () => {}, stale = () => false } = {}) {
    const key = shaderKey(doc);
    const refuse = (error) => {
      this.refusedKey = key;
      this.error = error;
      return null;
    };
    if (key !== this.key) {
      const response = await api("POST", `/api/glsl?${pathQuery}`, JSON.stringify(doc));
      if (!response.ok) return refuse(await errorOf(response));
      const shader = await response.json();
      const log = this.canvas.compile(shader.source);
      if (log) return refuse(`WebGL: ${log}`);
      this.key = key;
      this.uniforms = shader.uniforms;
      this.drawMs.clear();
    }
    this.canvas.setUniforms(this.uniforms.map((uniform) => ({ ...uniform, values: uniformValues(doc, uniform) })));
    if (this.drawMs.size === 0) this.canvas.draw(1, 1, frame);  // the first draw may finish compiling the shader
    // From the largest side known to fit the budget (a new shader: 32).
    let size = Math.min(side, 32);
    for (let larger = side; larger > size; larger /= 2)
      if (this.drawMs.get(larger) <= this.budgetMs) {
        size = larger;
        break;
      }
    this.sides = [];
    for (;;) {
      const started = performance.now();
      this.canvas.draw(...dimsOf(size), frame);
      this.drawMs.set(size, performance.now() - started);
      this.sides.push(size);
      if (size >= side) break;
      const next = Math.min(side, 2 * size);
      const projected = this.drawMs.get(size) * (next / size) ** 2;
      if (projected > this.longestDrawMs)
        return refuse(`the page's GPU would take about ${(projected / 1000).toFixed(1)} s for a ${dimsOf(next).join("x")} draft`);
      show(this.canvas.gl.canvas);
      await new Promise((resolve) => setTimeout(resolve, 0));  // input and painting between drafts
      if (stale()) return undefined;
      size = next;
    }
    this.error = null;
    return this.canvas.gl.canvas;
  }
}
