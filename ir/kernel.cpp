#include "ir/kernel.h"

#include <algorithm>
#include <sstream>

#include "nodes/op_frame.h"
#include "nodes/registry.h"

namespace shadetree {

GlobalSet globals_read(const ShadeIR& ir) {
  GlobalSet read;
  for (const IrInstr& instr : ir.code)
    if (instr.kind == IrOpKind::global) read.set(static_cast<std::size_t>(instr.immediate[0]));
  return read;
}

std::vector<int> varying_planes(const GlobalSet& read) {
  std::vector<int> planes;
  for (const GlobalDef& global : globals)
    if (global.variability == Variability::varying && read.test(static_cast<std::size_t>(global.id)))
      for (int c = 0; c < global.components; ++c) planes.push_back(global.first + c);
  return planes;
}

std::size_t plane_stride(std::size_t count) {
  constexpr std::size_t line = 16;  // floats in a 64-byte cache line
  return (count + line - 1) / line * line + line;
}

SampleBuffers::SampleBuffers(std::size_t count, const GlobalSet& stored) : count_(count), stored_(stored) {
  std::size_t planes = 0;
  for (const GlobalDef& global : globals) {
    if (global.variability != Variability::varying || !has(global.id)) continue;
    for (int c = 0; c < global.components; ++c) offset_[global.first + c] = plane_stride(count) * planes++;
  }
  storage_.assign(plane_stride(count) * planes, 0.0f);
}

OutputBuffers::OutputBuffers(std::size_t count, const OutputLayout& layout)
    : storage_(plane_stride(count) * static_cast<std::size_t>(layout.plane_count)) {
  for (int p = 0; p < layout.plane_count; ++p)
    planes_.push_back(storage_.data() + plane_stride(count) * static_cast<std::size_t>(p));
}

SampleInputs SampleBuffers::inputs() const {
  SampleInputs inputs;
  for (const GlobalDef& global : globals) {
    if (global.variability != Variability::varying || !has(global.id)) continue;
    for (int c = 0; c < global.components; ++c)
      inputs.planes[global.first + c] = storage_.data() + offset_[global.first + c];
  }
  return inputs;
}

OutputLayout output_layout(const ShadeIR& ir) {
  OutputLayout layout;
  layout.kind = ir.kind;
  layout.plane_count = output_plane_count(ir.kind);
  std::fill(std::begin(layout.first_plane), std::end(layout.first_plane), -1);
  for (const IrOutput& output : ir.outputs)
    layout.first_plane[static_cast<int>(output.id)] = output_first_plane(ir.kind, output.id);
  return layout;
}

std::vector<int> provided_planes(const OutputLayout& layout) {
  std::vector<int> planes;
  for (const OutputSpec& spec : output_contract(layout.kind))
    if (layout.provides(spec.id))
      for (int c = 0; c < component_count(spec.type); ++c) planes.push_back(layout.plane(spec.id, c));
  return planes;
}

std::string kernel_abi() {
  std::ostringstream text;
  text << "op-constants " << sizeof(OpConstants) << " args " << max_op_args << "\n";
  for (const OpDef& op : all_ops()) {
    text << op_symbol(op.id) << ' ' << static_cast<int>(op.tables) << " (";
    for (const PortSpec& port : op.inputs) text << static_cast<int>(port.rule) << type_name(port.type) << ' ';
    text << ") ->";
    for (const PortSpec& port : op.outputs) text << ' ' << static_cast<int>(port.rule) << type_name(port.type);
    text << '\n';
  }
  for (const GlobalDef& global : globals)
    text << global.name << ' ' << type_name(global.type) << ' ' << static_cast<int>(global.variability) << ' '
         << global.first << '\n';
  for (GraphKind kind : all_graph_kinds) {
    text << graph_kind_name(kind) << ':';
    for (const OutputSpec& spec : output_contract(kind)) text << ' ' << spec.name << ' ' << type_name(spec.type);
    text << '\n';
  }
  return text.str();
}

void BoundKernel::run_indexed(const SampleInputs& inputs, float* const* outputs, const std::uint32_t* index,
                              std::size_t count) {
  // Gathered in chunks that stay in the first-level cache.
  constexpr std::size_t chunk = 256;
  const std::vector<int> input_planes = varying_planes(reads_);
  const std::vector<int> output_planes = provided_planes(layout_);
  indexed_scratch_.resize((input_planes.size() + output_planes.size()) * chunk);

  SampleInputs gathered;
  std::vector<float*> gathered_planes, scattered(static_cast<std::size_t>(layout_.plane_count), nullptr);
  for (std::size_t i = 0; i < input_planes.size(); ++i) {
    gathered_planes.push_back(indexed_scratch_.data() + i * chunk);
    gathered.planes[input_planes[i]] = gathered_planes.back();
  }
  for (std::size_t i = 0; i < output_planes.size(); ++i)
    scattered[static_cast<std::size_t>(output_planes[i])] = indexed_scratch_.data() + (input_planes.size() + i) * chunk;

  for (std::size_t start = 0; start < count; start += chunk) {
    const std::size_t n = std::min(chunk, count - start);
    const std::uint32_t* samples = index + start;
    for (std::size_t i = 0; i < input_planes.size(); ++i) {
      const float* from = inputs.planes[input_planes[i]];
      for (std::size_t k = 0; k < n; ++k) gathered_planes[i][k] = from[samples[k]];
    }
    run(gathered, scattered.data(), n);
    for (int p : output_planes) {
      if (!outputs[p]) continue;
      const float* from = scattered[static_cast<std::size_t>(p)];
      for (std::size_t k = 0; k < n; ++k) outputs[p][samples[k]] = from[k];
    }
  }
}

}  // namespace shadetree
