// The shadetree command as a user meets it: exit statuses, one-line errors,
// no partial outputs, eval agreeing with render, generated docs up to date.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "graph/graph.h"
#include "nodes/registry.h"
#include "io/image_output.h"
#include "io/vdb_file.h"
#include "render/environment_driver.h"
#include "render/texture_driver.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int status;
  std::string out;
  std::string err;
};

std::string read_text(const fs::path& path) {
  std::ifstream stream(path);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

class Cli : public ::testing::Test {
 protected:
  CommandResult shadetree(const std::string& arguments, const std::string& binary = SHADETREE_BINARY) const {
    const fs::path err = directory_ / "stderr.txt";
    const std::string command = binary + " " + arguments + " 2>" + err.string();
    FILE* pipe = ::popen(command.c_str(), "r");
    std::string out;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    const int status = ::pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, read_text(err)};
  }

  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(directory_ / name) << text;
    return directory_ / name;
  }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_))
      if (entry.path().filename() != "stderr.txt") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  testing::TempFolder folder_{"shadetree-cli"};
  const fs::path& directory_ = folder_.path();
};

const std::string gallery = SHADETREE_SOURCE_DIR "/graphs/";

int line_count(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST_F(Cli, CheckAcceptsTheGallery) {
  const CommandResult run = shadetree("check " + gallery + "marble.json " + gallery + "julia.json");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(line_count(run.out), 2);
}

TEST_F(Cli, InvalidGraphsExitWithTwoAndOneLine) {
  const fs::path graph = write("bad.json", R"({"format": "shadetree-graph", "version": 1, "kind": "texture",
      "nodes": [{"id": "uv", "op": "uv"}, {"id": "t2", "op": "turbulence", "in": {"p": "uv"}}],
      "outputs": {"color": "t2"}})");
  const CommandResult run = shadetree("check " + graph.string());
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err, "error: " + graph.string() + ": node \"t2\" input \"p\": expected vec3, got vec2\n");
}

TEST_F(Cli, CheckReportsEveryFaultOfAGraphAndRenderTheFirst) {
  const fs::path graph = write("two.json", R"({"format": "shadetree-graph", "version": 1, "kind": "texture",
      "nodes": [{"id": "p", "op": "P"}, {"id": "u", "op": "uv"}, {"id": "n", "op": "noise", "in": {"p": "u"}},
                {"id": "t", "op": "turbulence", "in": {"p": "p", "octaves": 40}},
                {"id": "c", "op": "color", "in": {"r": "n", "g": "t"}}],
      "outputs": {"color": "c"}})");
  const std::string first = "error: " + graph.string() + ": node \"n\" input \"p\": expected vec3, got vec2\n";
  const CommandResult check = shadetree("check " + graph.string());
  EXPECT_EQ(check.status, 2);
  EXPECT_EQ(check.err, first + "error: " + graph.string() +
                           ": node \"t\" input \"octaves\": octaves must be between 0 and 16, got 40\n");
  const CommandResult render = shadetree("render " + graph.string() + " -o " + (directory_ / "two.png").string());
  EXPECT_EQ(render.status, 2);
  EXPECT_EQ(render.err, first);
}

// A graph read from a pipe is there to be read once: check, listing every
// fault, once read it a second time and waited for another writer.
TEST_F(Cli, CheckReadsAGraphOnceFromAPipe) {
  const fs::path text = write("two.txt", R"({"format": "shadetree-graph", "version": 1, "kind": "texture",
      "nodes": [{"id": "u", "op": "uv"}, {"id": "n", "op": "noise", "in": {"p": "u"}},
                {"id": "t", "op": "turbulence", "in": {"p": "u"}}, {"id": "c", "op": "color", "in": {"r": "n", "g": "t"}}],
      "outputs": {"color": "c"}})");
  const fs::path pipe = directory_ / "pipe.json";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const CommandResult run = shadetree("check " + pipe.string(),
                                      "cat " + text.string() + " > " + pipe.string() + " & timeout 60 " SHADETREE_BINARY);
  EXPECT_EQ(run.status, 2) << "124: still waiting on the pipe";
  EXPECT_EQ(line_count(run.err), 2) << run.err;
  EXPECT_NE(run.err.find("node \"t\" input \"p\": expected vec3, got vec2"), std::string::npos) << run.err;
}

TEST_F(Cli, MissingFilesAndUsageErrorsExitWithTwo) {
  CommandResult run = shadetree("check " + (directory_ / "absent.json").string());
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err, "error: " + (directory_ / "absent.json").string() + ": no such file\n");
  run = shadetree("render " + gallery + "marble.json");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(line_count(run.err), 1);
  run = shadetree("frobnicate");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(line_count(run.err), 1);
}

TEST_F(Cli, BadSizesParamsAndExtensionsExitWithTwoAndWriteNothing) {
  const std::string out = (directory_ / "out.png").string();
  CommandResult run = shadetree("render " + gallery + "marble.json -o " + out + " --size 100000x100000");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(run.err, "error: --size 100000x100000: each side must be between 1 and 16384 pixels\n");
  run = shadetree("render " + gallery + "marble.json -o " + out + " --size 8x8 --set nope=1");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("unknown param \"nope\""), std::string::npos) << run.err;
  run = shadetree("render " + gallery + "marble.json -o " + out + " --size 8x8 --set scale=-5");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("param \"scale\": -5 is below the minimum"), std::string::npos) << run.err;
  run = shadetree("render " + gallery + "marble.json -o " + (directory_ / "out.tiff").string() + " --size 8x8");
  EXPECT_EQ(run.status, 2);
  EXPECT_TRUE(files().empty());
}

TEST_F(Cli, UnwritableOutputsExitWithOneAndLeaveNoPartialFile) {
  const CommandResult run = shadetree("render " + gallery + "marble.json -o " + (directory_ / "missing" / "out.png").string() +
                            " --size 8x8");
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_TRUE(files().empty());
}

TEST_F(Cli, SurfaceGraphsRenderOnTheirSceneOrAPreviewObject) {
  const std::string out = (directory_ / "donut.png").string();
  CommandResult run = shadetree("render " + gallery + "donut_bumpy.json -o " + out + " --size 32x32 --spp 4");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("32x32 x 4 spp"), std::string::npos) << run.err;
  for (const char* object : {"sphere", "torus", "plane", "box"}) {
    run = shadetree("render " + gallery + "donut_spotted.json -o " + out + " --size 16x16 --object " + object);
    EXPECT_EQ(run.status, 0) << object << ": " << run.err;
  }
  run = shadetree("render " + gallery + "donut_spotted.json -o " + out + " --size 16x16 --object " + gallery +
                  "meshes/trefoil.obj");
  EXPECT_EQ(run.status, 0) << run.err;
  run = shadetree("render " + gallery + "marble.json -o " + out + " --size 16x16 --object torus");
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("for surface graphs"), std::string::npos) << run.err;
}

TEST_F(Cli, FramesRenderANumberedSequenceFromOneKernel) {
  const std::string pattern = (directory_ / "corona.##.png").string();
  const CommandResult run = shadetree("render " + gallery + "corona.json -o " + pattern + " --size 8x8 --frames 3..5");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"corona.03.png", "corona.04.png", "corona.05.png"}));
  EXPECT_NE(run.err.find("frame 3 of 3"), std::string::npos) << run.err;
  EXPECT_EQ(shadetree("render " + gallery + "corona.json -o " + pattern + " --frames 5..3").status, 2);
}

// --frames with no list renders the graph's render.frames, and says what
// is missing where the graph has none.
TEST_F(Cli, FramesWithNoListRenderTheGraphsRange) {
  std::string text = read_text(gallery + "looping_turbulence.json");
  text.replace(text.find(R"("frames": [0, 47])"), 17, R"("frames": [2, 4])");
  const fs::path graph = write("loop.json", text);
  const std::string pattern = (directory_ / "loop.#.png").string();
  const CommandResult run = shadetree("render " + graph.string() + " -o " + pattern + " --size 8x8 --frames");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"loop.2.png", "loop.3.png", "loop.4.png", "loop.json"}));
  const CommandResult none = shadetree("render " + gallery + "marble.json -o " + pattern + " --size 8x8 --frames");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("marble.json: --frames without a list needs the graph's render.frames [first, last]"),
            std::string::npos)
      << none.err;
}

// A farm task: the chunk of a stepped range, padded numbers, and a resumed
// sequence that renders only the frames not yet written.
TEST_F(Cli, FarmTasksRenderTheirChunkAndResume) {
  const std::string pattern = (directory_ / "corona.####.png").string();
  const std::string shot = "render " + gallery + "corona.json -o " + pattern + " --size 8x8 --frames 1-20x4";
  CommandResult run = shadetree(shot + " --chunk 5-100");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"corona.0005.png", "corona.0009.png", "corona.0013.png",
                                               "corona.0017.png"}));
  const auto written = fs::last_write_time(directory_ / "corona.0009.png");
  run = shadetree(shot + " --skip-existing");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(files().size(), 5u);
  EXPECT_EQ(fs::last_write_time(directory_ / "corona.0009.png"), written) << "an existing frame was rendered again";
  EXPECT_EQ(line_count(run.err), 1) << "one frame left: " << run.err;
  run = shadetree(shot + " --skip-existing");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("all 5 frames exist already"), std::string::npos) << run.err;
  for (const std::string& bad : {shot + " --chunk 30-40", shot + " --chunk 3", std::string("render ") + gallery +
                                 "corona.json -o " + pattern + " --chunk 1-5", shot + "x0"}) {
    run = shadetree(bad);
    EXPECT_EQ(run.status, 2) << bad << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << run.err;
  }
}

TEST_F(Cli, BadScenesExitWithTwoOneLineAndNoOutput) {
  const std::string out = (directory_ / "out.png").string();
  const std::string header = R"({"format": "shadetree-graph", "version": 1, "kind": "surface", "nodes": [],
      "outputs": {"color": [1, 1, 1]}, "render": {"scene": )";
  fs::create_directories(directory_ / "inner");
  std::ofstream(directory_ / "secret.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(directory_ / "broken.obj") << "v 0 0 0\nf 1 2 7\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"objects": [{"type": "teapot"}]})", "unknown type \"teapot\""},
      {R"({"objects": [{"type": "mesh", "file": "missing.obj"}]})", "no such mesh file"},
      {R"({"objects": [{"type": "mesh", "file": "../secret.obj"}]})", "outside the graph's folder"},
      {R"({"objects": [{"type": "mesh", "file": "../broken.obj"}]})", "outside the graph's folder"},
      {R"({"camera": {"position": [0, 0, 0], "target": [0, 0, 0]}, "objects": [{"type": "sphere"}]})", "must differ"},
      {R"({"objects": [{"type": "torus", "minor_radius": 1e39}]})", "32-bit float"}};
  for (const auto& [scene, words] : cases) {
    const fs::path graph = directory_ / "inner" / "scene.json";
    std::ofstream(graph) << header << scene << "}}";
    const CommandResult run = shadetree("render " + graph.string() + " -o " + out + " --size 8x8");
    EXPECT_EQ(run.status, 2) << scene << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << run.err;
    EXPECT_NE(run.err.find(words), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
    // check builds the scene as render does, and refuses it with the same line.
    const CommandResult check = shadetree("check " + graph.string());
    EXPECT_EQ(check.status, 2) << scene << ": " << check.err;
    EXPECT_EQ(check.err, run.err);
  }
  // Allowed by --search-path, the broken mesh is read, and refused for what it is.
  const fs::path graph = directory_ / "inner" / "scene.json";
  std::ofstream(graph) << header << R"({"objects": [{"type": "mesh", "file": "../broken.obj"}]})" << "}}";
  const CommandResult run =
      shadetree("render " + graph.string() + " -o " + out + " --size 8x8 --search-path " + directory_.string());
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("broken.obj"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(shadetree("check " + graph.string() + " --search-path " + directory_.string()).err, run.err);
}

TEST_F(Cli, ImageGraphsReadTheirFilesAndRefuseBadOnes) {
  const std::string out = (directory_ / "out.png").string();
  fs::create_directories(directory_ / "inner");
  std::ofstream(directory_ / "inner" / "broken.png") << "not a png";
  ASSERT_TRUE(write_image(Image{2, 1, 3, {0.25f, 0.5f, 1.0f, 1.0f, 0.5f, 0.25f}}, (directory_ / "outside.exr").string()).ok());
  // A real PNG cut short in its pixel data: libpng has its own say on
  // stderr, which must not add a line to the error (regression).
  Image ramp{64, 64, 3, {}};
  for (int i = 0; i < 64 * 64 * 3; ++i) ramp.pixels.push_back(static_cast<float>((i * 37) % 101) / 100.0f);
  const fs::path whole = directory_ / "whole.png";
  ASSERT_TRUE(write_image(ramp, whole.string()).ok());
  fs::copy_file(whole, directory_ / "inner" / "truncated.png");
  fs::resize_file(directory_ / "inner" / "truncated.png", fs::file_size(whole) / 2);
  auto graph_naming = [&](const std::string& file) {
    const fs::path graph = directory_ / "inner" / "image.json";
    std::ofstream(graph) << R"({"format": "shadetree-graph", "version": 1, "kind": "texture", "nodes": [
        {"id": "uv", "op": "uv"}, {"id": "img", "op": "image", "in": {"uv": "uv"}, "file": ")" << file << R"("}],
        "outputs": {"color": "img"}})";
    return graph.string();
  };
  for (const char* file : {"missing.png", "broken.png", "truncated.png", "../outside.exr"}) {
    const CommandResult run = shadetree("render " + graph_naming(file) + " -o " + out + " --size 8x8");
    EXPECT_EQ(run.status, 2) << file << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << run.err;
    EXPECT_EQ(run.err.find("\\n"), std::string::npos) << "no escaped second line: " << run.err;
    EXPECT_NE(run.err.find("node \"img\""), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // Allowed by --search-path, the image is read: its left pixel at uv (0.25, 0.5).
  const std::string graph = graph_naming("../outside.exr");
  ASSERT_EQ(shadetree("check " + graph + " --search-path " + directory_.string()).status, 0);
  const CommandResult run = shadetree("eval " + graph + " --at 0,0,0 --input uv=0.25,0.5 --search-path " + directory_.string());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["outputs"]["color"], nlohmann::json::parse("[0.25, 0.5, 1.0]"));
  EXPECT_EQ(shadetree("render " + graph + " -o " + out + " --size 8x8 --search-path " + directory_.string()).status, 0);
  EXPECT_TRUE(fs::exists(out));
}

TEST_F(Cli, VolumeGraphsRenderThroughTheRayMarcher) {
  const std::string out = (directory_ / "sphere.png").string();
  const CommandResult run = shadetree("render " + gallery + "noisy_sphere.json -o " + out + " --size 24x24 --step 0.05");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("24x24, "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("density samples"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("lanes in use"), std::string::npos) << run.err;
  Result<Image> image = read_image(out);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->width, 24);
}

// --shadows: cached (the default) reads the lights' transmittance grids,
// exact marches shadow rays, off has neither; --no-shadows is off, and
// other kinds refuse the option as they refuse --step.
TEST_F(Cli, ShadowModesOfTheRayMarcher) {
  const std::string out = (directory_ / "sphere.png").string();
  const std::string render = "render " + gallery + "noisy_sphere.json -o " + out + " --size 24x24 --step 0.05";
  for (const auto& [options, grids] : {std::pair{"", true}, std::pair{"--shadows cached", true},
                                       std::pair{"--shadows exact", false}, std::pair{"--shadows off", false},
                                       std::pair{"--no-shadows", false}}) {
    const CommandResult run = shadetree(render + " " + options);
    ASSERT_EQ(run.status, 0) << options << ": " << run.err;
    EXPECT_EQ(run.err.find("shadow grids of ") != std::string::npos, grids) << options << ": " << run.err;
    const bool off = std::string(options).find("off") != std::string::npos ||
                     std::string(options).find("no-shadows") != std::string::npos;
    EXPECT_EQ(run.err.find(", 0 for shadow rays") != std::string::npos, off) << options << ": " << run.err;
  }
  for (const char* options : {"--shadows sometimes", "--shadows exact --no-shadows", "--shadows 'exact\nx'"}) {
    const CommandResult run = shadetree(render + " " + options);
    EXPECT_EQ(run.status, 2) << options << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << options << ": " << run.err;
  }
  const CommandResult texture = shadetree("render " + gallery + "marble.json -o " + out + " --size 8x8 --shadows off");
  EXPECT_EQ(texture.status, 2);
  EXPECT_NE(texture.err.find("--shadows is for surface or volume graphs; this is a texture graph"), std::string::npos)
      << texture.err;
}

// --normals exact halves the reference marcher's gradient samples (one
// sample of the normal kernel instead of two probes, where it probes
// every sample lit); it is for volume graphs only.
TEST_F(Cli, NormalsOfTheRayMarcher) {
  const std::string out = (directory_ / "sphere.png").string();
  const std::string render =
      "render " + gallery + "noisy_sphere.json -o " + out + " --size 24x24 --step 0.05 --shadows exact";
  auto gradient_samples = [](const std::string& err) {
    const auto end = err.find(" for gradients");
    const auto start = err.rfind('(', end);
    return std::stol(err.substr(start + 1, end - start - 1));
  };
  const CommandResult probes = shadetree(render + " --normals probes");
  const CommandResult exact = shadetree(render + " --normals exact");
  ASSERT_EQ(probes.status, 0) << probes.err;
  ASSERT_EQ(exact.status, 0) << exact.err;
  EXPECT_EQ(gradient_samples(exact.err) * 2, gradient_samples(probes.err)) << exact.err << probes.err;
  for (const std::string& bad : {render + " --normals analytic",
                                 "render " + gallery + "marble.json -o " + out + " --size 8x8 --normals exact"}) {
    const CommandResult run = shadetree(bad);
    EXPECT_EQ(run.status, 2) << bad << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << run.err;
  }
}

TEST_F(Cli, BadVolumesExitWithTwoOneLineAndNoOutput) {
  const std::string out = (directory_ / "out.png").string();
  const std::string bounded = R"("volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "needs render.volume"},
      {R"("volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "step": 0})", "step must be positive"},
      {R"("volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "step": 1e-6})", "too small"},
      {R"("volume": {"bounds": {"min": [-1, -1, -1], "max": [-1, 1, 1]}})", "empty"},
      {bounded + R"(, "scene": {"objects": [{"type": "sphere", "radius": 0}]})", "radius must be positive"}};
  for (const auto& [render, words] : cases) {
    const fs::path graph = write("volume.json", R"({"format": "shadetree-graph", "version": 1, "kind": "volume",
        "nodes": [], "outputs": {"density": 0.5}, "render": {)" + render + "}}");
    const CommandResult run = shadetree("render " + graph.string() + " -o " + out + " --size 8x8");
    EXPECT_EQ(run.status, 2) << render << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << run.err;
    EXPECT_NE(run.err.find(words), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
    // What render refuses in a graph, check refuses with the same line.
    const CommandResult check = shadetree("check " + graph.string());
    EXPECT_EQ(check.status, 2) << render << ": " << check.err;
    EXPECT_EQ(check.err, run.err);
  }
  const fs::path graph = write("volume.json", R"({"format": "shadetree-graph", "version": 1, "kind": "volume",
      "nodes": [], "outputs": {"density": 0.5}, "render": {)" + bounded + "}}");
  for (const std::string& options : {"--step 0", "--step -1", "--step 1e-7", "--spp 4", "--object torus"}) {
    const CommandResult run = shadetree("render " + graph.string() + " -o " + out + " --size 8x8 " + options);
    EXPECT_EQ(run.status, 2) << options << ": " << run.err;
    EXPECT_EQ(line_count(run.err), 1) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
  EXPECT_EQ(shadetree("render " + gallery + "marble.json -o " + out + " --size 8x8 --step 0.1").status, 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, VoxelizeWritesAVdbFileOrExitsWithTwo) {
  const std::string out = (directory_ / "sphere.vdb").string();
  const CommandResult run = shadetree("voxelize " + gallery + "noisy_sphere.json -o " + out + " --res 16");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("16x16x16 voxels"), std::string::npos) << run.err;
  Result<VoxelGrid> grid = read_vdb(out);
  ASSERT_TRUE(grid.ok()) << grid.error().to_string();
  EXPECT_GT(*std::max_element(grid->density.begin(), grid->density.end()), 0.9f);
  fs::remove(out);
  for (const std::string& arguments : {gallery + "marble.json -o " + out, gallery + "noisy_sphere.json -o " +
                                       (directory_ / "sphere.png").string(),
                                       gallery + "noisy_sphere.json -o " + out + " --res 0",
                                       gallery + "noisy_sphere.json -o " + out + " --res 100000"}) {
    const CommandResult bad = shadetree("voxelize " + arguments);
    EXPECT_EQ(bad.status, 2) << arguments << ": " << bad.err;
    EXPECT_EQ(line_count(bad.err), 1) << bad.err;
  }
  EXPECT_EQ(files(), std::vector<std::string>{});
}

// bake writes each map the graph gives (the normal derived from its
// height), 16-bit PNGs by default, and a sidecar naming them; with
// --normal-convention directx the green channel of the normal map flips.
TEST_F(Cli, BakeWritesATextureSetWithItsSidecar) {
  const std::string stones = gallery + "tileable_stones.json";
  CommandResult run = shadetree("bake " + stones + " -o " + directory_.string() + " --size 32x32 --domain 0,0,4,4");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("4 maps of 32x32 (color, height, normal, roughness), tileable"), std::string::npos) << run.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"tileable_stones.json", "tileable_stones_color.png",
                                               "tileable_stones_height.png", "tileable_stones_normal.png",
                                               "tileable_stones_roughness.png"}));
  const nlohmann::json sidecar = nlohmann::json::parse(read_text(directory_ / "tileable_stones.json"));
  EXPECT_EQ(sidecar["tileable"], true);
  EXPECT_EQ(sidecar["maps"]["normal"]["convention"], "opengl");
  EXPECT_EQ(sidecar["maps"]["normal"]["from_height"]["strength"], 1.0);
  EXPECT_EQ(sidecar["maps"]["height"]["units"], "P");
  Result<Image> opengl = read_image((directory_ / "tileable_stones_normal.png").string());
  ASSERT_TRUE(opengl.ok());
  EXPECT_EQ(opengl->channels, 3);

  run = shadetree("bake " + stones + " -o " + directory_.string() +
                  " --size 32x32 --domain 0,0,4,4 --maps normal --normal-convention directx --name dx --format exr");
  ASSERT_EQ(run.status, 0) << run.err;
  Result<Image> directx = read_image((directory_ / "dx_normal.exr").string());
  ASSERT_TRUE(directx.ok());
  for (std::size_t i = 0; i < directx->pixels.size(); i += 3) {
    EXPECT_NEAR(directx->pixels[i], opengl->pixels[i], 1.0f / 65535 + 1e-6f);
    EXPECT_NEAR(directx->pixels[i + 1], 1.0f - opengl->pixels[i + 1], 1.0f / 65535 + 1e-6f);
  }
  // Over a domain that is not a whole number of periods, the set does not tile.
  run = shadetree("bake " + stones + " -o " + directory_.string() + " --size 32x32 --domain 0,0,3,3 --name part --maps color");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("not tileable"), std::string::npos) << run.err;
}

// The files bake writes, read back: the normal map is the slope of the
// height map (central differences over its pixels, on a smooth height).
TEST_F(Cli, ABakedNormalMapReadBackIsTheSlopeOfTheBakedHeightMap) {
  const fs::path graph = write("hills.json", R"({"format": "shadetree-graph", "version": 1, "kind": "texture",
      "name": "hills", "nodes": [{"id": "p", "op": "P"}, {"id": "n", "op": "pnoise", "in": {"p": "p"}},
        {"id": "h", "op": "mul", "in": {"a": "n", "b": 0.25}}],
      "outputs": {"color": "h", "height": "h"}})");
  const CommandResult run =
      shadetree("bake " + graph.string() + " -o " + directory_.string() + " --size 128x128 --domain 0,0,4,4 --format exr");
  ASSERT_EQ(run.status, 0) << run.err;
  Result<Image> height = read_image((directory_ / "hills_height.exr").string());
  Result<Image> normal = read_image((directory_ / "hills_normal.exr").string());
  ASSERT_TRUE(height.ok() && normal.ok());
  constexpr int size = 128;
  const double pixel = 4.0 / size;
  auto h = [&](int row, int column) {
    return double(height->pixels[static_cast<std::size_t>(((row + size) % size) * size + (column + size) % size)]);
  };
  double worst = 0;
  for (int row = 0; row < size; ++row)
    for (int column = 0; column < size; ++column) {
      const double dx = (h(row, column + 1) - h(row, column - 1)) / (2 * pixel);
      const double dy = -(h(row + 1, column) - h(row - 1, column)) / (2 * pixel);  // rows run down
      const double length = std::sqrt(dx * dx + dy * dy + 1);
      const float* encoded = &normal->pixels[static_cast<std::size_t>(row * size + column) * 3];
      worst = std::max({worst, std::fabs(2 * encoded[0] - 1 + dx / length), std::fabs(2 * encoded[1] - 1 + dy / length),
                        std::fabs(2 * encoded[2] - 1 - 1 / length)});
    }
  EXPECT_LT(worst, 1e-2);
}

TEST_F(Cli, BakeRefusesBadRequestsInOneLineAndWritesNothing) {
  const fs::path out = directory_ / "set";
  fs::create_directory(out);
  const std::string stones = gallery + "tileable_stones.json -o " + out.string();
  const std::pair<std::string, int> cases[] = {
      {gallery + "noisy_sphere.json -o " + out.string(), 2},           // not a texture graph
      {gallery + "marble.json -o " + out.string() + " --maps height", 2},  // an output it does not give
      {stones + " --maps colour", 2},
      {stones + " --size 0x4", 2},
      {stones + " --size 100000x4", 2},
      {stones + " --domain 4,0,0,4", 2},
      {stones + " --domain 0,0,nan,4", 2},
      {stones + " --normal-strength -1", 2},
      {stones + " --normal-strength inf", 2},
      {stones + " --format tiff", 2},
      {gallery + "tileable_stones.json -o " + (directory_ / "absent").string(), 1},
      {gallery + "tileable_stones.json -o " + gallery + "marble.json", 1},
  };
  for (const auto& [arguments, status] : cases) {
    const bool sized = arguments.find("--size") != std::string::npos;
    const CommandResult bad = shadetree("bake " + arguments + (sized ? "" : " --size 8x8"));
    EXPECT_EQ(bad.status, status) << arguments << ": " << bad.err;
    EXPECT_EQ(line_count(bad.err), 1) << arguments << ": " << bad.err;
  }
  EXPECT_TRUE(fs::is_empty(out));
}

TEST_F(Cli, RenderWritesTheImageAndASummary) {
  const std::string out = (directory_ / "marble.png").string();
  const CommandResult run = shadetree("render " + gallery + "marble.json -o " + out + " --size 32x16 --threads 2");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.err.find("32x16, 512 samples"), std::string::npos) << run.err;
  EXPECT_EQ(files(), std::vector<std::string>{"marble.png"});
  Result<Image> image = read_image(out);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->width, 32);
  EXPECT_EQ(image->height, 16);
}

// eval at a pixel's sample point prints exactly what render stored there.
TEST_F(Cli, EvalAgreesWithTheRenderedPixel) {
  const std::string out = (directory_ / "marble.exr").string();
  ASSERT_EQ(shadetree("render " + gallery + "marble.json -o " + out + " --size 24x24 --set scale=7").status, 0);
  Result<Image> image = read_image(out);
  ASSERT_TRUE(image.ok());
  TextureView view;
  view.width = view.height = 24;
  view.domain_max[0] = view.domain_max[1] = 2.0f;  // marble.json's render domain
  for (auto [column, row] : {std::pair{5, 7}, std::pair{0, 0}, std::pair{23, 11}}) {
    const TextureSample sample = texture_sample_at_pixel(view, column, row);
    std::ostringstream at;
    at.precision(9);
    at << sample.P[0] << "," << sample.P[1] << "," << sample.P[2];
    const CommandResult run = shadetree("eval " + gallery + "marble.json --size 24x24 --set scale=7 --at " + at.str());
    ASSERT_EQ(run.status, 0) << run.err;
    const auto result = nlohmann::json::parse(run.out);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(result["outputs"]["color"][c].get<float>(), image->pixels[(row * 24 + column) * 3 + c])
          << "pixel " << column << "," << row << " channel " << c;
  }
}

// For an environment, --at is the direction: eval there prints what the
// panorama shows (to rounding: eval normalizes the direction again).
TEST_F(Cli, EvalOfAnEnvironmentLooksInTheDirectionGiven) {
  const std::string out = (directory_ / "sky.exr").string();
  ASSERT_EQ(shadetree("render " + gallery + "sunset_sky.json -o " + out + " --size 32x16").status, 0);
  Result<Image> image = read_image(out);
  ASSERT_TRUE(image.ok());
  for (auto [column, row] : {std::pair{3, 2}, std::pair{20, 7}, std::pair{31, 12}}) {
    const glm::vec3 direction = panorama_direction(column + 0.5f, row + 0.5f, 32, 16);
    std::ostringstream at;
    at.precision(9);
    at << direction.x << "," << direction.y << "," << direction.z;
    const CommandResult run = shadetree("eval " + gallery + "sunset_sky.json --size 32x16 --at " + at.str());
    ASSERT_EQ(run.status, 0) << run.err;
    const auto result = nlohmann::json::parse(run.out);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(result["outputs"]["color"][c].get<float>(), image->pixels[(row * 32 + column) * 3 + c], 1e-4f)
          << "pixel " << column << "," << row << " channel " << c;
    EXPECT_NEAR(result["filter_width"].get<float>(), 3.14159265f / 16.0f, 1e-6f);
  }
}

TEST_F(Cli, BackendsRenderTheSameImage) {
  const std::string jit = (directory_ / "jit.exr").string(), interp = (directory_ / "interp.exr").string();
  ASSERT_EQ(shadetree("render " + gallery + "corona.json -o " + jit + " --size 37x29 --frame 5").status, 0);
  ASSERT_EQ(shadetree("render " + gallery + "corona.json -o " + interp + " --size 37x29 --frame 5 --backend interp")
                .status,
            0);
  Result<Image> a = read_image(jit), b = read_image(interp);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->pixels.size(), b->pixels.size());
  for (std::size_t i = 0; i < a->pixels.size(); ++i) ASSERT_NEAR(a->pixels[i], b->pixels[i], 1e-5f) << i;
}

// The JIT is a module (jit/jit_module.h): a shadetree without it still
// checks and interprets, and says why it cannot compile.
TEST_F(Cli, WithoutTheJitModuleGraphsAreCheckedAndInterpreted) {
  const fs::path alone = directory_ / "bin" / "shadetree";
  fs::create_directories(alone.parent_path());
  fs::copy_file(SHADETREE_BINARY, alone);
  CommandResult run = shadetree("check " + gallery + "marble.json", alone);
  EXPECT_EQ(run.status, 0) << run.err;
  const std::string image = (directory_ / "marble.png").string();
  run = shadetree("render " + gallery + "marble.json -o " + image + " --size 16x16", alone);
  EXPECT_EQ(run.status, 0) << run.err;  // tiered: on the interpreter throughout
  EXPECT_TRUE(fs::exists(image));
  run = shadetree("render " + gallery + "marble.json -o " + image + ".2.png --size 16x16 --backend jit", alone);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("cannot load the JIT (" + (alone.parent_path() / "libshadetree_jit.so").string()),
            std::string::npos)
      << run.err;
  run = shadetree("emit " + gallery + "marble.json --asm", alone);
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("(--backend interp still works)"), std::string::npos) << run.err;
}

TEST_F(Cli, EmitShowsTheOptimizedGraphAndVectorCode) {
  CommandResult run = shadetree("emit " + gallery + "marble.json --graph");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("turbulence"), std::string::npos);
  EXPECT_NE(run.out.find("output color: color"), std::string::npos);
  run = shadetree("emit " + gallery + "marble.json --llvm --width 8");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("<8 x float>"), std::string::npos);
  run = shadetree("emit " + gallery + "marble.json --asm --width 8");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("ymm"), std::string::npos);
  run = shadetree("emit " + gallery + "marble.json");
  EXPECT_EQ(run.status, 2);
}

TEST_F(Cli, EmitGlslWritesAShaderOrSaysWhyNot) {
  const std::string shader = (directory_ / "marble.frag").string();
  CommandResult run = shadetree("emit " + gallery + "marble.json --glsl --name stone -o " + shader);
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string text = read_text(shader);
  for (const char* part : {"#version 300 es", "uniform int u_octaves;", "void stone(", "void main()"})
    EXPECT_NE(text.find(part), std::string::npos) << part;
  run = shadetree("emit " + gallery + "marble.json --glsl --shadertoy");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("void mainImage("), std::string::npos);
  EXPECT_NE(run.out.find("const int u_octaves = 8;"), std::string::npos);
  run = shadetree("emit " + gallery + "composite.json --glsl -o " + shader + ".2");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("node \"footage\""), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(shader + ".2"));
  run = shadetree("emit " + gallery + "marble.json --shadertoy");
  EXPECT_EQ(run.status, 2);
  run = shadetree("emit " + gallery + "marble.json --graph -o " + shader);
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
}

TEST_F(Cli, EmitCppWritesAHeaderOrSaysWhyNot) {
  const std::string header = (directory_ / "kernel.h").string();
  CommandResult run = shadetree("emit " + gallery + "marble.json --cpp --name stone -o " + header);
  ASSERT_EQ(run.status, 0) << run.err;
  std::ifstream file(header);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for (const char* part : {"struct stone_params", "int octaves = 8;", "struct stone_inputs", "inline void stone_run("})
    EXPECT_NE(text.find(part), std::string::npos) << part;
  run = shadetree("emit " + gallery + "marble.json --cpp");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("inline void marble_run("), std::string::npos) << "the graph's name by default, on stdout";
  run = shadetree("emit " + gallery + "marble.json --cpp --name 2x");
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("must be an identifier"), std::string::npos) << run.err;
  const std::string nowhere = (directory_ / "missing" / "kernel.h").string();
  run = shadetree("emit " + gallery + "marble.json --cpp -o " + nowhere);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_FALSE(fs::exists(nowhere));
}

TEST_F(Cli, BenchPrintsTheDocumentedJsonKeys) {
  const CommandResult run =
      shadetree("bench " + gallery + "checker_aa.json " + gallery + "spotted.json --size 32x32 --repetitions 1 --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto results = nlohmann::json::parse(run.out);
  ASSERT_EQ(results.size(), 2u);
  for (const char* key : {"graph", "samples", "nodes_before", "nodes_after", "compile_ms_cold", "compile_ms_cached",
                          "compile_stages_ms", "compile_modules", "interp_sps_1t", "interp_sps_mt", "jit_sps_1t",
                          "jit_sps_mt", "cpu", "jit_cpu", "jit_width", "jit_gathers"})
    EXPECT_TRUE(results[0].contains(key)) << key;
  EXPECT_EQ(results[0]["graph"], "checker_aa");
  EXPECT_EQ(results[1]["samples"], 1024);
  EXPECT_GT(results[1]["jit_sps_1t"].get<double>(), 0.0);
}

// --compiles N: the median of N cold compiles, between the fastest and
// the slowest of them; none is a usage error.
TEST_F(Cli, BenchReportsTheMedianOfItsColdCompiles) {
  const CommandResult run =
      shadetree("bench " + gallery + "checker_aa.json --size 16x16 --repetitions 1 --compiles 3 --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto result = nlohmann::json::parse(run.out)[0];
  const double fastest = result["compile_ms_cold_fastest"].get<double>();
  const double slowest = result["compile_ms_cold_slowest"].get<double>();
  const double median = result["compile_ms_cold"].get<double>();
  EXPECT_GT(fastest, 0.0);
  EXPECT_LE(fastest, median);
  EXPECT_LE(median, slowest);
  const CommandResult none = shadetree("bench " + gallery + "checker_aa.json --size 16x16 --compiles 0");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--compiles"), std::string::npos) << none.err;
}

// A cold compile's stages, each the median of the compiles: one module
// compiled on one thread spends no more in them than the compile took.
TEST_F(Cli, BenchBreaksItsColdCompilesIntoStages) {
  const CommandResult run = shadetree("bench " + gallery +
                                      "checker_aa.json --size 16x16 --repetitions 1 --compiles 1 --width 8 --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto result = nlohmann::json::parse(run.out)[0];
  const auto& stages = result["compile_stages_ms"];
  double total = 0.0;
  for (const char* stage : {"emit", "optimize", "generate"}) {
    EXPECT_GT(stages[stage].get<double>(), 0.0) << stage;
    total += stages[stage].get<double>();
  }
  EXPECT_LE(total, result["compile_ms_cold"].get<double>());
  EXPECT_EQ(result["compile_modules"], 1);
}

// A driver's table row is as long as its graph's name: a name longer
// than the row's fixed buffer once wrote past it (a crash).
TEST_F(Cli, BenchTablesAGraphOfAnyNameLength) {
  std::ifstream gallery_file(gallery + "noisy_sphere.json");
  nlohmann::json graph = nlohmann::json::parse(gallery_file);
  const std::string name(3000, 'n');
  graph["name"] = name;
  const fs::path file = write("long_name.json", graph.dump());
  const CommandResult run = shadetree("bench " + file.string() + " --size 8x8 --repetitions 1");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find(name + " jit"), std::string::npos) << "the volume driver's row names the graph whole";
}

// Quick kernels are never cached, so they have no cached compile time.
TEST_F(Cli, BenchMeasuresQuickKernels) {
  const CommandResult run = shadetree("bench " + gallery + "marble.json --size 16x16 --repetitions 1 --json --quick");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto result = nlohmann::json::parse(run.out)[0];
  EXPECT_TRUE(result["compile_ms_cached"].is_null());
  EXPECT_GT(result["compile_ms_cold"].get<double>(), 0.0);
  EXPECT_GT(result["jit_sps_1t"].get<double>(), 0.0);
}

// Kernels of any width are measured, and say so; other widths are usage
// errors.
TEST_F(Cli, BenchMeasuresTheKernelsOfAGivenWidth) {
  for (const char* width : {"4", "8"}) {
    const CommandResult run = shadetree("bench " + gallery + "marble.json --size 16x16 --repetitions 1 --json --width " +
                                        width + " --gathers per-lane");
    ASSERT_EQ(run.status, 0) << run.err;
    const auto result = nlohmann::json::parse(run.out)[0];
    EXPECT_GT(result["jit_sps_1t"].get<double>(), 0.0) << width;
    EXPECT_EQ(result["jit_width"], std::stoi(width));
    EXPECT_EQ(result["jit_gathers"], "per-lane");
  }
  const CommandResult odd = shadetree("bench " + gallery + "marble.json --size 16x16 --width 3");
  EXPECT_EQ(odd.status, 2);
  EXPECT_NE(odd.err.find("--width"), std::string::npos) << odd.err;
}

TEST_F(Cli, BenchMarchesVolumeGraphs) {
  const CommandResult run =
      shadetree("bench " + gallery + "noisy_sphere.json --size 32x32 --repetitions 1 --threads 2 --json");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto marcher = nlohmann::json::parse(run.out)[0]["driver"];
  ASSERT_EQ(marcher.size(), 4u);  // jit and interp, at 1 and 2 threads
  for (const char* key : {"backend", "threads", "rays", "density_samples", "lane_utilisation", "kernel_s", "march_s",
                          "total_s", "kernel_sps", "kernel_vs_texture_samples"})
    EXPECT_TRUE(marcher[0].contains(key)) << key;
  EXPECT_GT(marcher[0]["density_samples"].get<long>(), 32 * 32);
  EXPECT_GT(marcher[0]["lane_utilisation"].get<double>(), 0.5);
}

TEST_F(Cli, NodesMarkdownIsTheCommittedReference) {
  const CommandResult run = shadetree("nodes --markdown");
  ASSERT_EQ(run.status, 0);
  EXPECT_EQ(run.out, read_text(SHADETREE_SOURCE_DIR "/docs/nodes.md"))
      << "docs/nodes.md is stale: regenerate it with build/shadetree nodes --markdown > docs/nodes.md";
}

TEST_F(Cli, SchemaEnumeratesEveryOp) {
  const CommandResult run = shadetree("schema");
  ASSERT_EQ(run.status, 0);
  const auto schema = nlohmann::json::parse(run.out);
  const auto& names = schema["$defs"]["node"]["properties"]["op"]["anyOf"][0]["enum"];
  EXPECT_EQ(names.size(), all_ops().size());
  ASSERT_EQ(schema["oneOf"].size(), std::size(all_graph_kinds));  // a variant per kind
  for (const auto& variant : schema["oneOf"]) EXPECT_EQ(variant["properties"]["version"]["const"], graph_format_version);
}

// Issue 21: --frame nan/inf and --step inf were accepted.
TEST_F(Cli, NumberOptionsRefuseNanAndInfinity) {
  const std::string out = (directory_ / "out.png").string();
  for (const std::string& option : {"--frame nan", "--frame inf", "--frame -inf", "--frame 0x10"}) {
    const CommandResult run = shadetree("render " + gallery + "marble.json -o " + out + " --size 8x8 " + option);
    EXPECT_EQ(run.status, 2) << option << ": " << run.err;
    EXPECT_NE(run.err.find("finite decimal number"), std::string::npos) << option << ": " << run.err;
  }
  for (const std::string& option : {"--step inf", "--step nan"}) {
    const CommandResult run = shadetree("render " + gallery + "fireball.json -o " + out + " --size 8x8 " + option);
    EXPECT_EQ(run.status, 2) << option << ": " << run.err;
  }
  EXPECT_EQ(shadetree("eval " + gallery + "marble.json --at 0,0,0 --frame nan").status, 2);
  EXPECT_TRUE(files().empty());
}

// Issue 21: check's "ok:" line printed graph names raw (newlines, escapes);
// a failed --object printed the "replaces the graph's scene" note too.
TEST_F(Cli, CheckPrintsNamesOnOneLineAndObjectFailuresAreOneLine) {
  std::string marble = read_text(gallery + "marble.json");
  marble.replace(marble.find("\"name\": \"marble\""), 16, "\"name\": \"two\\nlines \\u001b[2J\"");
  const CommandResult check = shadetree("check " + write("named.json", marble).string());
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(check.out.find("two\\nlines \\x1b[2J"), check.out.find("two")) << check.out;
  EXPECT_EQ(std::count(check.out.begin(), check.out.end(), '\n'), 1) << check.out;
  const CommandResult run = shadetree("render " + gallery + "marble_vase.json -o " + (directory_ / "o.png").string() +
                                      " --size 8x8 --object " + (directory_ / "missing.obj").string());
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

// A hostile-input pass found emit --graph printing node ids raw: a line
// break split an instruction's line, an escape sequence reached the
// terminal.
TEST_F(Cli, EmitListingsPrintNodeIdsOnOneLine) {
  const fs::path graph = write("ids.json", R"({"format": "shadetree-graph", "version": 1, "kind": "texture",
      "nodes": [{"id": "p\n%9 = evil \u001b[2J", "op": "P"}, {"id": "s", "op": "split", "in": {"v": "p\n%9 = evil \u001b[2J"}},
                {"id": "c", "op": "color", "in": {"r": "s.x"}}], "outputs": {"color": "c"}})");
  const CommandResult run = shadetree("emit " + graph.string() + " --graph");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(run.out.find('\x1b'), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("; p\\n%9 = evil \\x1b[2J\n"), std::string::npos) << run.out;
  for (std::size_t at = run.out.find('\n'); at != std::string::npos; at = run.out.find('\n', at + 1))
    EXPECT_NE(run.out.compare(at + 1, 3, "%9 "), 0) << run.out;
}

}  // namespace
}  // namespace shadetree
