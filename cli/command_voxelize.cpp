// shadetree voxelize FILE -o OUT.vdb: sample a volume graph on a grid over
// its render.volume bounds and write an OpenVDB file (a "density" fog
// volume and, if the graph has one, a "color" grid), so that the
// hypertexture opens in Blender or Houdini.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "pipeline/compile_graph.h"
#include "pipeline/tiered_kernel.h"
#include "io/graph_files.h"
#include "io/output_file.h"
#include "schedule/progress.h"
#include "io/vdb_file.h"
#include "render/voxelize.h"

namespace shadetree {

namespace {
struct VoxelizeArguments {
  std::string file;
  std::string output;
  int resolution = 128;
  SamplingArguments sampling;
};

// A .vdb path in a folder that exists: checked before any sampling.
Status check_vdb_path(const std::string& path) {
  if (std::filesystem::path(path).extension() != ".vdb")
    return invalid_input("output \"" + path + "\": voxelize writes OpenVDB files (.vdb)");
  return check_output_folder(path);
}

ExitStatus voxelize_graph(const VoxelizeArguments& arguments) {
  Result<LoadedGraph> loaded =
      load_and_compile(arguments.file, arguments.sampling.assignments, {}, graph_files(arguments.sampling.search_paths));
  if (!loaded) return report(loaded.error());
  const Graph& graph = *loaded->graph;
  if (graph.kind != GraphKind::volume)
    return report(Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {},
                             "voxelize samples volume graphs; this is " + a_graph_of(graph.kind)});
  Status writable = check_vdb_path(arguments.output);
  if (!writable) return report(writable.error());
  Result<std::unique_ptr<Kernel>> kernel = make_kernel(arguments.sampling.backend, loaded->ir, 0);
  if (!kernel) return report(kernel.error());

  ProgressReporter progress("voxelizing " + arguments.file, "slices", "voxels");
  VoxelizeOptions options;
  options.resolution = arguments.resolution;
  options.frame = arguments.sampling.frame.value_or(graph.render.frame);
  options.threads = arguments.sampling.threads;
  options.progress = progress.callback();
  const auto start = std::chrono::steady_clock::now();
  Result<VoxelGrid> grid = voxelize(**kernel, loaded->params, *graph.render.volume, options);
  if (!grid) return report(Diagnostic{grid.error().status, arguments.file, {}, {}, grid.error().message});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Status written = write_vdb(*grid, arguments.output);
  if (!written) return report(written.error());
  std::size_t occupied = 0;
  for (float density : grid->density) occupied += density > 0.0f;
  std::fprintf(stderr, "%s: %dx%dx%d voxels of %g, %zu with density, sampled in %.3f s (%.2f M samples/s, %s) -> %s\n",
               arguments.file.c_str(), grid->size[0], grid->size[1], grid->size[2], grid->voxel_size, occupied, seconds,
               static_cast<double>(grid->density.size()) / seconds / 1e6, arguments.sampling.backend.c_str(),
               arguments.output.c_str());
  return ExitStatus::ok;
}
}  // namespace

void add_voxelize_command(CLI::App& app, CommandRunner& run) {
  auto* command =
      app.add_subcommand("voxelize", "sample a volume graph on a grid and write an OpenVDB file (.vdb)");
  auto arguments = std::make_shared<VoxelizeArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  command->add_option("-o,--output", arguments->output, "output OpenVDB file (.vdb)")->required();
  command->add_option("--res", arguments->resolution,
                      "voxels along the longest side of the graph's render.volume bounds (default 128, at most " +
                          std::to_string(max_voxel_resolution) + ")")
      ->check(CLI::Range(1, max_voxel_resolution));
  add_sampling_options(*command, arguments->sampling);
  command->callback([&run, arguments] { run = [arguments] { return voxelize_graph(*arguments); }; });
}

}  // namespace shadetree
