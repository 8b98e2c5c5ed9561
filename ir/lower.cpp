// Stage 3 of the pipeline: CheckedGraph -> ShadeIR (see lower.h).
#include "ir/lower.h"

#include <map>

#include "ir/differentiate.h"
#include "nodes/ops/generators.h"

namespace shadetree {
namespace {

class Lowering {
 public:
  explicit Lowering(const CheckedGraph& graph) : graph_(graph), differentiator_(ir_) {}

  Result<ShadeIR> run() {
    const Graph& source = *graph_.graph;
    for (const ParamDecl& param : source.params) {
      ir_.params.push_back({param.name, param.type, ir_.param_block_size});
      ir_.param_block_size += component_count(param.type);
    }
    param_values_.assign(source.params.size(), -1);
    auto outputs = lower_body(graph_.main, {});
    if (ir_.code.size() > max_program_instructions)
      return Diagnostic{ExitStatus::invalid_input, graph_.graph->file, {}, {},
                        "the graph expands to more than " + std::to_string(max_program_instructions) +
                            " instructions once its functions are inlined"};
    ir_.kind = source.kind;
    for (const OutputSpec& spec : output_contract(source.kind))
      for (std::size_t i = 0; i < graph_.main.outputs.size(); ++i)
        if (graph_.main.outputs[i].name == spec.name) ir_.outputs.push_back({spec.id, spec.type, outputs[i].first});
    return std::move(ir_);
  }

 private:
  using TypedValue = std::pair<std::int32_t, Type>;

  std::int32_t append(IrInstr instr) {
    ir_.code.push_back(std::move(instr));
    return static_cast<std::int32_t>(ir_.code.size() - 1);
  }

  std::int32_t constant(const std::vector<float>& values, Type type, const std::string& source) {
    IrInstr instr;
    instr.kind = IrOpKind::constant;
    instr.type = values.size() == 1 ? (type == Type::int_ || type == Type::bool_ ? type : Type::float_) : type;
    instr.uniform = true;
    instr.data_offset = static_cast<std::int32_t>(ir_.data.size());
    instr.data_count = static_cast<std::int32_t>(values.size());
    ir_.data.insert(ir_.data.end(), values.begin(), values.end());
    instr.source = source;
    return append(std::move(instr));
  }

  std::int32_t param(int index) {
    if (param_values_[index] >= 0) return param_values_[index];
    IrInstr instr;
    instr.kind = IrOpKind::param;
    instr.type = ir_.params[index].type;
    instr.uniform = true;
    instr.immediate[0] = ir_.params[index].slot;
    instr.source = "$" + ir_.params[index].name;
    return param_values_[index] = append(std::move(instr));
  }

  // Lowers one body; returns the value and type of each of its outputs.
  std::vector<TypedValue> lower_body(const CheckedBody& body, const std::vector<TypedValue>& arguments) {
    std::vector<std::vector<TypedValue>> node_outputs(body.nodes.size());
    auto value_of = [&](const CheckedSource& source, Type target, const std::string& where) -> TypedValue {
      switch (source.kind) {
        case CheckedSource::Kind::node: return node_outputs[source.index][source.output];
        case CheckedSource::Kind::param: return {param(source.index), source.type};
        case CheckedSource::Kind::function_input: return arguments[source.index];
        case CheckedSource::Kind::constant: return {constant(source.constant, target, where), target};
      }
      return {-1, target};
    };
    for (std::size_t n = 0; n < body.nodes.size(); ++n) {
      if (ir_.code.size() > max_program_instructions) return std::vector<TypedValue>(body.outputs.size(), {0, Type::float_});
      const CheckedNode& node = body.nodes[n];
      std::vector<TypedValue> inputs;
      for (std::size_t i = 0; i < node.inputs.size(); ++i)
        inputs.push_back(value_of(node.inputs[i], node.input_types[i], node.node->id));
      if (node.function >= 0) {
        node_outputs[n] = lower_body(graph_.functions[node.function].body, inputs);
        continue;
      }
      node_outputs[n] = lower_op(node, inputs);
    }
    std::vector<TypedValue> outputs;
    for (const CheckedOutput& output : body.outputs)
      outputs.push_back(value_of(output.source, output.source.type, "output " + output.name));
    return outputs;
  }

  std::vector<TypedValue> lower_op(const CheckedNode& node, const std::vector<TypedValue>& inputs) {
    const OpId op = node.op->id;
    if (op == OpId::split) {
      std::vector<TypedValue> components;
      const int available = component_count(inputs[0].second);
      for (int c = 0; c < 3; ++c) {
        if (c >= available) {
          components.push_back({constant({0.0f}, Type::float_, node.node->id), Type::float_});
          continue;
        }
        IrInstr instr;
        instr.kind = IrOpKind::extract;
        instr.type = Type::float_;
        instr.arg_count = 1;
        instr.args[0] = inputs[0].first;
        instr.uniform = ir_.code[inputs[0].first].uniform;
        instr.immediate[0] = c;
        instr.source = node.node->id;
        components.push_back({append(std::move(instr)), Type::float_});
      }
      return components;
    }
    if (op == OpId::gradient) return {{differentiator_.gradient(inputs[0].first, node.node->id), Type::vec3}};
    if (op == OpId::bump) return {{lower_bump(inputs, node.node->id), Type::vec3}};
    if (op == OpId::vnoise) return {{lower_vnoise(node, inputs[0].first), Type::vec3}};
    IrInstr instr;
    instr.op = op;
    instr.type = node.output_types[0];
    instr.source = node.node->id;
    if (const std::optional<GlobalId> global = global_of(op)) {
      instr.kind = IrOpKind::global;
      instr.immediate[0] = static_cast<std::int32_t>(*global);
      instr.uniform = global_def(*global).variability == Variability::uniform;
      return {{append(std::move(instr)), node.output_types[0]}};
    }
    instr.kind = IrOpKind::op;
    instr.generic = node.generic_type;
    instr.arg_count = static_cast<std::uint8_t>(inputs.size());
    bool uniform = true;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      instr.args[i] = inputs[i].first;
      uniform = uniform && ir_.code[inputs[i].first].uniform;
    }
    instr.uniform = uniform;
    instr.data_offset = static_cast<std::int32_t>(ir_.data.size());
    instr.data_count = static_cast<std::int32_t>(node.data.size());
    ir_.data.insert(ir_.data.end(), node.data.begin(), node.data.end());
    instr.immediate = {node.immediate[0], node.immediate[1]};
    return {{append(std::move(instr)), node.output_types[0]}};
  }

  // An op instruction of the library, as lowering a node would make it.
  std::int32_t op_instruction(OpId op, Type generic, Type type, std::initializer_list<std::int32_t> args,
                              const std::string& source) {
    IrInstr instr;
    instr.op = op;
    instr.generic = generic;
    instr.type = type;
    instr.source = source;
    instr.uniform = true;
    for (std::int32_t arg : args) {
      instr.args[instr.arg_count++] = arg;
      instr.uniform = instr.uniform && ir_.code[arg].uniform;
    }
    return append(std::move(instr));
  }

  // bump (nodes/ops/derivatives.h): normalize(n - strength (g - (g . n) n))
  // with g the gradient of the height and n the normal, made unit.
  std::int32_t lower_bump(const std::vector<TypedValue>& inputs, const std::string& source) {
    const std::int32_t g = differentiator_.gradient(inputs[0].first, source);
    const std::int32_t n = op_instruction(OpId::normalize, Type::vec3, Type::vec3, {inputs[1].first}, source);
    const std::int32_t along_n = op_instruction(OpId::dot, Type::vec3, Type::float_, {g, n}, source);
    const std::int32_t normal_part = op_instruction(OpId::mul, Type::vec3, Type::vec3, {n, along_n}, source);
    const std::int32_t tangential = op_instruction(OpId::sub, Type::vec3, Type::vec3, {g, normal_part}, source);
    const std::int32_t tilt = op_instruction(OpId::mul, Type::vec3, Type::vec3, {tangential, inputs[2].first}, source);
    const std::int32_t bent = op_instruction(OpId::sub, Type::vec3, Type::vec3, {n, tilt}, source);
    return op_instruction(OpId::normalize, Type::vec3, Type::vec3, {bent}, source);
  }

  // vnoise (nodes/ops/generators.h): vec3(noise(p - sigma), noise(p),
  // noise(p + sigma)), each noise of the node's seed.
  std::int32_t lower_vnoise(const CheckedNode& node, std::int32_t p) {
    const std::string& source = node.node->id;
    const float* sigma = ops::vnoise::offset;
    const std::int32_t offset = constant({sigma[0], sigma[1], sigma[2]}, Type::vec3, source);
    const auto noise_at = [&](std::int32_t at) {
      const std::int32_t noise = op_instruction(OpId::noise, Type::float_, Type::float_, {at}, source);
      ir_.code[noise].immediate = {node.immediate[0], node.immediate[1]};
      return noise;
    };
    const std::int32_t below = noise_at(op_instruction(OpId::sub, Type::vec3, Type::vec3, {p, offset}, source));
    const std::int32_t at_p = noise_at(p);
    const std::int32_t above = noise_at(op_instruction(OpId::add, Type::vec3, Type::vec3, {p, offset}, source));
    return op_instruction(OpId::vec3, Type::float_, Type::vec3, {below, at_p, above}, source);
  }

  const CheckedGraph& graph_;
  ShadeIR ir_;
  Differentiator differentiator_;
  std::vector<std::int32_t> param_values_;
};

}  // namespace

Result<ShadeIR> lower(const CheckedGraph& graph) { return Lowering(graph).run(); }

std::vector<float> param_block(const Graph& graph, const ShadeIR& ir) {
  std::vector<float> block(static_cast<std::size_t>(ir.param_block_size), 0.0f);
  for (std::size_t i = 0; i < ir.params.size(); ++i) {
    const auto& value = graph.params[i].default_value;
    std::copy(value.begin(), value.end(), block.begin() + ir.params[i].slot);
  }
  return block;
}

}  // namespace shadetree
