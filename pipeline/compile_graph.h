// Load -> parse -> check -> lower, plus --set style param overrides: the
// front half of the pipeline, as every command and driver runs it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "graph/check.h"
#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "ir/optimize.h"
#include "ir/shade_ir.h"

namespace shadetree {

struct LoadedGraph {
  std::shared_ptr<const Graph> graph;
  ShadeIR ir;                 // optimized
  std::vector<float> params;  // the uniform block, overrides applied
  int instructions_before_optimization = 0;
};

// Sets param `name` of the uniform block to `value`, written as for --set
// ("14", "0.2,0.4,0.8", "true"), checked against its type and range.
Status set_param(LoadedGraph& loaded, const std::string& name, const std::string& value);

// `assignments` are NAME=VALUE strings (shadetree's --set). `observe` sees
// the program after lowering ("lower") and after each optimizer pass; in
// debug builds every one of those programs is also verified (ir/verify.h).
// `files` reads the files (images, meshes) the graph's ops name.
Result<LoadedGraph> load_and_compile(const std::string& path, const std::vector<std::string>& assignments,
                                     const PassObserver& observe = {}, const GraphFiles& files = {});

// The same from a parsed graph (its `file` names it in messages), for
// commands that add to a graph before compiling it (bake).
Result<LoadedGraph> compile_graph(Graph graph, const std::vector<std::string>& assignments,
                                  const GraphFiles& files = {});

// The same from JSON text; `file` names it in messages.
Result<LoadedGraph> compile_graph_text(const std::string& json, const std::string& file,
                                       const std::vector<std::string>& assignments = {},
                                       const PassObserver& observe = {}, const GraphFiles& files = {});

// Every fault of a graph that failed to compile with `failure`: those the
// checker finds in `parsed` (check_faults) when the check is what failed,
// else `failure` alone (the file did not parse, or a later stage refused
// it).
std::vector<Diagnostic> every_fault(const Result<Graph>& parsed, const Diagnostic& failure,
                                    const GraphFiles& files = {});

}  // namespace shadetree
