// ShadeIR to GLSL ES 3.00, the language of WebGL 2 (`shadetree emit
// --glsl`; desktop GL 3.3 and later take it with "#version 330 core" as
// its first line). The optimized program becomes one function,
//
//   void NAME(<each global it reads>, out <each output as out_NAME>)
//
// whose body is every op's own semantics traced into GLSL
// (glslgen/traced_ops.h), so it computes what the interpreter computes, in
// the same operations and order (GPU floats round sqrt, division and
// contracted multiply-adds their own way: docs/glsl.md). The graph's
// params are uniforms (u_ and the param's name; ints and bools as int and
// bool), its noise tables and op data const arrays, its conditional
// regions `if` blocks, its capped loops `for` loops.
//
// A texture graph gets a fragment shader around it, which places each
// pixel in the graph's domain as `shadetree render` does (uniforms
// st_resolution and st_frame) and writes colour and alpha to st_fragment;
// an environment graph one that draws its latitude-longitude panorama;
// with `shadertoy`, a mainImage for Shadertoy, the params as constants.
// Volume and surface graphs get the function alone.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "ir/shade_ir.h"

namespace shadetree {

struct GlslOptions {
  std::string name;        // of the function (an identifier is made of it)
  bool shadertoy = false;  // a mainImage, params as constants
};

// Bounds on what one shader may hold: op data beyond this many floats (an
// image, a distance grid) would be a const array too large for shader
// compilers; programs beyond this many statements take them seconds.
inline constexpr std::size_t max_glsl_data = 16384;
inline constexpr long max_glsl_statements = 100000;

// A param as the shader takes it.
struct GlslUniform {
  std::string param;    // the graph's name for it
  std::string name;     // the uniform's
  std::string type;     // float, vec2, vec3, int or bool
  int slot = 0;         // first float of the param in the param block
  int components = 1;
};

struct GlslShader {
  std::string source;
  std::vector<GlslUniform> uniforms;  // none with shadertoy (constants)
};

// `param_block` holds the params' values (the defaults the shader states).
Result<GlslShader> emit_glsl(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                             const GlslOptions& options);

}  // namespace shadetree
