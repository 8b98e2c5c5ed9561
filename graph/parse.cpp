// Stage 1 of the pipeline (see docs/architecture.md): JSON -> Graph.
// Structural errors (a field of the wrong JSON type, an unknown field, a
// malformed reference) are reported here with the node they occur in; type
// and name errors are left to check, which knows the node library.
#include "graph/parse.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "graph/file_path.h"
#include "graph/format_fields.h"
#include "graph/json_document.h"
#include "graph/json_reader.h"
#include "graph/parse_scene.h"
#include "graph/parse_volume.h"

namespace shadetree {
namespace {

class Parser : JsonReader {
 public:
  using JsonReader::JsonReader;

  Graph parse(const json& document) {
    if (!document.is_object()) fail({}, {}, "a graph file must hold a JSON object");
    Graph graph;
    graph.file = file();
    const std::string format = required_string(document, "format", {});
    if (format != "shadetree-graph")
      fail({}, {}, "field \"format\" must be \"shadetree-graph\", got \"" + format + "\"");
    if (!document.contains("version") || !document["version"].is_number_integer() ||
        document["version"].get<double>() < 0 || document["version"].get<double>() > 1e6)
      fail({}, {}, "field \"version\" must be an integer (this shadetree reads version " +
                       std::to_string(graph_format_version) + ")");
    graph.version = document["version"].get<int>();
    if (graph.version < 1 || graph.version > graph_format_version)
      fail({}, {}, "version " + std::to_string(graph.version) + " is not supported (this shadetree reads version " +
                       std::to_string(graph_format_version) + ")");
    graph.name = optional_string(document, "name", {}, stem(file()));
    const std::string kind = required_string(document, "kind", {});
    const std::optional<GraphKind> known_kind = parse_graph_kind(kind);
    if (!known_kind)
      fail({}, {}, "field \"kind\" must be " + kind_set_names(every_kind) + ", got \"" + kind + "\"");
    graph.kind = *known_kind;
    check_format_fields(*this, document, graph_fields(graph.kind), graph.kind, "graph");
    graph.doc = optional_string(document, "doc", {}, {});
    if (document.contains("params")) graph.params = parse_params(document["params"], graph.kind);
    if (document.contains("functions")) graph.functions = parse_functions(document["functions"], graph.kind);
    if (!document.contains("nodes")) fail({}, {}, "missing field \"nodes\"");
    graph.nodes = parse_nodes(document["nodes"], {});
    if (!document.contains("outputs")) fail({}, {}, "missing field \"outputs\"");
    graph.outputs = parse_outputs(document["outputs"], {});
    if (document.contains("render")) graph.render = parse_render(document["render"], graph.kind);
    // What a kind needs to be rendered at all (a volume its bounds) is
    // refused here, so that check refuses what render would.
    for (const auto& [section, field] : render_section_fields)
      if ((graph_kind_def(graph.kind).needed_sections & section) &&
          !(document.contains("render") && document["render"].contains(field)))
        fail({}, {}, a_graph_of(graph.kind) + " needs render." + std::string(field) + " to be rendered");
    return graph;
  }

 private:
  static std::string stem(const std::string& path) {
    std::string name = path.substr(path.find_last_of('/') + 1);
    return name.substr(0, name.rfind('.'));
  }

  Type type_field(const json& value, const std::string& node, const std::string& what) const {
    if (!value.is_string()) fail(node, {}, what + " must be a type name");
    auto type = parse_type_name(value.get<std::string>());
    if (!type)
      fail(node, {}, "unknown type \"" + value.get<std::string>() + "\" (types: float, int, bool, vec2, vec3, color)");
    return *type;
  }

  // A default or literal of a declared type: a number, a boolean or an
  // array of as many numbers as the type has components.
  std::vector<float> typed_value(const json& value, Type type, const std::string& node,
                                 const std::string& what) const {
    if (type == Type::bool_) {
      if (!value.is_boolean()) fail(node, {}, what + " must be true or false");
      return {value.get<bool>() ? 1.0f : 0.0f};
    }
    std::vector<float> result = numbers(value, node, what);
    const std::size_t components = static_cast<std::size_t>(component_count(type));
    if (result.size() == 1 && components > 1) result.assign(components, result[0]);
    if (result.size() != components)
      fail(node, {}, what + " must have " + std::to_string(components) + " components for type " +
                         std::string(type_name(type)));
    if (type == Type::int_ && result[0] != std::floor(result[0])) fail(node, {}, what + " must be an integer");
    return result;
  }

  std::vector<ParamDecl> parse_params(const json& params, GraphKind kind) const {
    if (!params.is_object()) fail({}, {}, "field \"params\" must be an object of name: {type, default, ...}");
    std::vector<ParamDecl> result;
    for (const auto& [name, spec] : params.items()) {
      const std::string where = "param \"" + name + "\"";
      if (!spec.is_object()) fail({}, {}, where + " must be an object with type and default");
      check_format_fields(*this, spec, param_fields(), kind, where);
      ParamDecl param;
      param.name = name;
      if (!spec.contains("type")) fail({}, {}, where + " has no type");
      param.type = type_field(spec["type"], {}, where + " type");
      if (!spec.contains("default")) fail({}, {}, where + " has no default");
      param.default_value = typed_value(spec["default"], param.type, {}, where + " default");
      if (spec.contains("min")) param.min = number(spec["min"], {}, where + " min");
      if (spec.contains("max")) param.max = number(spec["max"], {}, where + " max");
      param.doc = optional_string(spec, "doc", {}, {});
      result.push_back(std::move(param));
    }
    return result;
  }

  std::vector<FunctionDef> parse_functions(const json& functions, GraphKind kind) const {
    if (!functions.is_object()) fail({}, {}, "field \"functions\" must be an object of name: {inputs, nodes, outputs}");
    std::vector<FunctionDef> result;
    for (const auto& [name, spec] : functions.items()) {
      const std::string where = "function \"" + name + "\"";
      if (!spec.is_object()) fail({}, {}, where + " must be an object");
      check_format_fields(*this, spec, function_fields(), kind, where);
      FunctionDef function;
      function.name = name;
      function.doc = optional_string(spec, "doc", {}, {});
      if (spec.contains("inputs")) {
        if (!spec["inputs"].is_object()) fail({}, {}, where + " inputs must be an object of name: type");
        for (const auto& [input_name, input_spec] : spec["inputs"].items()) {
          FunctionInput input;
          input.name = input_name;
          const std::string input_where = where + " input \"" + input_name + "\"";
          if (input_spec.is_object()) {
            check_format_fields(*this, input_spec, function_input_fields(), kind, input_where);
            if (!input_spec.contains("type")) fail({}, {}, input_where + " has no type");
            input.type = type_field(input_spec["type"], {}, input_where);
            if (input_spec.contains("default"))
              input.default_value = typed_value(input_spec["default"], input.type, {}, input_where + " default");
          } else {
            input.type = type_field(input_spec, {}, input_where);
          }
          function.inputs.push_back(std::move(input));
        }
      }
      if (!spec.contains("nodes")) fail({}, {}, where + " has no nodes");
      function.nodes = parse_nodes(spec["nodes"], where + " ");
      if (!spec.contains("outputs")) fail({}, {}, where + " has no outputs");
      function.outputs = parse_outputs(spec["outputs"], where + " ");
      result.push_back(std::move(function));
    }
    return result;
  }

  std::vector<Node> parse_nodes(const json& nodes, const std::string& scope) const {
    if (!nodes.is_array()) fail({}, {}, scope + "field \"nodes\" must be an array");
    if (nodes.size() > max_nodes_per_graph)
      fail({}, {}, scope + "has " + std::to_string(nodes.size()) + " nodes, more than the limit of " +
                       std::to_string(max_nodes_per_graph));
    std::vector<Node> result;
    for (std::size_t index = 0; index < nodes.size(); ++index) {
      const json& spec = nodes[index];
      const std::string position = scope + "node #" + std::to_string(index + 1);
      if (!spec.is_object()) fail({}, {}, position + " must be an object with id and op");
      if (!spec.contains("id") || !spec["id"].is_string() || spec["id"].get<std::string>().empty())
        fail({}, {}, position + " needs a non-empty string \"id\"");
      Node node;
      node.id = spec["id"].get<std::string>();
      if (node.id[0] == '$' || node.id.find('.') != std::string::npos)
        fail(node.id, {}, "ids may not start with '$' or contain '.'");
      node.op = required_string(spec, "op", node.id);
      for (const auto& [key, value] : spec.items()) {
        if (key == "id" || key == "op" || key == "doc") continue;
        if (key == "in") {
          if (!value.is_object()) fail(node.id, {}, "field \"in\" must be an object of input: value");
          for (const auto& [input, input_value] : value.items())
            node.inputs.emplace_back(input, parse_input_value(input_value, node.id, input, "input \"" + input + "\""));
        } else {
          node.attributes[key] = parse_attribute(value, node.id, key);
        }
      }
      result.push_back(std::move(node));
    }
    return result;
  }

  [[noreturn]] void fail_at(const std::string& node, const std::string& input, const std::string& what,
                            const std::string& message) const {
    fail(node, input.empty() ? what : input, message);
  }

  // A node input (`input` names it) or a graph or function output (`input`
  // is empty and `what` names it, e.g. output "color").
  InputValue parse_input_value(const json& value, const std::string& node, const std::string& input,
                               const std::string& what) const {
    InputValue result;
    result.text = value.dump();
    if (value.is_string()) {
      const std::string text = value.get<std::string>();
      result.text = text;
      if (text.empty()) fail_at(node, input, what, "empty reference");
      if (text[0] == '$') {
        result.kind = InputValue::Kind::dollar;
        result.name = text.substr(1);
        if (result.name.empty()) fail_at(node, input, what, "\"$\" must be followed by a param name");
        return result;
      }
      result.kind = InputValue::Kind::node;
      const auto dot = text.find('.');
      result.node = text.substr(0, dot);
      if (dot != std::string::npos) result.output = text.substr(dot + 1);
      if (result.node.empty() || (dot != std::string::npos && result.output.empty()))
        fail_at(node, input, what, "malformed reference \"" + text + "\" (write \"id\" or \"id.output\")");
      return result;
    }
    if (value.is_boolean()) {
      result.kind = InputValue::Kind::boolean;
      result.numbers = {value.get<bool>() ? 1.0f : 0.0f};
      return result;
    }
    if (value.is_number()) {
      result.kind = InputValue::Kind::number;
      result.numbers = {number(value, node, what)};
      result.integral = value.is_number_integer() || result.numbers[0] == std::floor(result.numbers[0]);
      return result;
    }
    if (value.is_array() && (value.size() == 2 || value.size() == 3)) {
      result.kind = InputValue::Kind::array;
      for (const json& item : value) {
        if (!item.is_number()) fail_at(node, input, what, "array literals hold numbers only, got " + value.dump());
        result.numbers.push_back(number(item, node, what));
      }
      return result;
    }
    fail(node, input,
         "expected a node id, \"$param\", number, boolean or array of 2 or 3 numbers, got " + value.dump());
  }

  AttributeValue parse_attribute(const json& value, const std::string& node, const std::string& key) const {
    AttributeValue result;
    const std::string what = "attribute \"" + key + "\"";
    if (value.is_number()) {
      result.kind = AttributeValue::Kind::number;
      result.number = value.get<double>();
      if (!std::isfinite(result.number)) fail(node, {}, what + " must be finite");
      return result;
    }
    if (value.is_string()) {
      result.kind = AttributeValue::Kind::text;
      result.text = value.get<std::string>();
      return result;
    }
    if (value.is_array()) {
      result.kind = AttributeValue::Kind::list;
      for (const json& item : value) {
        if (item.is_array()) {
          result.items_are_arrays = true;
          result.items.push_back(numbers(item, node, what + " item"));
        } else {
          result.items.push_back({number(item, node, what + " item")});
        }
      }
      return result;
    }
    fail(node, {}, what + " must be a number, string or array (or did you mean to put it in \"in\"?)");
  }

  std::vector<OutputDecl> parse_outputs(const json& outputs, const std::string& scope) const {
    if (!outputs.is_object() || outputs.empty())
      fail({}, {}, scope + "field \"outputs\" must be a non-empty object of name: node id");
    std::vector<OutputDecl> result;
    for (const auto& [name, value] : outputs.items())
      result.push_back({name, parse_input_value(value, {}, {}, scope + "output \"" + name + "\"")});
    return result;
  }

  // [first, last]: whole frames, first <= last, a sequence of bounded length.
  std::pair<int, int> frame_range(const json& frames) const {
    const std::string expected = "render frames must be [first, last]: whole frames from 0 to " +
                                 std::to_string(largest_frame) + ", first <= last, at most " +
                                 std::to_string(max_sequence_frames) + " of them";
    if (!frames.is_array() || frames.size() != 2 || !frames[0].is_number_integer() || !frames[1].is_number_integer())
      fail({}, {}, expected);
    // Range-checked as doubles before narrowing, as render size is.
    const double first = frames[0].get<double>(), last = frames[1].get<double>();
    if (first < 0 || last > static_cast<double>(largest_frame) || first > last || last - first >= max_sequence_frames)
      fail({}, {}, expected);
    return {static_cast<int>(first), static_cast<int>(last)};
  }

  RenderSettings parse_render(const json& render, GraphKind kind) const {
    if (!render.is_object()) fail({}, {}, "field \"render\" must be an object");
    check_format_fields(*this, render, render_fields(kind), kind, "render");
    RenderSettings settings;
    if (render.contains("size")) {
      const json& size = render["size"];
      if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer())
        fail({}, {}, "render size must be [width, height] in pixels");
      // Range-check before narrowing, so that 2^32 + 2 is not read as 2.
      const double width = size[0].get<double>(), height = size[1].get<double>();
      if (width < 1 || height < 1 || width > max_image_side || height > max_image_side)
        fail({}, {}, "render size must be between 1 and " + std::to_string(max_image_side) + " pixels a side");
      settings.width = static_cast<int>(width);
      settings.height = static_cast<int>(height);
    }
    if (render.contains("domain")) {
      const json& domain = render["domain"];
      if (!domain.is_object()) fail({}, {}, "render domain must be {\"min\": [x, y], \"max\": [x, y]}");
      check_format_fields(*this, domain, domain_fields(), kind, "render domain");
      for (const char* corner : {"min", "max"}) {
        if (!domain.contains(corner)) fail({}, {}, std::string("render domain has no \"") + corner + "\"");
        std::vector<float> values = numbers(domain[corner], {}, std::string("render domain ") + corner);
        if (values.size() != 2) fail({}, {}, std::string("render domain ") + corner + " must be [x, y]");
        float* target = std::string(corner) == "min" ? settings.domain_min : settings.domain_max;
        target[0] = values[0];
        target[1] = values[1];
      }
      if (settings.domain_min[0] == settings.domain_max[0] || settings.domain_min[1] == settings.domain_max[1])
        fail({}, {}, "render domain is empty: min and max must differ in x and in y");
    }
    if (render.contains("z")) settings.z = number(render["z"], {}, "render z");
    if (render.contains("frame")) settings.frame = number(render["frame"], {}, "render frame");
    if (render.contains("frames")) settings.frames = frame_range(render["frames"]);
    if (render.contains("scene")) {
      settings.scene = parse_scene(*this, render["scene"], kind);
    }
    if (render.contains("volume")) {
      settings.volume = parse_volume(*this, render["volume"]);
    }
    return settings;
  }
};

}  // namespace

Result<Graph> parse_graph(const std::string& json_text, const std::string& file) {
  Result<json> document = parse_json_document(json_text, file);
  if (!document) return document.error();
  try {
    return Parser(file).parse(*document);
  } catch (const ParseError& error) {
    return error.diagnostic;
  } catch (const json::exception& error) {
    return Diagnostic{ExitStatus::invalid_input, file, {}, {}, std::string("malformed graph: ") + error.what()};
  }
}

Result<Graph> load_graph(const std::string& path) {
  if (Status text = check_path_text(path, "graph file"); !text) return text.error();
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    return Diagnostic{ExitStatus::invalid_input, path, {}, {}, "no such file"};
  if (std::filesystem::is_directory(path, error))
    return Diagnostic{ExitStatus::invalid_input, path, {}, {}, "is a directory, not a graph file"};
  std::ifstream stream(path, std::ios::binary);
  if (!stream) return Diagnostic{ExitStatus::failure, path, {}, {}, "cannot open file"};
  // Read at most one byte past the limit, whatever the file claims to be
  // (a device or a sparse file may report any size), in chunks: a buffer
  // of the whole limit, zeroed for each file, cost every load 16 MiB of
  // fresh pages (most of a test process's start under AddressSanitizer).
  constexpr std::size_t chunk = 64 * 1024;
  std::string text;
  while (stream && text.size() <= max_graph_file_bytes) {
    const std::size_t size = text.size();
    text.resize(size + std::min(chunk, max_graph_file_bytes + 1 - size));
    stream.read(text.data() + size, static_cast<std::streamsize>(text.size() - size));
    text.resize(size + static_cast<std::size_t>(stream.gcount()));
  }
  if (stream.bad()) return Diagnostic{ExitStatus::failure, path, {}, {}, "cannot read file"};
  if (text.size() > max_graph_file_bytes)
    return Diagnostic{ExitStatus::invalid_input, path, {}, {}, "file is larger than the 16 MiB limit"};
  return parse_graph(text, path);
}

}  // namespace shadetree
