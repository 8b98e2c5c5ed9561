// ShadeIR to standalone C++ (`shadetree emit --cpp`): one header with no
// dependency beyond the standard library, which runs the optimized program
// over structure-of-arrays planes as the JIT kernels do, in SIMD lanes
// where the target has them:
//
//   struct NAME_params   the graph's params, with its defaults and ranges
//   struct NAME_inputs   a plane per component of every varying global the
//                        program reads; the uniform globals it reads
//   struct NAME_outputs  a plane per component of every output (null: skip)
//   void NAME_run(const NAME_params*, const NAME_inputs*, NAME_outputs*,
//                 std::size_t count)
//
// The op semantics are the library's own headers (cppgen/library_source.h),
// so the emitted code computes what the interpreter computes. It is C++17.
#pragma once

#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "ir/shade_ir.h"

namespace shadetree {

// The program's data arrays are emitted as source text: beyond this many
// floats (an image or distance grid of about 1000^2 values) emit refuses,
// naming the node.
inline constexpr std::size_t max_emitted_data = std::size_t{1} << 20;

// `name` prefixes the emitted types and function (made an identifier by
// code_identifier, as every name of the graph that the code holds; its
// node ids, docs and file name appear only in comments, by quoted_text).
// `param_block` holds the params' values (the emitted defaults).
Result<std::string> emit_cpp(const Graph& graph, const ShadeIR& ir, const std::vector<float>& param_block,
                             const std::string& name);

// The part of an emitted header that is the graph's own (everything but the
// op library's source, which every header shares): where its names are.
std::string emitted_program(const std::string& source);

}  // namespace shadetree
