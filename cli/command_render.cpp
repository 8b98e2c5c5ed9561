// shadetree render FILE -o OUT.png|OUT.exr: render a texture graph.
#include <chrono>
#include <cstdio>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/arguments.h"
#include "pipeline/compile_graph.h"
#include "pipeline/tiered_kernel.h"
#include "render/image_output.h"
#include "render/progress.h"
#include "render/texture_driver.h"

namespace shadetree {

namespace {
struct RenderArguments {
  std::string file;
  std::string output;
  std::string size;
  std::vector<std::string> assignments;
  std::optional<float> frame;
  int threads = 0;
  std::string backend = "tiered";
  int width = 0;
};

std::string milliseconds_text(double milliseconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f ms", milliseconds);
  return text;
}

ExitStatus render(const RenderArguments& arguments) {
  Result<LoadedGraph> loaded = load_and_compile(arguments.file, arguments.assignments);
  if (!loaded) return report(loaded.error());
  // Refuse an output we cannot write before spending time on the render.
  Status writable = check_image_path(arguments.output);
  if (!writable) return report(writable.error());
  if (loaded->graph->kind != GraphKind::texture)
    return report({ExitStatus::invalid_input, arguments.file, {}, {},
                   "render supports texture graphs for now; this is a " +
                       std::string(graph_kind_name(loaded->graph->kind)) + " graph"});
  Result<TextureView> view_or_error = texture_view(*loaded->graph, arguments.size, arguments.frame);
  if (!view_or_error) return report(view_or_error.error());
  const TextureView& view = *view_or_error;

  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<TieredKernel> tiered;
  Result<std::unique_ptr<Kernel>> kernel = std::unique_ptr<Kernel>();
  if (arguments.backend == "tiered") {
    tiered = make_tiered_kernel(loaded->ir, arguments.width);
  } else {
    kernel = make_kernel(arguments.backend, loaded->ir, arguments.width);
    if (!kernel) return report(kernel.error());
  }
  const Kernel& chosen = tiered ? *tiered : **kernel;
  const auto render_start = std::chrono::steady_clock::now();
  Result<Image> image = [&] {
    ProgressReporter progress("rendering " + arguments.file);
    TextureRenderOptions options;
    options.threads = arguments.threads;
    options.progress = [&progress](double fraction) { progress.update(fraction); };
    return render_texture(chosen, loaded->params, view, options);
  }();
  if (!image) return report(image.error());
  const auto end = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(end - render_start).count();
  const double setup_milliseconds = std::chrono::duration<double, std::milli>(render_start - start).count();
  Status written = write_image(*image, arguments.output);
  if (!written) return report(written.error());
  const double samples = static_cast<double>(view.width) * view.height;
  std::string backend = arguments.backend + ", kernel ready in " + milliseconds_text(setup_milliseconds);
  if (tiered) {
    const TieredReport tiers = tiered->report();
    const long runs = tiers.interpreted_runs + tiers.compiled_runs;
    backend = tiers.jit_failed ? "tiered: the JIT failed, interpreter throughout"
              : !tiers.jit_ready || tiers.compiled_runs == 0
                  ? "tiered: interpreter throughout, the JIT still compiling"
                  : "tiered: JIT ready after " + milliseconds_text(tiers.jit_ready_milliseconds) + ", " +
                        std::to_string(tiers.compiled_runs) + " of " + std::to_string(runs) + " tiles on it";
  }
  std::fprintf(stderr, "%s: %dx%d, %.0f samples in %.3f s (%.2f M samples/s, %s) -> %s\n", arguments.file.c_str(),
               view.width, view.height, samples, seconds, samples / seconds / 1e6, backend.c_str(),
               arguments.output.c_str());
  return ExitStatus::ok;
}
}  // namespace

void add_render_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("render", "render a texture graph to a PNG or EXR image");
  auto arguments = std::make_shared<RenderArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  command->add_option("-o,--output", arguments->output, "output image (.png or .exr)")->required();
  command->add_option("--size", arguments->size, "image size WIDTHxHEIGHT (default: the graph's render size)");
  command->add_option("--set", arguments->assignments, "set a param: NAME=VALUE (repeatable)");
  command->add_option("--frame", arguments->frame, "animation frame (time = frame / 24)");
  command->add_option("--threads", arguments->threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->add_option("--backend", arguments->backend,
                      "backend: tiered (default: the interpreter while the JIT compiles, then the JIT), jit or interp")
      ->check(CLI::IsMember({"tiered", "jit", "interp"}));
  command->add_option("--width", arguments->width, "JIT vector width: 4, 8 or 16 (default: the host's widest)")
      ->check(CLI::IsMember({4, 8, 16}));
  command->callback([&run, arguments] { run = [arguments] { return render(*arguments); }; });
}

}  // namespace shadetree
