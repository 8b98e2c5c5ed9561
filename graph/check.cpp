// Stage 2 of the pipeline: Graph -> CheckedGraph (see check.h).
#include "graph/check.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "graph/number_list.h"
#include "nodes/noise_tables.h"
#include "nodes/output_contract.h"

namespace shadetree {
namespace {

struct CheckError {
  Diagnostic diagnostic;
};

// A node that reads a faulty node, or calls a faulty function, is not
// checked: its own fault would only repeat the first one.
struct FollowsFromAFault {};

std::string join_names(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

std::string type_text(Type type) { return std::string(type_name(type)); }

// The signature of whatever a node calls: a library op or a function.
struct Callee {
  const OpDef* op = nullptr;
  int function = -1;
  std::vector<PortSpec> inputs;
  std::vector<PortSpec> outputs;
};

class Checker {
 public:
  Checker(const Graph& graph, const GraphFiles& files) : graph_(graph), files_(files) {}

  // The checked graph, complete only if faults() is empty.
  CheckedGraph run(std::shared_ptr<const Graph> graph) {
    for (std::size_t i = 0; i < graph_.params.size(); ++i)
      collect_faults([&] { check_param_declaration(graph_.params[i]); });
    for (std::size_t i = 0; i < graph_.functions.size(); ++i) {
      const FunctionDef& function = graph_.functions[i];
      if (find_op(function.name))
        collect_faults(
            [&] { fail({}, {}, "function \"" + function.name + "\" has the name of a library op; rename it"); });
      function_index_[function.name] = static_cast<int>(i);
    }
    functions_.resize(graph_.functions.size());
    function_state_.assign(graph_.functions.size(), State::unvisited);
    for (std::size_t i = 0; i < graph_.functions.size(); ++i)
      collect_faults([&] { check_function(static_cast<int>(i)); });

    CheckedGraph result;
    result.graph = std::move(graph);
    result.main = check_body(graph_.nodes, graph_.outputs, nullptr);
    result.functions = std::move(functions_);
    collect_faults([&] { check_outputs(result.main); });
    return result;
  }

  // In the order the checker met them (parameters, functions, then the
  // main graph's nodes in dependency order).
  const std::vector<Diagnostic>& faults() const { return faults_; }

 private:
  enum class State { unvisited, in_progress, done, faulty };

  // Runs `check`, keeping its fault (up to max_check_faults) and going on.
  // Returns whether it passed.
  template <class Check>
  bool collect_faults(Check check) {
    try {
      check();
      return true;
    } catch (const CheckError& error) {
      if (++fault_count_ <= max_check_faults) faults_.push_back(error.diagnostic);
    } catch (const FollowsFromAFault&) {
    }
    return false;
  }

  [[noreturn]] void fail(const std::string& node, const std::string& input, const std::string& message) const {
    throw CheckError{Diagnostic{ExitStatus::invalid_input, graph_.file, node, input, message}};
  }

  void check_param_declaration(const ParamDecl& param) const {
    if (param.min && param.max && *param.min > *param.max)
      fail({}, {}, "param \"" + param.name + "\": min is above max");
    Status range = check_param_range(param, param.default_value);
    if (!range) fail({}, {}, range.error().message);
  }

  void check_function(int index) {
    if (function_state_[index] == State::done) return;
    if (function_state_[index] == State::faulty) throw FollowsFromAFault{};
    const FunctionDef& function = graph_.functions[index];
    if (function_state_[index] == State::in_progress)
      fail({}, {}, "function \"" + function.name + "\" calls itself (directly or through other functions)");
    if (function_depth_ == max_function_nesting)
      fail({}, {}, "function \"" + function.name + "\" is nested more than " + std::to_string(max_function_nesting) +
                       " calls deep");
    ++function_depth_;
    function_state_[index] = State::in_progress;
    functions_[index].definition = &function;
    const std::size_t faults_before = fault_count_;
    functions_[index].body = check_body(function.nodes, function.outputs, &function);
    --function_depth_;
    if (fault_count_ > faults_before) {
      function_state_[index] = State::faulty;
      throw FollowsFromAFault{};
    }
    function_state_[index] = State::done;
  }

  Callee resolve_callee(const Node& node) {
    Callee callee;
    if (const OpDef* op = find_op(node.op)) {
      callee.op = op;
      callee.inputs = op->inputs;
      callee.outputs = op->outputs;
      if (!op->kinds.contains(graph_.kind))
        fail(node.id, {}, "op \"" + op->name + "\" is only available in " + kind_set_names(op->kinds) +
                              " graphs, this is " + a_graph_of(graph_.kind));
      return callee;
    }
    auto found = function_index_.find(node.op);
    if (found == function_index_.end())
      fail(node.id, {}, "unknown op \"" + node.op + "\" (see `shadetree nodes` for the library)");
    check_function(found->second);
    callee.function = found->second;
    const FunctionDef& function = graph_.functions[found->second];
    for (const FunctionInput& input : function.inputs) {
      PortSpec port{input.name, TypeRule::fixed, input.type, std::nullopt, {}};
      callee.inputs.push_back(port);
    }
    const CheckedBody& body = functions_[found->second].body;
    for (const CheckedOutput& output : body.outputs)
      callee.outputs.push_back({output.name, TypeRule::fixed, output.source.type, std::nullopt, {}});
    return callee;
  }

  // Body-local context: node ids, callees, and what `$name` refers to.
  struct Body {
    const std::vector<Node>* nodes;
    const FunctionDef* function;  // null for the main graph
    std::map<std::string, int> index;
    std::vector<Callee> callees;
    std::vector<int> order;          // dependency order of node indices
    std::vector<int> checked_index;  // node index -> position in order
    std::vector<CheckedNode> checked;
    std::vector<bool> faulty;        // node index -> whether it or a node it reads has a fault
  };

  // A body's nodes, each checked on its own: a fault is collected and the
  // body goes on without the nodes that read the faulty one. A duplicate id
  // or a cycle leaves no order to go on in: the body stops there.
  CheckedBody check_body(const std::vector<Node>& nodes, const std::vector<OutputDecl>& outputs,
                         const FunctionDef* function) {
    Body body{&nodes, function, {}, {}, {}, {}, {}, std::vector<bool>(nodes.size(), false)};
    CheckedBody result;
    const bool ordered = collect_faults([&] {
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (!body.index.emplace(nodes[i].id, static_cast<int>(i)).second)
          fail(nodes[i].id, {}, "duplicate node id");
      }
      order_nodes(body);
    });
    if (!ordered) return result;
    body.callees.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      body.faulty[i] = !collect_faults([&] { body.callees[i] = resolve_callee(nodes[i]); });
    body.checked_index.assign(nodes.size(), -1);
    for (int node_index : body.order) {
      body.checked_index[node_index] = static_cast<int>(body.checked.size());
      body.checked.emplace_back();
      if (body.faulty[node_index] || reads_a_faulty_node(body, nodes[node_index].inputs)) {
        body.faulty[node_index] = true;
        continue;
      }
      body.faulty[node_index] = !collect_faults([&] { body.checked.back() = check_node(body, node_index); });
    }
    for (const OutputDecl& output : outputs) {
      if (reads_a_faulty_node(body, {{output.name, output.source}})) continue;
      collect_faults([&] {
        const std::string input = "output \"" + output.name + "\"";
        result.outputs.push_back({output.name, resolve_source(body, output.source, {}, input)});
      });
    }
    result.nodes = std::move(body.checked);
    return result;
  }

  static bool reads_a_faulty_node(const Body& body, const std::vector<std::pair<std::string, InputValue>>& inputs) {
    return std::any_of(inputs.begin(), inputs.end(), [&](const auto& input) {
      if (input.second.kind != InputValue::Kind::node) return false;
      auto found = body.index.find(input.second.node);
      return found != body.index.end() && body.faulty[found->second];
    });
  }

  // Depth-first topological order; a back edge is a cycle, reported with
  // its path. The walk keeps its own stack: a long chain of nodes must not
  // overflow the machine's.
  void order_nodes(Body& body) const {
    const auto& nodes = *body.nodes;
    std::vector<State> state(nodes.size(), State::unvisited);
    struct Frame {
      int node;
      std::size_t next_input;
    };
    std::vector<Frame> path;
    for (std::size_t root = 0; root < nodes.size(); ++root) {
      if (state[root] != State::unvisited) continue;
      state[root] = State::in_progress;
      path.push_back({static_cast<int>(root), 0});
      while (!path.empty()) {
        Frame& frame = path.back();
        const Node& node = nodes[frame.node];
        if (frame.next_input == node.inputs.size()) {
          state[frame.node] = State::done;
          body.order.push_back(frame.node);
          path.pop_back();
          continue;
        }
        const auto& [input, value] = node.inputs[frame.next_input++];
        if (value.kind != InputValue::Kind::node) continue;
        auto found = body.index.find(value.node);
        if (found == body.index.end()) continue;  // check_node reports it
        const int next = found->second;
        if (state[next] == State::done) continue;
        if (state[next] == State::in_progress) {
          std::string cycle;
          auto start = std::find_if(path.begin(), path.end(), [&](const Frame& f) { return f.node == next; });
          for (auto it = start; it != path.end(); ++it) cycle += nodes[it->node].id + " -> ";
          fail(nodes[next].id, {}, "cycle: " + cycle + nodes[next].id);
        }
        state[next] = State::in_progress;
        path.push_back({next, 0});
      }
    }
  }

  // The type and origin of an input value (before conversion).
  CheckedSource resolve_source(const Body& body, const InputValue& value, const std::string& node,
                               const std::string& input) const {
    CheckedSource source;
    switch (value.kind) {
      case InputValue::Kind::node: {
        auto found = body.index.find(value.node);
        if (found == body.index.end())
          fail(node, input, "no node \"" + value.node + "\"" +
                                (body.function ? " in function \"" + body.function->name + "\"" : ""));
        const int checked = body.checked_index[found->second];
        const Callee& callee = body.callees[found->second];
        source.kind = CheckedSource::Kind::node;
        source.index = checked;
        if (!value.output.empty()) {
          source.output = -1;
          std::vector<std::string> names;
          for (std::size_t i = 0; i < callee.outputs.size(); ++i) {
            names.push_back(callee.outputs[i].name);
            if (callee.outputs[i].name == value.output) source.output = static_cast<int>(i);
          }
          if (source.output < 0)
            fail(node, input, "node \"" + value.node + "\" has no output \"" + value.output + "\" (outputs: " +
                                  join_names(names) + ")");
        }
        source.type = body.checked[checked].output_types[source.output];
        return source;
      }
      case InputValue::Kind::dollar: {
        if (body.function) {
          const auto& inputs = body.function->inputs;
          for (std::size_t i = 0; i < inputs.size(); ++i) {
            if (inputs[i].name == value.name) {
              source.kind = CheckedSource::Kind::function_input;
              source.index = static_cast<int>(i);
              source.type = inputs[i].type;
              return source;
            }
          }
          fail(node, input, "function \"" + body.function->name + "\" has no input \"" + value.name +
                                "\" (functions see only their inputs: pass params in as inputs)");
        }
        for (std::size_t i = 0; i < graph_.params.size(); ++i) {
          if (graph_.params[i].name == value.name) {
            source.kind = CheckedSource::Kind::param;
            source.index = static_cast<int>(i);
            source.type = graph_.params[i].type;
            return source;
          }
        }
        fail(node, input, "unknown param \"$" + value.name + "\"");
      }
      case InputValue::Kind::boolean:
        source.constant = value.numbers;
        source.type = Type::bool_;
        return source;
      case InputValue::Kind::number:
        source.constant = value.numbers;
        source.type = value.integral ? Type::int_ : Type::float_;
        return source;
      case InputValue::Kind::array:
        source.constant = value.numbers;
        source.type = value.numbers.size() == 2 ? Type::vec2 : Type::vec3;
        return source;
    }
    fail(node, input, "unreadable value");
  }

  static bool is_literal_triple(const CheckedSource& source) {
    return source.kind == CheckedSource::Kind::constant && source.constant.size() == 3;
  }

  // Whether a source may feed an input of type `target`. Literal triples
  // are both vec3 and color; integral literals are ints or floats.
  static bool accepts(const CheckedSource& source, Type target) {
    if (is_literal_triple(source) && (target == Type::vec3 || target == Type::color)) return true;
    return converts_to(source.type, target);
  }

  CheckedNode check_node(Body& body, int node_index) {
    const Node& node = (*body.nodes)[node_index];
    const Callee& callee = body.callees[node_index];
    CheckedNode checked;
    checked.node = &node;
    checked.op = callee.op;
    checked.function = callee.function;

    if (callee.op) check_attributes(node, *callee.op, checked);
    if (!callee.op && !node.attributes.empty())
      fail(node.id, {}, "unknown field \"" + node.attributes.begin()->first + "\" (inputs of function " + node.op +
                            " go in \"in\")");
    std::vector<std::string> port_names;
    for (const PortSpec& port : callee.inputs) port_names.push_back(port.name);
    std::vector<std::optional<CheckedSource>> given(callee.inputs.size());
    for (const auto& [input, value] : node.inputs) {
      auto port = std::find(port_names.begin(), port_names.end(), input);
      if (port == port_names.end())
        fail(node.id, input, "unknown input (inputs of " + node.op + ": " + join_names(port_names) + ")");
      given[port - port_names.begin()] = resolve_source(body, value, node.id, input);
    }
    for (std::size_t i = 0; i < callee.inputs.size(); ++i) {
      if (given[i]) continue;
      std::optional<std::vector<float>> fallback;
      if (callee.inputs[i].default_value) fallback = std::vector<float>{*callee.inputs[i].default_value};
      if (callee.function >= 0) fallback = graph_.functions[callee.function].inputs[i].default_value;
      if (!fallback) fail(node.id, callee.inputs[i].name, "missing input (it has no default)");
      CheckedSource source;
      source.constant = *fallback;
      source.type = fallback->size() == 1 ? Type::float_ : callee.inputs[i].type;
      if (callee.inputs[i].type == Type::int_ || callee.inputs[i].type == Type::bool_)
        source.type = callee.inputs[i].type;
      given[i] = source;
    }

    if (callee.op && callee.op->generic != GenericSet::none)
      checked.generic_type = infer_generic_type(node, *callee.op, callee.inputs, given, checked.generic_type);
    for (std::size_t i = 0; i < callee.inputs.size(); ++i) {
      const PortSpec& port = callee.inputs[i];
      const Type target = port.rule == TypeRule::generic ? checked.generic_type : port.type;
      const CheckedSource& source = *given[i];
      if (!accepts(source, target)) {
        std::string found = source.kind == CheckedSource::Kind::constant && source.type == Type::float_
                                 ? "non-integral number " + text_of(source.constant[0])
                                 : type_text(source.type);
        fail(node.id, port.name, "expected " + type_text(target) + ", got " + found);
      }
      checked.input_types.push_back(target);
      checked.inputs.push_back(source);
    }
    for (const PortSpec& port : callee.outputs)
      checked.output_types.push_back(port.rule == TypeRule::generic ? checked.generic_type : port.type);
    if (callee.op) check_limits(node, *callee.op, checked);
    return checked;
  }

  static std::string text_of(float value) {
    std::ostringstream text;
    text << value;
    return text.str();
  }

  Type infer_generic_type(const Node& node, const OpDef& op, const std::vector<PortSpec>& ports,
                          const std::vector<std::optional<CheckedSource>>& given, Type from_knots) const {
    std::optional<Type> vector_type;
    std::string vector_port;
    std::optional<Type> literal_vector_type;
    if (op.type_from_knots) {
      vector_type = from_knots;
      vector_port = "knots";
    }
    for (std::size_t i = 0; i < ports.size(); ++i) {
      if (ports[i].rule != TypeRule::generic) continue;
      const CheckedSource& source = *given[i];
      if (source.type == Type::bool_)
        fail(node.id, ports[i].name, "expected a number or vector, got bool (use select to turn it into numbers)");
      if (!is_vector(source.type)) continue;
      if (source.kind == CheckedSource::Kind::constant) {
        if (!literal_vector_type) literal_vector_type = source.type;
        continue;
      }
      if (vector_type && *vector_type != source.type && !op.type_from_knots)
        fail(node.id, ports[i].name,
             "expected " + type_text(*vector_type) + " (like input \"" + vector_port + "\"), got " +
                 type_text(source.type));
      if (!vector_type) {
        vector_type = source.type;
        vector_port = ports[i].name;
      }
    }
    Type result = vector_type ? *vector_type : literal_vector_type ? *literal_vector_type : Type::float_;
    if (op.generic == GenericSet::vectors && !is_vector(result)) {
      std::string first = ports.empty() ? std::string() : ports[0].name;
      fail(node.id, first, "expected a vector (vec2, vec3 or color), got " + type_text(result));
    }
    return result;
  }

  // A node's attributes, read by its op's layout (nodes/attributes.h);
  // faults are reported on the node.
  class NodeAttributes final : public Attributes {
   public:
    NodeAttributes(const Checker& checker, const Node& node) : checker_(checker), node_(node) {}
    const AttributeValue* find(const std::string& name) const override {
      auto found = node_.attributes.find(name);
      return found == node_.attributes.end() ? nullptr : &found->second;
    }
    [[noreturn]] void fail(const std::string& message) const override { checker_.fail(node_.id, {}, message); }
    const Image& image_file(const std::string& name) const override {
      const AttributeValue* value = find(name);
      if (!value || value->kind != AttributeValue::Kind::text || value->text.empty())
        fail("attribute \"" + name + "\" must be the path of an image file");
      if (!checker_.files_.image) fail("image files cannot be read here (attribute \"" + name + "\")");
      Result<Image> read = checker_.files_.image(checker_.graph_.file, value->text);
      if (!read) failed_to_read(read.error());
      if (read->width < 1 || read->height < 1 || read->channels < 1 ||
          read->pixels.size() != static_cast<std::size_t>(read->width) * read->height * read->channels)
        fail("image \"" + value->text + "\" has no pixels");
      if (static_cast<long long>(read->width) * read->height > max_image_pixels)
        fail("image \"" + value->text + "\" is " + std::to_string(read->width) + "x" + std::to_string(read->height) +
             "; images of up to " + std::to_string(max_image_pixels) + " pixels (1024x1024) can be sampled");
      image_ = std::move(*read);
      return image_;
    }
    const DistanceGrid& mesh_distance_grid(const std::string& name, int resolution) const override {
      const AttributeValue* value = find(name);
      if (!value || value->kind != AttributeValue::Kind::text || value->text.empty())
        fail("attribute \"" + name + "\" must be the path of a mesh file (.obj, .ply)");
      if (!checker_.files_.distance_grid) fail("mesh files cannot be read here (attribute \"" + name + "\")");
      Result<DistanceGrid> read = checker_.files_.distance_grid(checker_.graph_.file, value->text, resolution);
      if (!read) failed_to_read(read.error());
      grid_ = std::move(*read);
      return grid_;
    }

   private:
    // A file that could not be read is reported on the node, with the
    // reader's status.
    [[noreturn]] void failed_to_read(Diagnostic error) const {
      error.file = checker_.graph_.file;
      error.node = node_.id;
      throw CheckError{std::move(error)};
    }
    const Checker& checker_;
    const Node& node_;
    mutable Image image_;
    mutable DistanceGrid grid_;
  };

  // Validates attribute names and required attributes, then lays out their
  // data for the semantics: see CheckedNode::data and immediate.
  void check_attributes(const Node& node, const OpDef& op, CheckedNode& checked) const {
    std::vector<std::string> names;
    for (const AttributeSpec& spec : op.attributes) names.push_back(spec.name);
    for (const auto& [name, value] : node.attributes) {
      if (std::find(names.begin(), names.end(), name) == names.end())
        fail(node.id, {}, "unknown field \"" + name + "\" (inputs go in \"in\"; attributes of " + op.name + ": " +
                              join_names(names) + ")");
    }
    for (const AttributeSpec& spec : op.attributes)
      if (spec.required && !node.attributes.contains(spec.name))
        fail(node.id, {}, "missing attribute \"" + spec.name + "\" (" + spec.doc + ")");
    AttributeLayout layout = lay_out_attributes(op, NodeAttributes(*this, node));
    checked.data = std::move(layout.data);
    checked.immediate[0] = layout.immediate[0];
    checked.immediate[1] = layout.immediate[1];
    if (layout.generic) checked.generic_type = *layout.generic;
  }

  // Octave and iteration counts given as literals or params must respect
  // the documented limits (the loops stop there regardless).
  void check_limits(const Node& node, const OpDef& op, const CheckedNode& checked) const {
    for (std::size_t i = 0; i < op.inputs.size(); ++i) {
      const std::string& name = op.inputs[i].name;
      int limit = 0;
      if (name == "octaves") limit = max_octaves;
      if (name == "iterations") limit = max_julia_iterations;
      if (limit == 0) continue;
      const CheckedSource& source = checked.inputs[i];
      std::vector<float> values;
      if (source.kind == CheckedSource::Kind::constant) values = source.constant;
      if (source.kind == CheckedSource::Kind::param) {
        const ParamDecl& param = graph_.params[source.index];
        values = param.default_value;
        if (param.max) values.push_back(*param.max);
      }
      for (float value : values)
        if (value < 0 || value > limit)
          fail(node.id, name, name + " must be between 0 and " + std::to_string(limit) + ", got " + text_of(value));
    }
  }

  // The main body's outputs against the kind's contract: known names,
  // convertible types, required ones present.
  void check_outputs(const CheckedBody& body) const {
    const std::string kind(graph_kind_name(graph_.kind));
    std::string names;
    for (const OutputSpec& spec : output_contract(graph_.kind))
      names += (names.empty() ? "" : ", ") + std::string(spec.name);
    for (const CheckedOutput& output : body.outputs) {
      const OutputSpec* spec = find_output_spec(graph_.kind, output.name);
      if (!spec) fail({}, {}, "\"" + output.name + "\" is not an output of " + kind + " graphs (" + names + ")");
      // At an output, a vec3 is taken for a color and a color for a vec3.
      const bool three_components = spec->type == Type::color || spec->type == Type::vec3;
      if (!accepts(output.source, spec->type) &&
          !(three_components && component_count(output.source.type) == 3))
        fail({}, {}, "output \"" + output.name + "\": expected " + type_text(spec->type) + ", got " +
                         type_text(output.source.type));
    }
    for (const OutputSpec& spec : output_contract(graph_.kind)) {
      const bool present = std::any_of(graph_.outputs.begin(), graph_.outputs.end(),
                                       [&](const OutputDecl& output) { return output.name == spec.name; });
      if (spec.required && !present)
        fail({}, {}, a_graph_of(graph_.kind) + " needs an output \"" + std::string(spec.name) + "\"");
    }
  }


  const Graph& graph_;
  const GraphFiles& files_;
  std::map<std::string, int> function_index_;
  std::vector<CheckedFunction> functions_;
  std::vector<State> function_state_;
  int function_depth_ = 0;
  std::vector<Diagnostic> faults_;
  std::size_t fault_count_ = 0;  // faults_ and those beyond max_check_faults
};

}  // namespace


Result<CheckedGraph> check_graph(std::shared_ptr<const Graph> graph, const GraphFiles& files) {
  Checker checker(*graph, files);
  CheckedGraph checked = checker.run(graph);
  if (!checker.faults().empty()) return checker.faults().front();
  return checked;
}

std::vector<Diagnostic> check_faults(std::shared_ptr<const Graph> graph, const GraphFiles& files) {
  Checker checker(*graph, files);
  checker.run(graph);
  return checker.faults();
}

Result<std::vector<float>> parse_param_value(const ParamDecl& param, const std::string& text) {
  auto bad = [&](const std::string& why) {
    return invalid_input("param \"" + param.name + "\": " + why + ", got \"" + text + "\"");
  };
  if (param.type == Type::bool_) {
    if (text == "true" || text == "1") return std::vector<float>{1.0f};
    if (text == "false" || text == "0") return std::vector<float>{0.0f};
    return bad("expected true or false");
  }
  std::optional<std::vector<float>> parsed = parse_number_list(text);
  if (!parsed) return bad("expected " + std::to_string(component_count(param.type)) + " comma-separated number(s)");
  std::vector<float> values = std::move(*parsed);
  const std::size_t components = static_cast<std::size_t>(component_count(param.type));
  if (values.size() == 1 && components > 1) values.assign(components, values[0]);
  if (values.size() != components)
    return bad("expected " + std::to_string(components) + " comma-separated numbers for " +
               std::string(type_name(param.type)));
  if (param.type == Type::int_ && values[0] != std::floor(values[0])) return bad("expected an integer");
  Status range = check_param_range(param, values);
  if (!range) return range.error();
  return values;
}

Status check_param_range(const ParamDecl& param, const std::vector<float>& value) {
  for (float component : value) {
    std::ostringstream text;
    text << component;
    if (param.min && component < *param.min) {
      std::ostringstream limit;
      limit << *param.min;
      return invalid_input("param \"" + param.name + "\": " + text.str() + " is below the minimum " + limit.str());
    }
    if (param.max && component > *param.max) {
      std::ostringstream limit;
      limit << *param.max;
      return invalid_input("param \"" + param.name + "\": " + text.str() + " is above the maximum " + limit.str());
    }
  }
  return success();
}

}  // namespace shadetree
