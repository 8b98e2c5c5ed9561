// The samples the backends are compared on: 517 of them (two interpreter
// blocks and a tail, and a tail for every vector width), with a plane for
// every varying global, including lattice points, negative and large (1e4)
// coordinates; and a kernel's outputs over them.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "interp/interpreter.h"
#include "ir/kernel.h"
#include "jit/jit_kernel.h"

namespace shadetree::testing {

struct SampleSet {
  static constexpr std::size_t count = 517;
  SampleBuffers input{count, GlobalSet().set()};
  UniformInputs uniforms;

  SampleSet() {
    std::mt19937 random(1989);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    auto store_unit_vector = [&](GlobalId id, std::size_t i) {
      const float v[3] = {unit(random), unit(random), unit(random) + 2.0f};
      const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (int c = 0; c < 3; ++c) input.plane(id, c)[i] = v[c] / length;
    };
    for (std::size_t i = 0; i < count; ++i) {
      float p[3];
      switch (i % 5) {
        case 0:  // lattice points
          for (float& c : p) c = std::round(unit(random) * 4.0f);
          break;
        case 1:  // negative coordinates
          for (float& c : p) c = -std::fabs(unit(random)) * 7.0f;
          break;
        case 2:  // far from the origin
          for (float& c : p) c = 1e4f + unit(random) * 3.0f;
          break;
        default:
          for (float& c : p) c = unit(random) * 3.0f;
      }
      for (int c = 0; c < 3; ++c) input.plane(GlobalId::P, c)[i] = p[c];
      for (GlobalId id : {GlobalId::N, GlobalId::I, GlobalId::L}) store_unit_vector(id, i);
      for (int c = 0; c < 2; ++c) input.plane(GlobalId::uv, c)[i] = (unit(random) + 1.0f) / 2.0f;
      const float widths[] = {0.0f, 0.001f, 0.01f, 0.1f, 0.7f};
      input.plane(GlobalId::filter_width)[i] = widths[i % 5];
      input.plane(GlobalId::density)[i] = (unit(random) + 1.0f) / 2.0f;
      input.plane(GlobalId::surface)[i] = static_cast<float>(i % 4);
    }
    uniforms.set(GlobalId::time, 0.75f);
    uniforms.set(GlobalId::frame, 18.0f);
    uniforms.set(GlobalId::step_size, 0.01f);
    for (int c = 0; c < 3; ++c) uniforms.set(GlobalId::light_color, 1.0f - 0.1f * c, c);
  }

  float P(int component, std::size_t i) const { return input.inputs().plane(GlobalId::P, component)[i]; }
};

inline const SampleSet& samples() {
  static const SampleSet set;
  return set;
}

// The interpreter, then the JIT at widths 4, 8 and 16; a JIT that fails
// to compile fails the test and is left out.
inline std::vector<std::unique_ptr<Kernel>> kernels_on_every_backend(const ShadeIR& ir) {
  std::vector<std::unique_ptr<Kernel>> kernels;
  kernels.push_back(make_interpreted_kernel(ir));
  for (int width : {4, 8, 16}) {
    Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(ir, width);
    EXPECT_TRUE(jit.ok()) << jit.error().to_string();
    if (jit) kernels.push_back(std::move(*jit));
  }
  return kernels;
}

inline std::vector<std::vector<float>> run(const Kernel& kernel, const std::vector<float>& params) {
  const OutputLayout& layout = kernel.outputs();
  std::vector<std::vector<float>> results(static_cast<std::size_t>(layout.plane_count),
                                          std::vector<float>(SampleSet::count, -12345.0f));
  std::vector<float*> pointers;
  for (auto& plane : results) pointers.push_back(plane.data());
  kernel.bind(params.data(), samples().uniforms)->run(samples().input.inputs(), pointers.data(), SampleSet::count);
  return results;
}

}  // namespace shadetree::testing
