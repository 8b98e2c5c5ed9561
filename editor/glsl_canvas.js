// Draws a fragment shader written by `shadetree emit --glsl` (a texture
// graph's) over a WebGL 2 canvas: one full-screen triangle, the graph's
// params as uniforms, and the pixels readable as floats (RGBA32F, through
// EXT_color_buffer_float) for comparison with the server's render.
const vertexSource = `#version 300 es
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
`;

export class GlslCanvas {
  // null where the browser has no WebGL 2.
  static create(canvas) {
    // Colour beside alpha is straight, as the server's previews are.
    const gl = canvas.getContext("webgl2", { antialias: false, preserveDrawingBuffer: true, premultipliedAlpha: false });
    return gl ? new GlslCanvas(gl) : null;
  }

  constructor(gl) {
    this.gl = gl;
    this.program = null;
    this.floats = gl.getExtension("EXT_color_buffer_float") !== null;
  }

  // Compiles and links `source`; the compiler's log on failure, else "".
  compile(source) {
    const gl = this.gl;
    const stage = (type, text) => {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, text);
      gl.compileShader(shader);
      return shader;
    };
    const vertex = stage(gl.VERTEX_SHADER, vertexSource);
    const fragment = stage(gl.FRAGMENT_SHADER, source);
    const program = gl.createProgram();
    gl.attachShader(program, vertex);
    gl.attachShader(program, fragment);
    gl.linkProgram(program);
    const log = gl.getProgramParameter(program, gl.LINK_STATUS)
      ? ""
      : (gl.getShaderInfoLog(fragment) || "") + (gl.getProgramInfoLog(program) || "");
    gl.deleteShader(vertex);
    gl.deleteShader(fragment);
    if (log) {
      gl.deleteProgram(program);
      return log;
    }
    if (this.program) gl.deleteProgram(this.program);
    this.program = program;
    return "";
  }

  // uniforms: [{name, type, values}] as emit_glsl lists them (type float,
  // vec2, vec3, int or bool; values the param's floats).
  setUniforms(uniforms) {
    const gl = this.gl;
    gl.useProgram(this.program);
    for (const { name, type, values } of uniforms) {
      const where = gl.getUniformLocation(this.program, name);
      if (where === null) continue;  // optimized out
      if (type === "int" || type === "bool") gl.uniform1i(where, Math.trunc(values[0]));
      else gl[`uniform${values.length}fv`](where, values);
    }
  }

  // Draws a width x height image of frame `frame` to the canvas (and waits
  // until the GPU has drawn it), or, with `floats`, to a float target whose
  // pixels it returns (rows from the top, RGBA).
  draw(width, height, frame = 0, { floats = false } = {}) {
    const gl = this.gl;
    gl.useProgram(this.program);
    let target = null, texture = null;
    if (floats) {
      texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, height);
      target = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, target);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
    } else if (gl.canvas.width !== width || gl.canvas.height !== height) {
      gl.canvas.width = width;
      gl.canvas.height = height;
    }
    gl.viewport(0, 0, width, height);
    gl.uniform2f(gl.getUniformLocation(this.program, "st_resolution"), width, height);
    gl.uniform1f(gl.getUniformLocation(this.program, "st_frame"), frame);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    if (!floats) {
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));  // done drawing
      return null;
    }
    const bottomUp = new Float32Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, bottomUp);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(target);
    gl.deleteTexture(texture);
    const pixels = new Float32Array(bottomUp.length);
    const row = width * 4;
    for (let y = 0; y < height; ++y) pixels.set(bottomUp.subarray((height - 1 - y) * row, (height - y) * row), y * row);
    return pixels;
  }
}
