// A parsed graph file: what the user wrote, not yet checked. Every name and
// reference is kept as text so that the checker can report it.
#pragma once

#include <map>
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "graph/scene.h"
#include "nodes/attributes.h"
#include "nodes/graph_kind.h"
#include "nodes/type.h"

namespace shadetree {

inline constexpr int graph_format_version = 1;

// The value given to a node input: a wire from another node's output, a
// `$name` reference (a param, or inside a function, a function input) or a
// literal.
struct InputValue {
  enum class Kind { node, dollar, number, boolean, array } kind = Kind::number;
  std::string node;    // Kind::node: node id
  std::string output;  // Kind::node: output name, empty for the node's first output
  std::string name;    // Kind::dollar: param or function-input name
  std::vector<float> numbers;  // number (1), array (2 or 3) or boolean (0/1)
  bool integral = false;       // Kind::number: written without a fraction
  std::string text;            // as written, for messages
};

struct Node {
  std::string id;
  std::string op;
  std::vector<std::pair<std::string, InputValue>> inputs;  // in file order
  std::map<std::string, AttributeValue> attributes;
};

struct OutputDecl {
  std::string name;
  InputValue source;
};

struct ParamDecl {
  std::string name;
  Type type = Type::float_;
  std::vector<float> default_value;  // component_count(type) values
  std::optional<float> min, max;     // per component
  std::string doc;
};

// A user-defined node: a subgraph declared once and used like a library op.
struct FunctionInput {
  std::string name;
  Type type = Type::float_;
  std::optional<std::vector<float>> default_value;
};

struct FunctionDef {
  std::string name;
  std::string doc;
  std::vector<FunctionInput> inputs;
  std::vector<Node> nodes;
  std::vector<OutputDecl> outputs;
};

// Optional render settings; the command line overrides them.
struct RenderSettings {
  int width = 512;
  int height = 512;
  float domain_min[2] = {0.0f, 0.0f};  // P.xy at the image's lower-left corner
  float domain_max[2] = {1.0f, 1.0f};  // P.xy at the upper-right corner
  float z = 0.0f;                      // P.z of the image plane
  float frame = 0.0f;
  std::optional<std::pair<int, int>> frames;  // the animation's first and last frame
  std::optional<SceneDesc> scene;      // surface and volume graphs
  std::optional<VolumeDesc> volume;    // volume graphs
};

struct Graph {
  std::string file;  // as given on the command line, for messages
  int version = graph_format_version;
  std::string name;
  GraphKind kind = GraphKind::texture;
  std::string doc;
  std::vector<ParamDecl> params;
  std::vector<FunctionDef> functions;
  std::vector<Node> nodes;
  std::vector<OutputDecl> outputs;
  RenderSettings render;
};

// The output the graph declares as `name`, or null.
inline const OutputDecl* find_output(const Graph& graph, std::string_view name) {
  for (const OutputDecl& output : graph.outputs)
    if (output.name == name) return &output;
  return nullptr;
}


}  // namespace shadetree
