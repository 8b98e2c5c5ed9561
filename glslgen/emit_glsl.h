// ShadeIR to GLSL ES 3.00, the language of WebGL 2 (`shadetree emit
// --glsl`). The optimized program becomes one function,
//
//   void NAME(<each global it reads>, out <each output as out_NAME>)
//
// whose body is every op's own semantics traced into GLSL
// (glslgen/traced_ops.h), so it computes what the interpreter computes, in
// the same operations and order (GPU floats round sqrt, division and
// contracted multiply-adds their own way: docs/glsl.md). The graph's
// params are uniforms (u_ and the param's name; ints and bools as int and
// bool), or constants at their defaults for Shadertoy, its noise tables
// and op data const arrays, its conditional regions `if` blocks, its
// capped loops `for` loops.
//
// The shader around the function, which places the samples as the
// graph's driver does, is the kinds table's (render/glsl_shader.h).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "ir/shade_ir.h"
#include "nodes/globals.h"
#include "nodes/output_contract.h"

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

// The graph's function and what it needs: its params and tables.
struct GlslFunction {
  std::string name;
  std::string declarations;  // the params, the const arrays and the function
  std::vector<GlobalId> reads;  // its first parameters, in order
  struct Output {
    OutputId id;
    int components;
  };
  std::vector<Output> outputs;  // its out parameters (out_NAME), in order
  std::vector<GlslUniform> uniforms;  // none with shadertoy (constants)

  // "vec3 out_color;\n..." : a variable for each output.
  std::string output_declarations(const std::string& indent) const;
  // "NAME(<argument(global) for each global read>, out_...);"
  std::string call(const std::function<std::string(GlobalId)>& argument) const;
  bool writes(OutputId id) const;
};

// "out_color": the variable and out parameter of an output.
std::string glsl_output_name(OutputId id);
// float, vec2 or vec3.
std::string glsl_vector_type(int components);

// `param_block` holds the params' values (the defaults the shader states).
Result<GlslFunction> emit_glsl_function(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                                        const GlslOptions& options);

}  // namespace shadetree
