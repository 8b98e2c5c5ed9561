#include "pipeline/compile_graph.h"

#include <cstdio>
#include <cstdlib>

#include "graph/check.h"
#include "ir/lower.h"
#include "ir/optimize.h"
#include "ir/verify.h"
#include "interp/interpreter.h"
#include "graph/parse.h"

namespace shadetree {

namespace {

// In debug builds, a pass that breaks an invariant stops the program at
// once, naming the pass.
PassObserver verified_in_debug_builds(const PassObserver& observe) {
#ifdef NDEBUG
  return observe;
#else
  return [observe](const char* pass, const ShadeIR& ir) {
    if (std::string problem = verify_shade_ir(ir); !problem.empty()) {
      std::fprintf(stderr, "error: internal error: ShadeIR after %s: %s\n", pass, problem.c_str());
      std::abort();
    }
    if (observe) observe(pass, ir);
  };
#endif
}

Result<LoadedGraph> compile_parsed(Result<Graph> parsed, const std::string& path,
                                   const std::vector<std::string>& assignments, const PassObserver& observe,
                                   const GraphFiles& files) {
  if (!parsed) return parsed.error();
  auto graph = std::make_shared<const Graph>(std::move(*parsed));
  Result<CheckedGraph> checked = check_graph(graph, files);
  if (!checked) return checked.error();
  Result<ShadeIR> ir = lower(*checked);
  if (!ir) return ir.error();
  LoadedGraph loaded{graph, std::move(*ir), {}, 0};
  loaded.instructions_before_optimization = static_cast<int>(loaded.ir.code.size());
  const PassObserver observer = verified_in_debug_builds(observe);
  if (observer) observer("lower", loaded.ir);
  optimize(loaded.ir, evaluate_constant_program, observer);
  loaded.params = param_block(*graph, loaded.ir);
  for (const std::string& assignment : assignments) {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0)
      return Diagnostic{ExitStatus::invalid_input, path, {}, {}, "--set expects NAME=VALUE, got \"" + assignment + "\""};
    if (Status set = set_param(loaded, assignment.substr(0, equals), assignment.substr(equals + 1)); !set) {
      Diagnostic error = set.error();
      error.file = path;
      return error;
    }
  }
  return loaded;
}

}  // namespace

Status set_param(LoadedGraph& loaded, const std::string& name, const std::string& value) {
  const Graph& graph = *loaded.graph;
  std::string known;
  for (std::size_t i = 0; i < graph.params.size(); ++i) {
    const ParamDecl& param = graph.params[i];
    if (param.name != name) {
      known += (known.empty() ? "" : ", ") + param.name;
      continue;
    }
    Result<std::vector<float>> values = parse_param_value(param, value);
    if (!values) return values.error();
    std::copy(values->begin(), values->end(), loaded.params.begin() + loaded.ir.params[i].slot);
    return success();
  }
  return invalid_input("--set: unknown param \"" + name + "\" (params: " + (known.empty() ? "none" : known) + ")");
}

Result<LoadedGraph> compile_graph(Graph graph, const std::vector<std::string>& assignments, const GraphFiles& files) {
  const std::string file = graph.file;
  return compile_parsed(std::move(graph), file, assignments, {}, files);
}

Result<LoadedGraph> load_and_compile(const std::string& path, const std::vector<std::string>& assignments,
                                     const PassObserver& observe, const GraphFiles& files) {
  return compile_parsed(load_graph(path), path, assignments, observe, files);
}

Result<LoadedGraph> compile_graph_text(const std::string& json, const std::string& file,
                                       const std::vector<std::string>& assignments, const PassObserver& observe,
                                       const GraphFiles& files) {
  return compile_parsed(parse_graph(json, file), file, assignments, observe, files);
}

std::vector<Diagnostic> every_fault(const Result<Graph>& parsed, const Diagnostic& failure, const GraphFiles& files) {
  if (!parsed) return {failure};
  std::vector<Diagnostic> faults = check_faults(std::make_shared<const Graph>(*parsed), files);
  if (faults.empty()) return {failure};
  return faults;
}

}  // namespace shadetree
