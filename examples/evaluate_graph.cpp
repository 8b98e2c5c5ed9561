// Evaluates a graph at a few points through shadetree's C++ stages: load,
// check and compile a graph, JIT its kernel, bind its params and run it.
//   evaluate_graph GRAPH.json
#include <cstdio>

#include "jit/jit_kernel.h"
#include "pipeline/compile_graph.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: evaluate_graph GRAPH.json\n");
    return 2;
  }
  shadetree::Result<shadetree::LoadedGraph> loaded = shadetree::load_and_compile(argv[1], {});
  if (!loaded) {
    std::fprintf(stderr, "%s\n", loaded.error().to_string().c_str());
    return static_cast<int>(loaded.error().status);
  }
  shadetree::Result<std::unique_ptr<shadetree::Kernel>> kernel = shadetree::make_jit_kernel(loaded->ir);
  if (!kernel) {
    std::fprintf(stderr, "%s\n", kernel.error().to_string().c_str());
    return 1;
  }
  constexpr std::size_t count = 4;
  shadetree::SampleBuffers inputs(count, (*kernel)->reads());
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < 3; ++c)
      if (inputs.has(shadetree::GlobalId::P)) inputs.plane(shadetree::GlobalId::P, c)[i] = 0.25f * static_cast<float>(i + c);
  shadetree::OutputBuffers outputs(count, (*kernel)->outputs());
  (*kernel)->bind(loaded->params.data(), {})->run(inputs.inputs(), outputs.planes(), count);
  const shadetree::OutputLayout& layout = (*kernel)->outputs();
  for (std::size_t i = 0; i < count; ++i) {
    std::printf("sample %zu:", i);
    for (int plane : shadetree::provided_planes(layout)) std::printf(" %g", outputs.plane(plane)[i]);
    std::printf("\n");
  }
  return 0;
}
