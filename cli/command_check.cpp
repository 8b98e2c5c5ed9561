// shadetree check FILE...: parse and type-check graphs without running
// them, and set up each one's driver (render/graph_kinds.h) as render
// would, scene files and all, so that check refuses what render would.
// A graph that fails the type check has each of its faults reported.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/arguments.h"
#include "io/graph_files.h"
#include "graph/parse.h"
#include "pipeline/compile_graph.h"
#include "render/graph_kinds.h"

namespace shadetree {

void add_check_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("check", "type-check graph files");
  auto files = std::make_shared<std::vector<std::string>>();
  auto search_paths = std::make_shared<std::vector<std::string>>();
  command->add_option("files", *files, "graph files")->required();
  add_search_path_option(*command, *search_paths);
  command->callback([&run, files, search_paths] {
    run = [files, search_paths] {
      ExitStatus worst = ExitStatus::ok;
      for (const std::string& file : *files) {
        const GraphFiles files = graph_files(*search_paths);
        // Read once: a second read for the list of faults found a pipe
        // empty (and waited on it for a writer).
        const Result<Graph> parsed = load_graph(file);
        Result<LoadedGraph> loaded = parsed ? compile_graph(*parsed, {}, files) : Result<LoadedGraph>(parsed.error());
        const auto failed = [&](ExitStatus status) {
          if (worst == ExitStatus::ok || status == ExitStatus::invalid_input) worst = status;
        };
        if (!loaded) {
          for (const Diagnostic& fault : every_fault(parsed, loaded.error(), files)) failed(report(fault));
          continue;
        }
        RenderRequest request;
        request.search_paths = *search_paths;
        Result<std::unique_ptr<FrameRenderer>> renderer = prepare_render(*loaded->graph, request);
        if (!renderer) {
          failed(report(renderer.error()));
          continue;
        }
        std::printf("ok: %s (%s graph \"%s\", %zu instructions)\n", printable(file).c_str(),
                    std::string(graph_kind_name(loaded->graph->kind)).c_str(), printable(loaded->graph->name).c_str(),
                    loaded->ir.code.size());
      }
      return worst;
    };
  });
}

}  // namespace shadetree
