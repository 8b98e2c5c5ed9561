// The shadetree subcommands. Each registers its options on the CLI11 app
// and returns the function that runs it once parsing succeeded.
#pragma once

#include <functional>

#include "graph/diagnostic.h"

namespace CLI {
class App;
}

namespace shadetree {

using CommandRunner = std::function<ExitStatus()>;

void add_check_command(CLI::App& app, CommandRunner& run);
void add_render_command(CLI::App& app, CommandRunner& run);
void add_eval_command(CLI::App& app, CommandRunner& run);
void add_nodes_command(CLI::App& app, CommandRunner& run);
void add_schema_command(CLI::App& app, CommandRunner& run);
void add_emit_command(CLI::App& app, CommandRunner& run);
void add_bench_command(CLI::App& app, CommandRunner& run);
void add_voxelize_command(CLI::App& app, CommandRunner& run);
void add_bake_command(CLI::App& app, CommandRunner& run);
void add_serve_command(CLI::App& app, CommandRunner& run);

// Prints a diagnostic as its one line on stderr; returns its exit status.
ExitStatus report(const Diagnostic& diagnostic);

}  // namespace shadetree
