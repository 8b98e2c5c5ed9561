// The shadetree command line. Exit status: 0 success, 1 I/O or internal
// failure, 2 invalid input (usage, graph or parameter); every failure
// prints one line on stderr.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "graph/diagnostic.h"
#include "platform/process_heap.h"

namespace shadetree {

ExitStatus report(const Diagnostic& diagnostic) {
  std::fprintf(stderr, "%s\n", diagnostic.to_string().c_str());
  return diagnostic.status;
}

}  // namespace shadetree

int main(int argc, char** argv) {
  using namespace shadetree;
  keep_freed_memory_in_the_process();
  CLI::App app{"shadetree: compile and render JSON shade graphs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "shadetree 0.1 (graph format 1)");
  CommandRunner run;
  add_check_command(app, run);
  add_render_command(app, run);
  add_eval_command(app, run);
  add_nodes_command(app, run);
  add_schema_command(app, run);
  add_emit_command(app, run);
  add_bench_command(app, run);
  add_voxelize_command(app, run);
  add_bake_command(app, run);
  add_serve_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ParseError& error) {
    // The message echoes what was typed: escaped, it stays one line.
    std::fprintf(stderr, "error: %s (see shadetree --help)\n", printable(error.what()).c_str());
    return static_cast<int>(ExitStatus::invalid_input);
  }
  try {
    return static_cast<int>(run());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory\n");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: internal error: %s\n", error.what());
  }
  return static_cast<int>(ExitStatus::failure);
}
