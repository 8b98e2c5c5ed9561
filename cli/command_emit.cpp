// shadetree emit FILE --graph [--after-each-pass] | --llvm | --asm
//                    | --cpp | --glsl [--shadertoy] [-o FILE] [--name NAME]:
// what a graph compiles to, after optimization, so that a reader can check
// the passes and see the vector instructions; or the kernel as standalone
// C++ to build into another program, or as GLSL for a GPU.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <CLI/CLI.hpp>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cppgen/emit_cpp.h"
#include "render/glsl_shader.h"
#include "graph/generated_names.h"
#include "pipeline/compile_graph.h"
#include "io/output_file.h"
#include "io/graph_files.h"
#include "jit/jit_compiler.h"

namespace shadetree {

namespace {
struct EmitArguments {
  std::string file;
  bool graph = false, llvm = false, assembly = false, cpp = false, glsl = false, shadertoy = false,
       after_each_pass = false;
  std::string output, name;
  int width = 0;
  std::vector<std::string> assignments;
  std::vector<std::string> search_paths;
};

// The kernel's name: --name, else the graph's name, else the file's stem.
std::string kernel_name(const EmitArguments& arguments, const Graph& graph) {
  if (!arguments.name.empty()) return arguments.name;
  if (!graph.name.empty()) return graph.name;
  return std::filesystem::path(arguments.file).stem().string();
}

Result<std::string> glsl_source(const EmitArguments& arguments, const LoadedGraph& loaded, const std::string& name) {
  Result<GlslShader> shader = glsl_shader(*loaded.graph, loaded.ir, loaded.params, {name, arguments.shadertoy});
  if (!shader) return shader.error();
  return shader->source;
}

// The C++ or GLSL source of the kernel, to stdout or -o.
ExitStatus emit_source_file(const EmitArguments& arguments, const LoadedGraph& loaded) {
  if (!arguments.name.empty() && code_identifier(arguments.name) != arguments.name)
    return report(Diagnostic{ExitStatus::invalid_input, arguments.file, {}, {},
                             "--name must be an identifier (ASCII letters, digits and single _ inside, not a keyword "
                             "or an all-capitals name), got " + quoted_text(arguments.name)});
  const std::string name = kernel_name(arguments, *loaded.graph);
  Result<std::string> source = arguments.glsl ? glsl_source(arguments, loaded, name)
                                              : emit_cpp(*loaded.graph, loaded.ir, loaded.params, name);
  if (!source) return report(source.error());
  if (arguments.output.empty()) {
    std::fwrite(source->data(), 1, source->size(), stdout);
    return ExitStatus::ok;
  }
  if (Status folder = check_output_folder(arguments.output); !folder) return report(folder.error());
  Status written = write_then_rename(arguments.output, [&](const std::string& temporary) -> std::string {
    std::ofstream file(temporary, std::ios::binary);
    file << *source;
    file.close();
    return file ? "" : "cannot write " + temporary;
  });
  return written ? ExitStatus::ok : report(written.error());
}

ExitStatus emit(const EmitArguments& arguments) {
  PassObserver print_each_pass;
  if (arguments.after_each_pass)
    print_each_pass = [](const char* pass, const ShadeIR& ir) {
      std::printf("; after %s: %zu instructions\n%s\n", pass, ir.code.size(), format_shade_ir(ir).c_str());
    };
  Result<LoadedGraph> loaded = load_and_compile(arguments.file, arguments.assignments, print_each_pass, graph_files(arguments.search_paths));
  if (!loaded) return report(loaded.error());
  if (arguments.after_each_pass) return ExitStatus::ok;
  if (arguments.cpp || arguments.glsl) return emit_source_file(arguments, *loaded);
  if (arguments.graph) {
    std::printf("; %s: %d instructions before optimization, %zu after\n", printable(arguments.file).c_str(),
                loaded->instructions_before_optimization, loaded->ir.code.size());
    std::printf("%s", format_shade_ir(loaded->ir).c_str());
    return ExitStatus::ok;
  }
  Result<std::string> listing =
      kernel_listing(loaded->ir, arguments.width, arguments.llvm ? Listing::optimized_llvm_ir : Listing::assembly);
  if (!listing) return report(listing.error());
  std::printf("%s", listing->c_str());
  return ExitStatus::ok;
}
}  // namespace

void add_emit_command(CLI::App& app, CommandRunner& run) {
  auto* command = app.add_subcommand("emit", "print the optimized graph, LLVM IR or machine code of a graph, or write its kernel as C++ or GLSL");
  auto arguments = std::make_shared<EmitArguments>();
  command->add_option("file", arguments->file, "graph file")->required();
  auto* graph = command->add_flag("--graph", arguments->graph, "the optimized ShadeIR");
  auto* llvm = command->add_flag("--llvm", arguments->llvm, "the optimized LLVM IR of the kernel");
  auto* assembly = command->add_flag("--asm", arguments->assembly, "the kernel's machine code");
  command->add_flag("--after-each-pass", arguments->after_each_pass,
                    "with --graph: the program after lowering and after each optimizer pass")
      ->needs(graph);
  auto* cpp = command->add_flag("--cpp", arguments->cpp, "the kernel as a standalone C++ header");
  auto* glsl = command->add_flag("--glsl", arguments->glsl,
                                 "the kernel as GLSL ES 3.00 (WebGL 2): a fragment shader of its driver (texture, environment, volume march, surface)");
  command->add_flag("--shadertoy", arguments->shadertoy, "with --glsl: a mainImage to paste into Shadertoy")
      ->needs(glsl);
  command->add_option("-o,--output", arguments->output, "with --cpp or --glsl: the file to write (default: stdout)");
  command->add_option("--name", arguments->name,
                      "with --cpp or --glsl: name of the emitted function (default: the graph's name)");
  graph->excludes(llvm)->excludes(assembly)->excludes(cpp)->excludes(glsl);
  llvm->excludes(assembly)->excludes(cpp)->excludes(glsl);
  assembly->excludes(cpp)->excludes(glsl);
  cpp->excludes(glsl);
  command->add_option("--width", arguments->width, "vector width: 4, 8 or 16 (default: the host's widest)")
      ->check(CLI::IsMember({4, 8, 16}));
  command->add_option("--set", arguments->assignments, "set a param: NAME=VALUE (repeatable)");
  add_search_path_option(*command, arguments->search_paths);
  command->callback([&run, arguments] {
    if (!arguments->graph && !arguments->llvm && !arguments->assembly && !arguments->cpp && !arguments->glsl)
      throw CLI::ValidationError("emit", "choose one of --graph, --llvm, --asm, --cpp, --glsl");
    if ((!arguments->output.empty() || !arguments->name.empty()) && !arguments->cpp && !arguments->glsl)
      throw CLI::ValidationError("emit", "-o and --name go with --cpp or --glsl");
    run = [arguments] { return emit(*arguments); };
  });
}

}  // namespace shadetree
