// The C API (api/shadetree.h) over the pipeline, the backends and the
// texture driver. No exception or crash crosses it: every failure becomes a
// status and a one-line message.
#include "api/shadetree.h"

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/parse.h"
#include "interp/interpreter.h"
#include "interp/interval_program.h"
#include "jit/jit_compiler.h"
#include "jit/jit_kernel.h"
#include "nodes/globals.h"
#include "nodes/output_contract.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"
#include "io/image_output.h"
#include "render/graph_kinds.h"

struct shadetree_graph {
  shadetree::LoadedGraph loaded;
  int backend = SHADETREE_JIT;
  std::unique_ptr<shadetree::Kernel> kernel;
  std::unique_ptr<shadetree::IntervalProgram> bounds;  // made by the first shadetree_bound
};

namespace shadetree {
namespace {

thread_local std::string last_error;

shadetree_status fail(const Diagnostic& diagnostic) {
  last_error = diagnostic.to_string();
  return static_cast<shadetree_status>(diagnostic.status);
}

shadetree_status fail_with(ExitStatus status, const std::string& message) {
  return fail(Diagnostic{status, {}, {}, {}, message});
}

shadetree_status succeed() {
  last_error.clear();
  return SHADETREE_OK;
}

// Runs `body`, turning what it throws (out of memory, a library fault)
// into a failure.
template <class Body>
shadetree_status guarded(Body body) {
  try {
    return body();
  } catch (const std::exception& error) {
    return fail_with(ExitStatus::failure, std::string("internal error: ") + error.what());
  } catch (...) {
    return fail_with(ExitStatus::failure, "internal error");
  }
}

shadetree_status finish_load(Result<LoadedGraph> loaded, int backend, shadetree_graph** graph) {
  if (!loaded) return fail(loaded.error());
  auto result = std::make_unique<shadetree_graph>();
  result->loaded = std::move(*loaded);
  result->backend = backend;
  if (backend == SHADETREE_INTERPRETER) {
    result->kernel = make_interpreted_kernel(result->loaded.ir);
  } else {
    Result<std::unique_ptr<Kernel>> compiled = make_jit_kernel(result->loaded.ir);
    if (!compiled) return fail(compiled.error());
    result->kernel = std::move(*compiled);
  }
  *graph = result.release();
  return succeed();
}

bool valid_backend(int backend) { return backend == SHADETREE_JIT || backend == SHADETREE_INTERPRETER; }

const GlobalDef* find_global(std::string_view name) {
  for (const GlobalDef& global : globals)
    if (global.name == name) return &global;
  return nullptr;
}

UniformInputs frame_uniforms(float frame) {
  UniformInputs uniforms;
  uniforms.set(GlobalId::time, frame / frames_per_second);
  uniforms.set(GlobalId::frame, frame);
  for (int c = 0; c < 3; ++c) uniforms.set(GlobalId::light_color, 1.0f, c);
  return uniforms;
}

}  // namespace
}  // namespace shadetree

using namespace shadetree;

extern "C" {

const char* shadetree_last_error(void) { return last_error.c_str(); }

shadetree_status shadetree_load(const char* path, int backend, shadetree_graph** graph) {
  if (graph) *graph = nullptr;
  if (!path || !graph) return fail_with(ExitStatus::invalid_input, "shadetree_load: path and graph must not be NULL");
  if (!valid_backend(backend)) return fail_with(ExitStatus::invalid_input, "shadetree_load: unknown backend");
  return guarded([&] { return finish_load(load_and_compile(path, {}, {}, graph_files()), backend, graph); });
}

shadetree_status shadetree_load_text(const char* json, const char* name, int backend, shadetree_graph** graph) {
  if (graph) *graph = nullptr;
  if (!json || !graph)
    return fail_with(ExitStatus::invalid_input, "shadetree_load_text: json and graph must not be NULL");
  if (!valid_backend(backend)) return fail_with(ExitStatus::invalid_input, "shadetree_load_text: unknown backend");
  return guarded([&] {
    return finish_load(compile_graph_text(json, name ? name : "graph.json", {}, {}, graph_files()), backend, graph);
  });
}

void shadetree_free(shadetree_graph* graph) { delete graph; }

const char* shadetree_kind(const shadetree_graph* graph) {
  // A kind's name views a string literal of nodes/graph_kind.h, so it ends in a NUL.
  return graph ? graph_kind_name(graph->loaded.graph->kind).data() : "";
}

shadetree_status shadetree_set_param(shadetree_graph* graph, const char* name, const char* value) {
  if (!graph || !name || !value)
    return fail_with(ExitStatus::invalid_input, "shadetree_set_param: graph, name and value must not be NULL");
  return guarded([&] {
    Status set = set_param(graph->loaded, name, value);
    if (!set) {
      Diagnostic error = set.error();
      error.file = graph->loaded.graph->file;
      return fail(error);
    }
    return succeed();
  });
}

int shadetree_input_plane(const char* global, int component) {
  const GlobalDef* found = global ? find_global(global) : nullptr;
  if (!found || found->variability != Variability::varying || component < 0 || component >= found->components)
    return -1;
  return found->first + component;
}

int shadetree_output_plane(const shadetree_graph* graph, const char* output, int component) {
  if (!graph || !output) return -1;
  const OutputSpec* spec = find_output_spec(graph->loaded.graph->kind, output);
  if (!spec || component < 0 || component >= component_count(spec->type)) return -1;
  return output_first_plane(graph->loaded.graph->kind, spec->id) + component;
}

int shadetree_input_plane_count(void) { return varying_plane_count; }

int shadetree_output_plane_count(const shadetree_graph* graph) {
  return graph ? output_plane_count(graph->loaded.graph->kind) : 0;
}

shadetree_status shadetree_run(shadetree_graph* graph, float frame, const float* const* inputs, float* const* outputs,
                               size_t count) {
  if (!graph || !inputs || !outputs)
    return fail_with(ExitStatus::invalid_input, "shadetree_run: graph, inputs and outputs must not be NULL");
  SampleInputs planes;
  for (int plane : varying_planes(graph->kernel->reads())) {
    if (!inputs[plane])
      return fail_with(ExitStatus::invalid_input,
                       "shadetree_run: input plane " + std::to_string(plane) + " is NULL, and the graph reads it");
    planes.planes[plane] = inputs[plane];
  }
  return guarded([&] {
    graph->kernel->bind(graph->loaded.params.data(), frame_uniforms(frame))->run(planes, outputs, count);
    return succeed();
  });
}

shadetree_status shadetree_bound(shadetree_graph* graph, float frame, const float* lo, const float* hi, float* out_lo,
                                 float* out_hi) {
  if (!graph || !lo || !hi || !out_lo || !out_hi)
    return fail_with(ExitStatus::invalid_input, "shadetree_bound: graph, lo, hi, out_lo and out_hi must not be NULL");
  SampleBox box;
  for (int plane = 0; plane < varying_plane_count; ++plane) {
    if (!(lo[plane] <= hi[plane]))
      return fail_with(ExitStatus::invalid_input, "shadetree_bound: input plane " + std::to_string(plane) +
                                                      " has lo > hi, or a NaN bound");
    box.planes[plane] = {lo[plane], hi[plane]};
  }
  return guarded([&] {
    if (!graph->bounds) {
      auto program = std::make_unique<IntervalProgram>(graph->loaded.ir);
      if (graph->backend == SHADETREE_JIT) {
        Result<CompiledIntervalProgram> compiled = compile_interval_program(graph->loaded.ir, {});
        if (!compiled) return fail(compiled.error());
        program->use_compiled(compiled->evaluate, compiled->code);
      }
      graph->bounds = std::move(program);
    }
    const OutputLayout& layout = graph->bounds->outputs();
    std::vector<lanes::Interval> outputs(static_cast<std::size_t>(layout.plane_count));
    for (std::size_t plane = 0; plane < outputs.size(); ++plane) outputs[plane] = {out_lo[plane], out_hi[plane]};
    graph->bounds->bind(graph->loaded.params.data(), frame_uniforms(frame)).evaluate(box, outputs.data());
    for (std::size_t plane = 0; plane < outputs.size(); ++plane) {
      out_lo[plane] = outputs[plane].lo;
      out_hi[plane] = outputs[plane].hi;
    }
    return succeed();
  });
}

shadetree_status shadetree_render(shadetree_graph* graph, int width, int height, float frame, float* rgba) {
  if (!graph || !rgba) return fail_with(ExitStatus::invalid_input, "shadetree_render: graph and rgba must not be NULL");
  if (width < 1 || height < 1 || width > max_image_side || height > max_image_side)
    return fail_with(ExitStatus::invalid_input,
                     "shadetree_render: each side must be between 1 and " + std::to_string(max_image_side));
  return guarded([&] {
    RenderRequest request;
    request.size = {width, height};
    Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*graph->loaded.graph, request);
    if (!renderer) return fail(renderer.error());
    Result<Image> image = (*renderer)->render(*graph->kernel, graph->loaded.params, frame, {}, nullptr);
    if (!image) return fail(image.error());
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    for (std::size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 4; ++c)
        rgba[4 * i + c] = c < image->channels ? image->pixels[i * image->channels + c] : 1.0f;
    return succeed();
  });
}

shadetree_status shadetree_render_texture(shadetree_graph* graph, int width, int height, float frame, float* rgba) {
  if (graph && graph->loaded.graph->kind != GraphKind::texture)
    return fail_with(ExitStatus::invalid_input, "shadetree_render_texture: " + graph->loaded.graph->file + " is " +
                                                    a_graph_of(graph->loaded.graph->kind) + ", not a texture graph");
  return shadetree_render(graph, width, height, frame, rgba);
}

shadetree_status shadetree_write_image(const char* path, const float* pixels, int width, int height, int channels) {
  if (!path || !pixels)
    return fail_with(ExitStatus::invalid_input, "shadetree_write_image: path and pixels must not be NULL");
  if (width < 1 || height < 1 || width > max_image_side || height > max_image_side || channels < 1 || channels > 4)
    return fail_with(ExitStatus::invalid_input, "shadetree_write_image: " + std::string(path) +
                                                    ": sides must be 1 to " + std::to_string(max_image_side) +
                                                    " and channels 1 to 4");
  return guarded([&] {
    Image image{width, height, channels,
                std::vector<float>(pixels, pixels + static_cast<std::size_t>(width) * height * channels)};
    if (Status checked = check_image_path(path); !checked) return fail(checked.error());
    if (Status written = write_image(image, path); !written) return fail(written.error());
    return succeed();
  });
}

}  // extern "C"
