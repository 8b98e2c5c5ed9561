// Stage 2: Graph -> CheckedGraph. Resolves ops against the node library and
// the graph's functions, resolves every reference, orders nodes, infers and
// checks types, validates attributes and limits. Every fault becomes one
// Diagnostic naming the file, node and input.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "nodes/distance_grid.h"
#include "nodes/image.h"
#include "nodes/registry.h"

namespace shadetree {

// Where a checked input's value comes from.
struct CheckedSource {
  enum class Kind { node, param, function_input, constant } kind = Kind::constant;
  int index = -1;   // node index (in its body), param index or function input index
  int output = 0;   // output index of a node
  std::vector<float> constant;  // Kind::constant: the literal or default, one value per component
  Type type = Type::float_;     // the type the source provides (before conversion)
};

struct CheckedNode {
  const Node* node = nullptr;
  const OpDef* op = nullptr;  // library op, or null for a function call
  int function = -1;          // index into CheckedGraph::functions for a call
  Type generic_type = Type::float_;        // the op's T, where it has one
  std::vector<CheckedSource> inputs;       // in signature order, all present
  std::vector<Type> input_types;           // the type each input is converted to
  std::vector<Type> output_types;
  // Compile-time attribute data, laid out for the semantics (see lower.cpp).
  std::vector<float> data;
  std::int32_t immediate[2] = {0, 0};
};

struct CheckedOutput {
  std::string name;
  CheckedSource source;
};

// A graph body (the main graph or a function), its nodes in dependency order.
struct CheckedBody {
  std::vector<CheckedNode> nodes;
  std::vector<CheckedOutput> outputs;
};

struct CheckedFunction {
  const FunctionDef* definition = nullptr;
  CheckedBody body;
};

struct CheckedGraph {
  std::shared_ptr<const Graph> graph;
  CheckedBody main;
  std::vector<CheckedFunction> functions;
};

// Functions calling functions: deeper chains are reported, not recursed into.
inline constexpr int max_function_nesting = 64;

// The files a graph's ops name, read for the checker (io/graph_files.h
// reads them with OpenImageIO, Assimp and OpenVDB, below the graph's
// folder): `path` as written in the graph file `graph_file`. A graph that
// names a file and is checked without the reader for it is an error.
using ImageReader = std::function<Result<Image>(const std::string& graph_file, const std::string& path)>;
// A mesh file as a signed distance grid, `resolution` voxels along the
// longest side of its bounding box.
using DistanceGridReader =
    std::function<Result<DistanceGrid>(const std::string& graph_file, const std::string& path, int resolution)>;

struct GraphFiles {
  ImageReader image;
  DistanceGridReader distance_grid;
};

// The checked graph, or the first of its faults.
Result<CheckedGraph> check_graph(std::shared_ptr<const Graph> graph, const GraphFiles& files = {});

// Every fault of the graph (up to max_check_faults), found in one pass: the
// first is the one check_graph reports. A node that reads a faulty node is
// not checked, so a fault is not repeated down the graph; a duplicate id or
// a cycle stops its body's check. Empty when the graph checks.
inline constexpr std::size_t max_check_faults = 100;
std::vector<Diagnostic> check_faults(std::shared_ptr<const Graph> graph, const GraphFiles& files = {});


// Validates a value given for a param (from --set or an editor) against
// its declaration: type, component count and range.
Result<std::vector<float>> parse_param_value(const ParamDecl& param, const std::string& text);
Status check_param_range(const ParamDecl& param, const std::vector<float>& value);

}  // namespace shadetree
