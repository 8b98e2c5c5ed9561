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
    this.refusedKey = null; // of a graph the server or the browser could not make a shader of
    this.error = null;      // and why
  }

  get available() { return this.canvas !== null; }

  // Whether `doc` (the preview's document) is drawn here.
  accepts(doc) {
    return this.enabled && gpuKinds.includes(doc.kind) && shaderKey(doc) !== this.refusedKey;
  }

  // Draws `doc` at side x side, frame `frame`: the canvas drawn, or null
  // (this.error says why) for the server to draw instead.
  async draw(doc, side, frame, pathQuery) {
    const key = shaderKey(doc);
    if (key !== this.key) {
      const refuse = (error) => {
        this.refusedKey = key;
        this.error = error;
        return null;
      };
      const response = await api("POST", `/api/glsl?${pathQuery}`, JSON.stringify(doc));
      if (!response.ok) return refuse(await errorOf(response));
      const shader = await response.json();
      const log = this.canvas.compile(shader.source);
      if (log) return refuse(`WebGL: ${log}`);
      this.key = key;
      this.uniforms = shader.uniforms;
    }
    this.canvas.setUniforms(this.uniforms.map((uniform) => ({ ...uniform, values: uniformValues(doc, uniform) })));
    this.canvas.draw(side, side, frame);
    this.error = null;
    return this.canvas.gl.canvas;
  }
}
