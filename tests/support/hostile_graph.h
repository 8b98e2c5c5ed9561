// A graph whose every name would be live code, break a generated file or
// collide if an emitter pasted it verbatim: for the tests of emit --cpp
// and emit --glsl.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadetree::testing {

// Names a graph supplies that would be live code, break the header or
// collide if pasted verbatim (issue 21: a newline in a node id ran the rest
// of it in the user's program; a doc ending in a backslash spliced the next
// line into its comment; __LINE__ and quotes broke the header).
inline const std::vector<std::string>& hostile_names() {
  static const std::vector<std::string> names = {
      "x\nstatic_assert(false, \"node id\");", "x\r\n#error injected", "*/ static_assert(false); /*",
      "ends in a backslash\\", "\\\nstatic_assert(false);", "\"quoted\"", "__LINE__", "__FILE__", "NULL", "M_PI",
      "float", "main", "2d", "_Reserved", "a-b", "a_b", "a b", "caf\xc3\xa9 \xe2\x82\xac", "?\?/", "x?\?/",
      "#include <no_such_header>", "x\x01y\x7f", std::string(5000, 'z'), "params", "inputs", "u", "block", "F",
      "i", "count", "data"};
  return names;
}

// A texture graph whose node ids, param names and docs are the hostile
// names: a chain of adds of each name's param (all different defaults, so
// a field mixed up with another changes the result), a conditional region
// under a hostile id, a file name with a line break.
inline std::string hostile_graph() {
  nlohmann::ordered_json params = nlohmann::ordered_json::object(), nodes = nlohmann::ordered_json::array();
  nodes.push_back({{"id", "p"}, {"op", "P"}});
  nodes.push_back({{"id", "c"}, {"op", "split"}, {"in", {{"v", "p"}}}});
  std::string previous = "c.x";
  float value = 0.125f;
  for (const std::string& name : hostile_names()) {
    params[name] = {{"type", "float"}, {"default", value}, {"doc", name}};
    value *= 1.5f;
    nodes.push_back({{"id", name}, {"op", "add"}, {"in", {{"a", previous}, {"b", "$" + name}}}});
    previous = name;
  }
  nodes.push_back({{"id", "*/ cond \\"}, {"op", "lt"}, {"in", {{"a", "c.y"}, {"b", 0.5}}}});
  nodes.push_back({{"id", "\nsin\\"}, {"op", "sin"}, {"in", {{"x", previous}}}});
  nodes.push_back({{"id", "if\n#error x"}, {"op", "if"}, {"in", {{"cond", "*/ cond \\"}, {"then", "\nsin\\"}, {"else", previous}}}});
  nodes.push_back({{"id", "rgb"}, {"op", "color"}, {"in", {{"r", "if\n#error x"}, {"g", previous}, {"b", 0.5}}}});
  return nlohmann::ordered_json{{"format", "shadetree-graph"}, {"version", 1}, {"name", "n\n#error name"},
                                {"kind", "texture"}, {"doc", "doc\\"}, {"params", params}, {"nodes", nodes},
                                {"outputs", {{"color", "rgb"}}}}
      .dump();
}

// A file name with a line break and a directive after it.
inline const std::string hostile_file_name = "dir/evil\n#error file.json";

}  // namespace shadetree::testing
