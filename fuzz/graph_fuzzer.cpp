// libFuzzer harness: any bytes through the whole front of the pipeline
// (parse, check, lower, every optimizer pass with the ShadeIR verifier
// after each), then the interpreter on a handful of samples, and for one
// input in eight that compiles to a small program, the JIT, whose results
// must equal the interpreter's bit for bit. Every diagnostic must be one
// line, and runs on an index list must equal dense runs. The C++ that
// emit --cpp writes for it must hold no text of the graph outside quoted
// comments (for one input in eight): printable ASCII only, and no line
// continued by a backslash. The program's interval form over the box of
// the samples' inputs must enclose every output the interpreter gave them.
// Built by
// scripts/fuzz.sh (clang, -fsanitize=fuzzer,address,undefined).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "cppgen/emit_cpp.h"
#include "render/glsl_shader.h"
#include "interp/interpreter.h"
#include "interp/interval_program.h"
#include "ir/verify.h"
#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"

namespace shadetree {
namespace {

[[noreturn]] void fault(const std::string& what) {
  std::fprintf(stderr, "fuzz: %s\n", what.c_str());
  std::abort();
}

constexpr std::size_t sample_count = 19;  // two JIT vectors and a tail

struct Samples {
  SampleBuffers input{sample_count, GlobalSet().set()};
  UniformInputs uniforms;

  Samples() {
    for (const GlobalDef& global : globals)
      for (int c = 0; c < global.components; ++c) {
        if (global.variability == Variability::uniform) {
          uniforms.set(global.id, 0.5f + static_cast<float>(c), c);
          continue;
        }
        for (std::size_t i = 0; i < sample_count; ++i)
          input.plane(global.id, c)[i] = static_cast<float>(i) * 0.37f - 3.0f + static_cast<float>(c);
      }
  }
};

// The outputs of a dense run; a run on a reversed index list must give the
// same values.
std::vector<std::vector<float>> run(const Kernel& kernel, const std::vector<float>& params, Samples& samples) {
  OutputBuffers outputs(sample_count, kernel.outputs()), indexed(sample_count, kernel.outputs());
  std::unique_ptr<BoundKernel> bound = kernel.bind(params.data(), samples.uniforms);
  bound->run(samples.input.inputs(), outputs.planes(), sample_count);
  std::uint32_t index[sample_count];
  for (std::uint32_t i = 0; i < sample_count; ++i) index[i] = static_cast<std::uint32_t>(sample_count) - 1 - i;
  bound->run_indexed(samples.input.inputs(), indexed.planes(), index, sample_count);
  std::vector<std::vector<float>> values;
  for (int p : provided_planes(kernel.outputs())) {
    values.emplace_back(outputs.plane(p), outputs.plane(p) + sample_count);
    for (std::size_t i = 0; i < sample_count; ++i) {
      const float a = outputs.plane(p)[i], b = indexed.plane(p)[i];
      if (!(a == b || (std::isnan(a) && std::isnan(b)))) fault("an indexed run differs from the dense run");
    }
  }
  return values;
}

// Any file a graph names reads as a small made-up one (an RGB image, a
// distance grid of a sphere), so that the ops that read files are fuzzed
// without touching the disk.
Result<Image> made_up_image(const std::string&, const std::string&) {
  Image image{3, 2, 3, {}};
  for (int i = 0; i < 18; ++i) image.pixels.push_back(static_cast<float>(i) / 17.0f);
  return image;
}

Result<DistanceGrid> made_up_grid(const std::string&, const std::string&, int) {
  DistanceGrid grid{{4, 4, 4}, {-1.0f, -1.0f, -1.0f}, 0.5f, {}};
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        grid.distance.push_back(std::sqrt(float((i - 1.5) * (i - 1.5) + (j - 1.5) * (j - 1.5) + (k - 1.5) * (k - 1.5))) * 0.5f - 0.6f);
  return grid;
}

// Every output of every sample lies in the enclosure of the program over
// the box that holds the samples' inputs.
void check_enclosure(const LoadedGraph& loaded, Samples& samples, const std::vector<std::vector<float>>& reference) {
  const IntervalProgram program(loaded.ir);
  BoundIntervalProgram bound = program.bind(loaded.params.data(), samples.uniforms);
  SampleBox box;
  for (const GlobalDef& global : globals) {
    if (global.variability == Variability::uniform) continue;
    for (int c = 0; c < global.components; ++c) {
      const float* plane = samples.input.plane(global.id, c);
      const auto [lo, hi] = std::minmax_element(plane, plane + sample_count);
      box.set(global.id, {*lo, *hi}, c);
    }
  }
  std::vector<lanes::Interval> enclosures(static_cast<std::size_t>(program.outputs().plane_count));
  bound.evaluate(box, enclosures.data());
  const std::vector<int> planes = provided_planes(program.outputs());
  for (std::size_t p = 0; p < planes.size(); ++p)
    for (std::size_t i = 0; i < sample_count; ++i) {
      const lanes::Interval enclosure = enclosures[static_cast<std::size_t>(planes[p])];
      if (!lanes::encloses(enclosure, reference[p][i]))
        fault("the interval form of plane " + std::to_string(planes[p]) + " [" + std::to_string(enclosure.lo) + ", " +
              std::to_string(enclosure.hi) + "] misses sample " + std::to_string(i) + ": " +
              std::to_string(reference[p][i]));
    }
}

}  // namespace
}  // namespace shadetree

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace shadetree;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const PassObserver verify = [](const char* pass, const ShadeIR& ir) {
    if (std::string problem = verify_shade_ir(ir); !problem.empty()) fault(std::string("after ") + pass + ": " + problem);
  };
  Result<LoadedGraph> loaded = compile_graph_text(text, "fuzz.json", {}, verify, GraphFiles{made_up_image, made_up_grid});
  if (!loaded) {
    const std::string line = loaded.error().to_string();
    if (line.find('\n') != std::string::npos || line.find('\0') != std::string::npos) fault("diagnostic of several lines");
    return 0;
  }
  // Emitted source, C++ for one graph in eight and GLSL for another: a
  // graph's text never continues a line or leaves printable ASCII.
  const std::size_t emitter = std::hash<std::string>{}(text) % 8;
  Result<std::string> source = invalid_input("not emitted");
  if (emitter == 1) {
    source = emit_cpp(*loaded->graph, loaded->ir, loaded->params, loaded->graph->name);
    if (source) source = emitted_program(*source);
  } else if (emitter == 2) {
    Result<GlslShader> shader = glsl_shader(*loaded->graph, loaded->ir, loaded->params, {loaded->graph->name, false});
    if (shader) source = shader->source;
  }
  if (source) {
    char previous = '\n';
    for (char c : *source) {
      if (c == '\n' && previous == '\\') fault("emitted source continues a line with a backslash");
      if (c != '\n' && (c < 0x20 || c > 0x7e)) fault("emitted source holds a byte that is not printable ASCII");
      previous = c;
    }
  }
  static Samples samples;
  const auto reference = run(*make_interpreted_kernel(loaded->ir), loaded->params, samples);
  check_enclosure(*loaded, samples, reference);
  if (std::hash<std::string>{}(text) % 8 != 0 || loaded->ir.code.size() > 60) return 0;
  Result<std::unique_ptr<Kernel>> jit = make_jit_kernel(loaded->ir, 8, JitSettings{false, {}, false, std::nullopt});
  if (!jit) fault("JIT failed: " + jit.error().to_string());
  const auto compiled = run(**jit, loaded->params, samples);
  for (std::size_t p = 0; p < reference.size(); ++p)
    for (std::size_t i = 0; i < sample_count; ++i) {
      const float a = reference[p][i], b = compiled[p][i];
      if (!(a == b || (std::isnan(a) && std::isnan(b))))
        fault("backends disagree on plane " + std::to_string(p) + " sample " + std::to_string(i) + ": " +
              std::to_string(a) + " vs " + std::to_string(b));
    }
  return 0;
}
