// The JIT's interval programs (codegen/emit_interval_program.h, compiled by
// jit/jit_compiler.h's compile_interval_program): the interpreter's
// enclosures to the bit, for every op over random boxes and for every
// gallery volume, and so enclosures of what the lane backends compute
// (the property test of interval_program_test.cpp, run on the JIT).
#include <gtest/gtest.h>

#include <bit>
#include <random>

#include "interp/exec_context.h"
#include "interp/interval_program.h"
#include "jit/jit_compiler.h"
#include "nodes/registry.h"
#include "support/gallery.h"
#include "support/interval_enclosure.h"
#include "support/one_op_graph.h"

namespace shadetree {
namespace {

using lanes::Interval;

bool same_bits(Interval a, Interval b) {
  return std::bit_cast<std::uint32_t>(a.lo) == std::bit_cast<std::uint32_t>(b.lo) &&
         std::bit_cast<std::uint32_t>(a.hi) == std::bit_cast<std::uint32_t>(b.hi);
}

// The program of `ir` on both backends, over `box_count` random boxes of
// every varying global (P about `centre`): every output plane the same.
void expect_backends_agree(const ShadeIR& ir, const std::vector<float>& params, const UniformInputs& uniforms,
                           float centre, float reach, int box_count, const std::vector<OutputId>& bounded = {}) {
  const IntervalProgram interpreted(ir, bounded);
  IntervalProgram compiled(ir, bounded);
  Result<CompiledIntervalProgram> code = compile_interval_program(ir, bounded);
  ASSERT_TRUE(code) << code.error().message;
  compiled.use_compiled(code->evaluate, code->code);
  BoundIntervalProgram by_interpreter = interpreted.bind(params.data(), uniforms);
  BoundIntervalProgram by_jit = compiled.bind(params.data(), uniforms);
  const auto planes = static_cast<std::size_t>(interpreted.outputs().plane_count);
  std::vector<Interval> expected(planes), found(planes);
  std::mt19937 random(1985);
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(random); };
  const float widths[] = {0.0f, 1e-3f, 0.05f, 0.5f, 3.0f};
  for (int b = 0; b < box_count; ++b) {
    SampleBox box;
    for (int plane = 0; plane < varying_plane_count; ++plane) {
      const float middle = uniform(centre - reach, centre + reach), half = widths[(b + plane) % 5] * uniform(0, 1);
      box.planes[plane] = {middle - half, middle + half};
    }
    // The same stale planes on both sides: outputs left out stay as they were.
    std::fill(expected.begin(), expected.end(), Interval{-7.0f, 7.0f});
    std::fill(found.begin(), found.end(), Interval{-7.0f, 7.0f});
    by_interpreter.evaluate(box, expected.data());
    by_jit.evaluate(box, found.data());
    for (std::size_t plane = 0; plane < planes; ++plane)
      ASSERT_TRUE(same_bits(expected[plane], found[plane]))
          << "box " << b << ", plane " << plane << ": the JIT's " << testing::shown(found[plane])
          << " against the interpreter's " << testing::shown(expected[plane]);
  }
}

TEST(JitIntervalProgram, EveryOpAgreesWithTheInterpreterToTheBit) {
  for (const OpDef& op : all_ops()) {
    if (!interp::op_kernel(op.id)) continue;  // replaced by lowering
    for (Type instance : testing::op_instances(op)) {
      SCOPED_TRACE(op.name + " over " + std::string(type_name(instance)));
      Result<LoadedGraph> loaded = testing::one_op_graph(op, instance);
      ASSERT_TRUE(loaded) << loaded.error().message;
      expect_backends_agree(loaded->ir, loaded->params, UniformInputs{}, 0.0f, 4.0f, 60);
    }
  }
}

TEST(JitIntervalProgram, GalleryVolumesAgreeWithTheInterpreterToTheBit) {
  for (const std::string& path : testing::gallery_graphs(GraphKind::volume)) {
    SCOPED_TRACE(testing::gallery_graph_name(path));
    Result<LoadedGraph> loaded = testing::load_gallery_graph(path);
    ASSERT_TRUE(loaded) << loaded.error().message;
    const UniformInputs uniforms = testing::march_uniforms(*loaded->graph->render.volume);
    expect_backends_agree(loaded->ir, loaded->params, uniforms, 0.0f, 1.5f, 200);
    // As the marcher bounds it: the opacity (or density) alone.
    const OutputId seen = loaded->ir.outputs.front().id;
    expect_backends_agree(loaded->ir, loaded->params, uniforms, 0.0f, 1.5f, 50, {seen});
  }
}

TEST(JitIntervalProgram, GalleryVolumesEncloseTheInterpreterOverBoxesOfP) {
  for (const std::string& path : testing::gallery_graphs(GraphKind::volume)) {
    SCOPED_TRACE(testing::gallery_graph_name(path));
    Result<LoadedGraph> loaded = testing::load_gallery_graph(path);
    ASSERT_TRUE(loaded) << loaded.error().message;
    const VolumeDesc& volume = *loaded->graph->render.volume;
    IntervalProgram program(loaded->ir);
    Result<CompiledIntervalProgram> code = compile_interval_program(loaded->ir, {});
    ASSERT_TRUE(code) << code.error().message;
    program.use_compiled(code->evaluate, code->code);
    testing::expect_program_encloses_the_interpreter(program, loaded->ir, loaded->params,
                                                      testing::march_uniforms(volume), volume.bounds_min,
                                                      volume.bounds_max, 300);
  }
}

}  // namespace
}  // namespace shadetree
