// The enclosure property of an interval program, whichever backend runs it
// (the interpreter's, or the JIT's compiled form: IntervalProgram::
// use_compiled): over random boxes of P within the bounds, every output
// plane's enclosure holds what the interpreter's lanes compute at points
// of the box (its corners and random points inside).
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <sstream>
#include <string>

#include "graph/parse_volume.h"
#include "interp/interpreter.h"
#include "interp/interval_program.h"

namespace shadetree::testing {

inline std::string shown(lanes::Interval x) {
  std::ostringstream text;
  text.precision(9);
  text << "[" << x.lo << ", " << x.hi << "]";
  return text.str();
}

// The uniforms a volume is marched with.
inline UniformInputs march_uniforms(const VolumeDesc& volume) {
  UniformInputs uniforms;
  uniforms.set(GlobalId::step_size, march_step(volume));
  return uniforms;
}

// Boxes of P of widths 0 to half the bounds, the other varying globals as
// a marcher sets them (I a direction, filter_width up to 0.01, density in
// [0, 1], the surface globals 0).
inline void expect_program_encloses_the_interpreter(const IntervalProgram& program, const ShadeIR& ir,
                                                    const std::vector<float>& params, const UniformInputs& uniforms,
                                                    const std::array<float, 3>& lo, const std::array<float, 3>& hi,
                                                    int box_count) {
  constexpr std::size_t samples = 256;
  BoundIntervalProgram bound = program.bind(params.data(), uniforms);
  auto kernel = make_interpreted_kernel(ir);
  auto binding = kernel->bind(params.data(), uniforms);
  SampleBuffers inputs(samples, GlobalSet().set());
  OutputBuffers outputs(samples, kernel->outputs());
  std::vector<lanes::Interval> enclosures(static_cast<std::size_t>(kernel->outputs().plane_count));
  std::mt19937 random(7);
  auto uniform = [&](float from, float to) { return std::uniform_real_distribution<float>(from, to)(random); };
  for (int b = 0; b < box_count; ++b) {
    SampleBox box;
    const float fractions[] = {0.0f, 0.002f, 0.02f, 0.1f, 0.5f};
    const float fraction = fractions[b % 5];
    for (int a = 0; a < 3; ++a) {
      const float centre = uniform(lo[a], hi[a]), half = fraction * (hi[a] - lo[a]) * 0.5f;
      box.set(GlobalId::P, {centre - half, centre + half}, a);
    }
    const float direction[3] = {0.48f, -0.6f, 0.64f};
    for (int a = 0; a < 3; ++a) box.set(GlobalId::I, direction[a], a);
    box.set(GlobalId::filter_width, {0.0f, 0.01f});
    box.set(GlobalId::density, {0.0f, 1.0f});
    for (GlobalId id : {GlobalId::N, GlobalId::uv, GlobalId::L, GlobalId::surface})
      for (int c = 0; c < global_def(id).components; ++c) box.set(id, 0.0f, c);
    for (int plane = 0; plane < varying_plane_count; ++plane)
      for (std::size_t i = 0; i < samples; ++i) {
        const lanes::Interval x = box.planes[plane];
        float* to = const_cast<float*>(inputs.inputs().planes[plane]);
        to[i] = i == 0 ? x.lo : i == 1 ? x.hi : std::min(x.hi, x.lo + (x.hi - x.lo) * uniform(0, 1));
      }
    binding->run(inputs.inputs(), outputs.planes(), samples);
    bound.evaluate(box, enclosures.data());
    for (int plane : provided_planes(kernel->outputs()))
      for (std::size_t i = 0; i < samples; ++i)
        ASSERT_TRUE(lanes::encloses(enclosures[static_cast<std::size_t>(plane)], outputs.plane(plane)[i]))
            << "plane " << plane << ": " << outputs.plane(plane)[i] << " outside "
            << shown(enclosures[static_cast<std::size_t>(plane)]) << " for P in " << shown(box.planes[0]) << " x "
            << shown(box.planes[1]) << " x " << shown(box.planes[2]);
  }
}

}  // namespace shadetree::testing
