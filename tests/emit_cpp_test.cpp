// emit --cpp: the C++ emitted for every gallery graph and for random
// graphs, built as C++17 by g++ and clang++ at -O2 -march=native with SIMD
// lanes and without (SHADETREE_NO_SIMD), and by g++ for plain x86-64 (SSE2,
// the portable primitives), computes what the interpreter computes on
// the differential samples, within 1e-5 (relative above 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cppgen/emit_cpp.h"
#include "graph/generated_names.h"
#include "interp/interpreter.h"
#include "support/differential_samples.h"
#include "support/gallery.h"
#include "support/graph_text.h"
#include "support/hostile_graph.h"
#include "support/random_graph.h"
#include "support/test_files.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

struct Emitted {
  std::string name;  // of the kernel
  LoadedGraph loaded;
};

// The varying globals in the order the driver reads their planes.
std::vector<std::pair<GlobalId, int>> varying_planes() {
  std::vector<std::pair<GlobalId, int>> planes;
  for (const GlobalDef& global : globals)
    if (global.variability == Variability::varying)
      for (int c = 0; c < global.components; ++c) planes.push_back({global.id, c});
  return planes;
}

// A program that runs every kernel on the samples of inputs.bin (the
// varying planes, then the uniform values) and writes their outputs, in
// the kernels' output order, to the file it is given.
std::string driver_source(const std::vector<Emitted>& kernels) {
  std::ostringstream out;
  for (const Emitted& kernel : kernels) out << "#include \"" << kernel.name << ".h\"\n";
  out << "#include <cstdio>\n#include <vector>\n\nint main(int, char** argv) {\n"
      << "  const std::size_t count = " << testing::SampleSet::count << ";\n"
      << "  std::vector<std::vector<float>> planes(" << varying_planes().size() << ", std::vector<float>(count));\n"
      << "  float uniforms[" << uniform_value_count << "];\n"
      << "  std::FILE* in = std::fopen(argv[1], \"rb\");\n"
      << "  for (auto& plane : planes) if (std::fread(plane.data(), sizeof(float), count, in) != count) return 1;\n"
      << "  if (std::fread(uniforms, sizeof uniforms, 1, in) != 1) return 1;\n"
      << "  std::FILE* out = std::fopen(argv[2], \"wb\");\n";
  const auto planes = varying_planes();
  for (const Emitted& kernel : kernels) {
    const std::string& n = kernel.name;
    out << "  {\n    " << n << "_params params;\n    " << n << "_inputs inputs;\n    " << n << "_outputs outputs;\n";
    std::set<GlobalId> reads;
    for (const IrInstr& instr : kernel.loaded.ir.code)
      if (instr.kind == IrOpKind::global) reads.insert(static_cast<GlobalId>(instr.immediate[0]));
    for (GlobalId id : reads) {
      const GlobalDef& global = global_def(id);
      for (int c = 0; c < global.components; ++c) {
        const std::string field = "inputs." + std::string(global.name) + (global.components > 1 ? "[" + std::to_string(c) + "]" : "");
        if (global.variability == Variability::uniform) {
          out << "    " << field << " = uniforms[" << global.first + c << "];\n";
          continue;
        }
        const auto at = std::find(planes.begin(), planes.end(), std::pair{id, c}) - planes.begin();
        out << "    " << field << " = planes[" << at << "].data();\n";
      }
    }
    int plane = 0;
    for (const IrOutput& output : kernel.loaded.ir.outputs)
      for (int c = 0; c < component_count(output.type); ++c, ++plane)
        out << "    std::vector<float> out" << plane << "(count);\n    outputs." << output_id_name(output.id) << "[" << c
            << "] = out" << plane << ".data();\n";
    out << "    " << n << "_run(&params, &inputs, &outputs, count);\n";
    for (int p = 0; p < plane; ++p) out << "    std::fwrite(out" << p << ".data(), sizeof(float), count, out);\n";
    out << "  }\n";
  }
  out << "  return std::fclose(out) == 0 ? 0 : 1;\n}\n";
  return out.str();
}

// The interpreter's outputs of every kernel, in the driver's order.
std::vector<float> interpreted(const std::vector<Emitted>& kernels) {
  std::vector<float> all;
  for (const Emitted& kernel : kernels) {
    auto reference = make_interpreted_kernel(kernel.loaded.ir);
    const auto planes = testing::run(*reference, kernel.loaded.params);
    const OutputLayout& layout = reference->outputs();
    for (const IrOutput& output : kernel.loaded.ir.outputs)
      for (int c = 0; c < component_count(output.type); ++c) {
        const auto& plane = planes[static_cast<std::size_t>(layout.plane(output.id, c))];
        all.insert(all.end(), plane.begin(), plane.end());
      }
  }
  return all;
}

void write_inputs(const fs::path& path) {
  std::ofstream file(path, std::ios::binary);
  const auto& samples = testing::samples();
  for (const auto& [id, c] : varying_planes())
    file.write(reinterpret_cast<const char*>(samples.input.inputs().plane(id, c)),
               sizeof(float) * testing::SampleSet::count);
  float uniforms[uniform_value_count];
  for (const GlobalDef& global : globals)
    if (global.variability == Variability::uniform)
      for (int c = 0; c < global.components; ++c) uniforms[global.first + c] = samples.uniforms.get(global.id, c);
  file.write(reinterpret_cast<const char*>(uniforms), sizeof uniforms);
}

bool close_enough(float emitted, float reference) {
  if (std::isnan(emitted) || std::isnan(reference)) return std::isnan(emitted) && std::isnan(reference);
  if (std::isinf(reference)) return emitted == reference;
  return std::fabs(emitted - reference) <= 1e-5f * std::max(1.0f, std::fabs(reference));
}

class EmitCpp : public ::testing::Test {
 protected:
  void emit(const std::string& name, Result<LoadedGraph> loaded) {
    ASSERT_TRUE(loaded.ok()) << name << ": " << loaded.error().to_string();
    Result<std::string> source = emit_cpp(*loaded->graph, loaded->ir, loaded->params, name);
    ASSERT_TRUE(source.ok()) << name << ": " << source.error().to_string();
    std::ofstream(directory_ / (name + ".h")) << *source;
    kernels_.push_back({name, std::move(*loaded)});
  }

  // Builds the driver with `compiler` and `flags`, runs it and compares
  // every output sample with the interpreter's.
  void compare(const std::string& compiler, const std::string& flags) {
    const fs::path driver = directory_ / "driver.cpp", program = directory_ / "driver";
    std::ofstream(driver) << driver_source(kernels_);
    write_inputs(directory_ / "inputs.bin");
    const std::string build = compiler + " -std=c++17 -O2 -march=native -w " + flags + " -I" + directory_.string() +
                              " " + driver.string() + " -o " + program.string() + " 2>&1";
    ASSERT_EQ(std::system(build.c_str()), 0) << build;
    const fs::path outputs = directory_ / "outputs.bin";
    ASSERT_EQ(std::system((program.string() + " " + (directory_ / "inputs.bin").string() + " " + outputs.string()).c_str()), 0);
    const std::vector<float> expected = interpreted(kernels_);
    std::vector<float> actual(expected.size());
    std::ifstream(outputs, std::ios::binary).read(reinterpret_cast<char*>(actual.data()), sizeof(float) * actual.size());
    ASSERT_EQ(fs::file_size(outputs), sizeof(float) * expected.size());
    std::size_t at = 0;
    for (const Emitted& kernel : kernels_) {
      int wrong = 0;
      for (const IrOutput& output : kernel.loaded.ir.outputs)
        for (int c = 0; c < component_count(output.type); ++c)
          for (std::size_t i = 0; i < testing::SampleSet::count; ++i, ++at)
            if (!close_enough(actual[at], expected[at]) && wrong++ < 3)
              ADD_FAILURE() << compiler << " " << flags << ": " << kernel.name << " output " << output_id_name(output.id)
                            << "[" << c << "] sample " << i << ": emitted " << actual[at] << ", interpreter "
                            << expected[at];
    }
  }

  testing::TempFolder folder_{"shadetree-emit-cpp"};
  const fs::path& directory_ = folder_.path();
  std::vector<Emitted> kernels_;
};

TEST_F(EmitCpp, GalleryAndRandomGraphsAgreeWithTheInterpreter) {
  for (const std::string& path : testing::gallery_graphs())
    emit(code_identifier(testing::gallery_graph_name(path)), testing::load_gallery_graph(path));
  for (std::uint32_t seed = 1; seed <= 24; ++seed)
    emit("random_" + std::to_string(seed), compile_graph_text(testing::RandomGraph(seed).generate(18), "generated.json",
                                                             {}, {}, testing::test_files()));
  for (const char* compiler : {SHADETREE_GXX, SHADETREE_CLANGXX})
    for (const char* flags : {"", "-DSHADETREE_NO_SIMD"}) compare(compiler, flags);
  // SSE2 only: 4 lanes, and the portable floor, sqrt and gathers.
  compare(SHADETREE_GXX, "-march=x86-64");
}

// An image of 1024 x 1024 RGBA pixels is 4 M floats of data: emit says so
// and names the node instead of writing 50 MB of source.
TEST(EmitCppLimits, RefusesDataTooLargeToEmitNamingTheNode) {
  Result<LoadedGraph> loaded = testing::large_image_graph();
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> source = emit_cpp(*loaded->graph, loaded->ir, loaded->params, "big");
  ASSERT_FALSE(source.ok());
  EXPECT_EQ(source.error().node, "photo");
  EXPECT_EQ(source.error().file, "big.json");
  EXPECT_NE(source.error().message.find("too many to emit"), std::string::npos) << source.error().message;
}

TEST_F(EmitCpp, HostileNamesAreNeverLiveCode) {
  Result<LoadedGraph> loaded = compile_graph_text(testing::hostile_graph(), testing::hostile_file_name, {}, {}, {});
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  Result<std::string> source = emit_cpp(*loaded->graph, loaded->ir, loaded->params, "hostile");
  ASSERT_TRUE(source.ok()) << source.error().to_string();
  // Every line of the graph's part is printable ASCII, no line ends in a
  // backslash, and what would be live code is inside a comment.
  std::istringstream lines(emitted_program(*source));
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    for (char c : line) ASSERT_TRUE(c >= 0x20 && c < 0x7f) << "line " << number << ": " << line;
    ASSERT_TRUE(line.empty() || line.back() != '\\') << "line " << number << ": " << line;
    for (const char* live : {"#error", "static_assert(", "#include <no_such"}) {
      if (line.find(live) != std::string::npos) {
        EXPECT_LT(line.find("//"), line.find(live)) << "line " << number << " is not a comment: " << line;
      }
    }
  }
  emit("hostile", std::move(loaded));
  compare(SHADETREE_GXX, "");
  compare(SHADETREE_CLANGXX, "-DSHADETREE_NO_SIMD");
}

}  // namespace
}  // namespace shadetree
