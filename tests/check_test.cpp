// Every error class of parse and check produces its one-line message.
#include <gtest/gtest.h>

#include "graph/check.h"
#include "pipeline/compile_graph.h"
#include "graph/parse.h"
#include "support/graph_text.h"

namespace shadetree {
namespace {

using testing::graph_text;

// The message of the first error in the text, or "ok".
std::string diagnose(const std::string& text) {
  Result<Graph> parsed = parse_graph(text, "g.json");
  if (!parsed) return parsed.error().to_string();
  Result<CheckedGraph> checked = check_graph(std::make_shared<const Graph>(*parsed));
  if (!checked) return checked.error().to_string();
  return "ok";
}

const std::string color_out = R"("color": "c")";

TEST(Check, AcceptsAWellTypedGraph) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "n", "op": "noise", "in": {"p": "p"}},
                                   {"id": "c", "op": "mul", "in": {"a": "n", "b": [1, 0.5, 0.2]}})",
                                color_out)),
            "ok");
}

TEST(Check, ReportsInvalidJsonWithItsPosition) {
  EXPECT_EQ(diagnose("{\"format\": }").rfind("error: g.json: invalid JSON: parse error at line 1, column 12", 0), 0u);
}

// Regression: a number beyond double range was an internal error (exit 1,
// no file name).
TEST(Check, ReportsNumbersOutOfRangeAsInvalidJson) {
  for (const char* number : {"1e400", "-1e309"})
    EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"})", std::string(R"("color": )") + number)),
              std::string("error: g.json: invalid JSON: number overflow parsing '") + number + "'");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"})", R"("color": 1e39)")),
            "error: g.json: output \"color\" is out of the range of a 32-bit float");
}

// Regression: ids were echoed raw, so a newline split the error line and a
// NUL cut it short.
TEST(Check, EscapesControlCharactersInMessages) {
  const std::string message = diagnose(graph_text(R"({"id": "a\nb\u0000c\t", "op": "nois"})", color_out));
  EXPECT_EQ(message, R"(error: g.json: node "a\nb\x00c\t": unknown op "nois" (see `shadetree nodes` for the library))");
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(Check, ReportsWrongFormatAndNewerVersions) {
  EXPECT_EQ(diagnose(R"({"format": "x", "version": 1})"),
            "error: g.json: field \"format\" must be \"shadetree-graph\", got \"x\"");
  EXPECT_EQ(diagnose(R"({"format": "shadetree-graph", "version": 9, "kind": "texture"})"),
            "error: g.json: version 9 is not supported (this shadetree reads version 1)");
}

TEST(Check, ReportsTypeMismatchWithNodeAndInput) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "t", "op": "time"}, {"id": "c", "op": "noise", "in": {"p": "uv"}},
                                   {"id": "uv", "op": "uv"})",
                                color_out)),
            "error: g.json: node \"c\" input \"p\": expected vec3, got vec2");
}

TEST(Check, RejectsAddingVec2ToVec3) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "uv", "op": "uv"},
                                   {"id": "c", "op": "add", "in": {"a": "p", "b": "uv"}})",
                                color_out)),
            "error: g.json: node \"c\" input \"b\": expected vec3 (like input \"a\"), got vec2");
}

TEST(Check, PromotesFloatsToVectors) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "s", "op": "add", "in": {"a": 1.5, "b": "p"}},
                                   {"id": "c", "op": "to_color", "in": {"v": "s"}})",
                                color_out)),
            "ok");
}

TEST(Check, ReportsUnknownOps) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "nosie"})", color_out)),
            "error: g.json: node \"c\": unknown op \"nosie\" (see `shadetree nodes` for the library)");
}

TEST(Check, ReportsDuplicateIds) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "P"}, {"id": "c", "op": "N"})", color_out)),
            "error: g.json: node \"c\": duplicate node id");
}

TEST(Check, ReportsDanglingReferences) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "noise", "in": {"p": "q"}})", color_out)),
            "error: g.json: node \"c\" input \"p\": no node \"q\"");
}

TEST(Check, ReportsCyclesWithTheirPath) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "a", "op": "add", "in": {"a": "b", "b": 1}},
                                   {"id": "b", "op": "add", "in": {"a": "a", "b": 1}},
                                   {"id": "c", "op": "color", "in": {"r": "a"}})",
                                color_out)),
            "error: g.json: node \"a\": cycle: a -> b -> a");
}

TEST(Check, ReportsMissingOutputs) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}})",
                                R"("alpha": "s.x")")),
            "error: g.json: a texture graph needs an output \"color\"");
  EXPECT_NE(diagnose(graph_text(R"({"id": "p", "op": "P"})", R"("color": "p")", "", "volume"))
                .find("needs an output \"density\""),
            std::string::npos);
}

TEST(Check, OutputsFollowTheKindsContract) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"})", R"("color": "p", "colour": "p")")),
            "error: g.json: \"colour\" is not an output of texture graphs (color, alpha, height, normal, roughness)");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"})", R"("color": "p", "density": "p")", "", "surface")),
            "error: g.json: \"density\" is not an output of surface graphs (color, normal, specular, roughness, "
            "opacity, emission)");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p"}})",
                                R"("density": "s.x", "ior": "p")", "", "volume")),
            "error: g.json: output \"ior\": expected float, got vec3");
}

TEST(Check, ReportsWrongLiteralTypes) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "c", "op": "turbulence", "in": {"p": "p", "octaves": 2.5}})",
                                color_out)),
            "error: g.json: node \"c\" input \"octaves\": expected int, got non-integral number 2.5");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "noise", "in": {"p": true}})", color_out)),
            "error: g.json: node \"c\" input \"p\": expected vec3, got bool");
}

TEST(Check, ReportsUnknownParamsAndInputs) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "mul", "in": {"a": "$nope", "b": 1}})", color_out)),
            "error: g.json: node \"c\" input \"a\": unknown param \"$nope\"");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "mul", "in": {"a": 1, "c": 1}})", color_out)),
            "error: g.json: node \"c\" input \"c\": unknown input (inputs of mul: a, b)");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "mul", "in": {"a": 1}})", color_out)),
            "error: g.json: node \"c\" input \"b\": missing input (it has no default)");
}

TEST(Check, ReportsOutOfRangeParams) {
  const std::string params = R"("params": {"k": {"type": "float", "default": 5, "min": 0, "max": 2}},)";
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "mul", "in": {"a": "$k", "b": 1}})", color_out, params)),
            "error: g.json: param \"k\": 5 is above the maximum 2");
}

TEST(Check, ReportsOctavesBeyondTheLimit) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "c", "op": "turbulence", "in": {"p": "p", "octaves": 40}})",
                                color_out)),
            "error: g.json: node \"c\" input \"octaves\": octaves must be between 0 and 16, got 40");
  const std::string params = R"("params": {"o": {"type": "int", "default": 4, "max": 64}},)";
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "c", "op": "fbm", "in": {"p": "p", "octaves": "$o"}})",
                                color_out, params)),
            "error: g.json: node \"c\" input \"octaves\": octaves must be between 0 and 16, got 64");
}

TEST(Check, ReportsBadAttributes) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "spline", "in": {"x": 0.5}, "knots": [1, 2]})", color_out)),
            "error: g.json: node \"c\": attribute \"knots\" needs 4 to 4096 values, got 2");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "spline", "in": {"x": 0.5}, "knots": [1, 2], "basis": "cubic"})",
                                color_out)),
            "error: g.json: node \"c\": attribute \"basis\" must be one of: catmull-rom, linear, step");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "noise", "p": [1, 2, 3]})", color_out)),
            "error: g.json: node \"c\": unknown field \"p\" (inputs go in \"in\"; attributes of noise: seed)");
}

TEST(Check, SplineTypeFollowsItsKnots) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "spline", "in": {"x": 0.5}, "basis": "linear",
                                    "knots": [[0, 0, 0], [1, 1, 1]]})",
                                color_out)),
            "ok");
}

TEST(Check, ChecksFunctionsAndTheirCalls) {
  const std::string functions = R"("functions": {"twice": {"inputs": {"x": "float"},
      "nodes": [{"id": "d", "op": "mul", "in": {"a": "$x", "b": 2}}], "outputs": {"y": "d"}}},)";
  EXPECT_EQ(diagnose(graph_text(R"({"id": "t", "op": "twice", "in": {"x": 0.25}},
                                   {"id": "c", "op": "color", "in": {"r": "t.y"}})",
                                color_out, functions)),
            "ok");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"}, {"id": "t", "op": "twice", "in": {"x": "p"}},
                                   {"id": "c", "op": "color", "in": {"r": "t"}})",
                                color_out, functions)),
            "error: g.json: node \"t\" input \"x\": expected float, got vec3");
  const std::string recursive = R"("functions": {"f": {"inputs": {"x": "float"},
      "nodes": [{"id": "d", "op": "f", "in": {"x": "$x"}}], "outputs": {"y": "d"}}},)";
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "f", "in": {"x": 1}})", color_out, recursive)),
            "error: g.json: function \"f\" calls itself (directly or through other functions)");
}

// Every fault of a graph, one line each, in the order the checker meets
// them; what follows from a fault is not reported again.
std::vector<std::string> faults_of(const std::string& text) {
  Result<Graph> parsed = parse_graph(text, "g.json");
  EXPECT_TRUE(parsed) << parsed.error().to_string();
  auto graph = std::make_shared<const Graph>(*parsed);
  std::vector<std::string> lines;
  for (const Diagnostic& fault : check_faults(graph)) lines.push_back(fault.to_string());
  Result<CheckedGraph> checked = check_graph(graph);
  EXPECT_EQ(checked ? "ok" : checked.error().to_string(), lines.empty() ? "ok" : lines.front());
  return lines;
}

TEST(CheckFaults, ReportsEveryIndependentFaultOnce) {
  using Lines = std::vector<std::string>;
  EXPECT_EQ(faults_of(graph_text(R"({"id": "p", "op": "P"}, {"id": "u", "op": "uv"},
                                    {"id": "n", "op": "noise", "in": {"p": "u"}},
                                    {"id": "m", "op": "mul", "in": {"a": "n", "b": 2}},
                                    {"id": "t", "op": "turbulence", "in": {"p": "p", "octaves": 40}},
                                    {"id": "x", "op": "nois", "in": {"p": "p"}},
                                    {"id": "c", "op": "color", "in": {"r": "m", "g": "t", "b": "$nope"}})",
                                 color_out)),
            (Lines{"error: g.json: node \"x\": unknown op \"nois\" (see `shadetree nodes` for the library)",
                   "error: g.json: node \"n\" input \"p\": expected vec3, got vec2",
                   "error: g.json: node \"t\" input \"octaves\": octaves must be between 0 and 16, got 40"}));
  EXPECT_EQ(faults_of(graph_text(R"({"id": "c", "op": "color", "in": {"r": "gone", "g": "$nope"}})", color_out)),
            (Lines{"error: g.json: node \"c\" input \"r\": no node \"gone\""}));
  EXPECT_TRUE(faults_of(graph_text(R"({"id": "c", "op": "color", "in": {"r": 1}})", color_out)).empty());
}

TEST(CheckFaults, AFaultyFunctionIsReportedOnceAndNotAtItsCalls) {
  const std::string functions = R"("functions": {"f": {"inputs": {"x": "float"},
      "nodes": [{"id": "d", "op": "mul", "in": {"a": "$x", "b": "$y"}}], "outputs": {"y": "d"}}},)";
  EXPECT_EQ(faults_of(graph_text(R"({"id": "a", "op": "f", "in": {"x": 1}}, {"id": "b", "op": "f", "in": {"x": 2}},
                                    {"id": "c", "op": "color", "in": {"r": "a", "g": "b", "b": [1, 2]}})",
                                 color_out, functions)),
            (std::vector<std::string>{
                "error: g.json: node \"d\" input \"b\": function \"f\" has no input \"y\" (functions see only their "
                "inputs: pass params in as inputs)"}));
}

TEST(CheckFaults, ACycleStopsItsBodyAndFaultsAreBounded) {
  EXPECT_EQ(faults_of(graph_text(R"({"id": "a", "op": "abs", "in": {"x": "b"}}, {"id": "b", "op": "abs", "in": {"x": "a"}},
                                    {"id": "c", "op": "nois"})",
                                 color_out)),
            (std::vector<std::string>{"error: g.json: node \"a\": cycle: a -> b -> a"}));
  std::string nodes = R"({"id": "c", "op": "color"})";
  for (int i = 0; i < 150; ++i) nodes += R"(, {"id": "x)" + std::to_string(i) + R"(", "op": "nois"})";
  EXPECT_EQ(faults_of(graph_text(nodes, color_out)).size(), max_check_faults);
}

TEST(Check, FunctionOutputsKeepFileOrder) {
  const std::string functions = R"("functions": {"polar": {"inputs": {"x": "float"},
      "nodes": [{"id": "r", "op": "abs", "in": {"x": "$x"}}, {"id": "a", "op": "vec2", "in": {"x": "$x"}}],
      "outputs": {"radius": "r", "angle": "a"}}},)";
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "polar", "in": {"x": 2}},
                                   {"id": "c", "op": "color", "in": {"r": "p"}})",
                                color_out, functions)),
            "ok");  // "p" is radius (float), not angle (vec2)
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "polar", "in": {"x": 2}, "seed": 3},
                                   {"id": "c", "op": "color", "in": {"r": "p"}})",
                                color_out, functions)),
            "error: g.json: node \"p\": unknown field \"seed\" (inputs of function polar go in \"in\")");
}

TEST(Check, AlphaMustBeAFloat) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "p", "op": "P"})", R"("color": "p", "alpha": "p")")),
            "error: g.json: output \"alpha\": expected float, got vec3");
}

TEST(Check, DensityIsOnlyForVolumes) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "density"})", color_out)),
            "error: g.json: node \"c\": op \"density\" is only available in volume graphs, this is a texture graph");
}

TEST(Check, RefusesFunctionsThatExpandBeyondTheInstructionLimit) {
  // Each level calls the one below twice: 2^20 copies of the innermost node.
  std::string functions = R"("functions": {"f0": {"inputs": {"x": "float"},
      "nodes": [{"id": "n", "op": "neg", "in": {"x": "$x"}}], "outputs": {"y": "n"}})";
  for (int level = 1; level <= 20; ++level) {
    const std::string below = "f" + std::to_string(level - 1);
    functions += ", \"f" + std::to_string(level) + R"(": {"inputs": {"x": "float"}, "nodes": [
        {"id": "a", "op": ")" + below + R"(", "in": {"x": "$x"}},
        {"id": "b", "op": ")" + below + R"(", "in": {"x": "a"}}], "outputs": {"y": "b"}})";
  }
  functions += "},";
  Result<LoadedGraph> loaded = compile_graph_text(
      graph_text(R"({"id": "c", "op": "f20", "in": {"x": 1}})", color_out, functions), "bomb.json");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().to_string(),
            "error: bomb.json: the graph expands to more than 50000 instructions once its functions are inlined");
  EXPECT_EQ(loaded.error().status, ExitStatus::invalid_input);
}

TEST(Check, LongChainsDoNotExhaustTheStack) {
  // 60000 nodes listed last to first: the ordering walk goes 60000 deep.
  std::string nodes = R"({"id": "c", "op": "color", "in": {"r": "n59999"}})";
  for (int i = 59999; i >= 1; --i)
    nodes += R"(, {"id": "n)" + std::to_string(i) + R"(", "op": "neg", "in": {"x": "n)" + std::to_string(i - 1) + "\"}}";
  nodes += R"(, {"id": "n0", "op": "time"})";
  EXPECT_EQ(diagnose(graph_text(nodes, color_out)), "ok");
}

TEST(Check, RefusesDeeplyNestedJson) {
  std::string deep(100000, '[');
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "noise", "in": {"p": )" + deep + "}}", color_out)),
            "error: g.json: JSON nested deeper than 64 levels");
}

TEST(Check, RefusesMalformedReferencesAndOversizedRenders) {
  EXPECT_EQ(diagnose(graph_text(R"({"id": "s", "op": "P"}, {"id": "c", "op": "to_color", "in": {"v": "s."}})",
                                color_out)),
            "error: g.json: node \"c\" input \"v\": malformed reference \"s.\" (write \"id\" or \"id.output\")");
  EXPECT_EQ(diagnose(graph_text(R"({"id": "c", "op": "color"})", color_out,
                                R"("render": {"size": [4294967298, 3]},)")),
            "error: g.json: render size must be between 1 and 16384 pixels a side");
}

// render.frames: the animation's range, whole frames, first <= last, of
// bounded length; anything else is refused with the form it must take.
TEST(Check, RenderFramesAreARangeOfWholeFrames) {
  const auto with_frames = [](const std::string& frames) {
    return graph_text(R"({"id": "c", "op": "color"})", color_out, R"("render": {"frames": )" + frames + "},");
  };
  Result<Graph> parsed = parse_graph(with_frames("[0, 47]"), "g.json");
  ASSERT_TRUE(parsed) << parsed.error().to_string();
  EXPECT_EQ(parsed->render.frames, (std::pair<int, int>{0, 47}));
  EXPECT_EQ(diagnose(with_frames("[5, 5]")), "ok");
  const std::string expected =
      "error: g.json: render frames must be [first, last]: whole frames from 0 to 1000000000, first <= last, at most "
      "100000 of them";
  for (const char* bad : {"[5, 3]", "[0.5, 2]", "[0, 100000]", "[-1, 4]", "[0, 4294967298]", "\"0-47\"", "[1]"})
    EXPECT_EQ(diagnose(with_frames(bad)), expected) << bad;
}

TEST(ParamValue, ParsesAndRangeChecksSetValues) {
  ParamDecl param{"k", Type::vec3, {0, 0, 0}, 0.0f, 10.0f, {}};
  EXPECT_EQ(*parse_param_value(param, "1,2,3"), (std::vector<float>{1, 2, 3}));
  EXPECT_EQ(*parse_param_value(param, "4"), (std::vector<float>{4, 4, 4}));
  EXPECT_EQ(parse_param_value(param, "1,2").error().message,
            "param \"k\": expected 3 comma-separated numbers for vec3, got \"1,2\"");
  EXPECT_EQ(parse_param_value(param, "1,2,30").error().message, "param \"k\": 30 is above the maximum 10");
}

}  // namespace
}  // namespace shadetree
