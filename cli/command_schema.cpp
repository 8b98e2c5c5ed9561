// shadetree schema: the JSON Schema of the graph format (graph/format_schema.h).
#include <cstdio>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "graph/format_schema.h"

namespace shadetree {

void add_schema_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("schema", "print a JSON Schema of the graph format");
  command->callback([&run] {
    run = [] {
      std::printf("%s\n", graph_format_schema().dump(2).c_str());
      return ExitStatus::ok;
    };
  });
}

}  // namespace shadetree
