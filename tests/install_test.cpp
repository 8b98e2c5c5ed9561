// The installed package: `cmake --install` of this build into a temporary
// prefix, then examples/ configured with find_package(shadetree) against
// it, built, and run on gallery graphs (the C API renders a PNG and finds
// a volume's empty space, the C++ stages evaluate a graph).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "io/image_output.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;

// Runs `command`; its exit status, and its output (stdout and stderr) in `output`.
int run(const std::string& command, std::string* output) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen((command + " 2>&1").c_str(), "r"), ::pclose);
  char buffer[4096];
  while (std::size_t read = std::fread(buffer, 1, sizeof buffer, pipe.get())) output->append(buffer, read);
  const int status = ::pclose(pipe.release());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Install, ExamplesBuildAgainstTheInstalledPackageAndRun) {
  const fs::path root = fs::temp_directory_path() / "shadetree-install-test";
  fs::remove_all(root);
  const fs::path prefix = root / "prefix", build = root / "build";
  std::string log;
  ASSERT_EQ(run(std::string(SHADETREE_CMAKE) + " --install " SHADETREE_BUILD_DIR " --prefix " + prefix.string(), &log), 0)
      << log;
  EXPECT_TRUE(fs::exists(prefix / "include" / "shadetree.h"));
  EXPECT_TRUE(fs::exists(prefix / "include" / "shadetree" / "pipeline" / "compile_graph.h"));
  log.clear();
  ASSERT_EQ(run(std::string(SHADETREE_CMAKE) + " -S " SHADETREE_SOURCE_DIR "/examples -B " + build.string() +
                    " -G Ninja -DCMAKE_PREFIX_PATH=" + prefix.string() + " -DCMAKE_C_FLAGS='" SHADETREE_EXAMPLE_FLAGS
                    "' -DCMAKE_CXX_FLAGS='" SHADETREE_EXAMPLE_FLAGS "'",
                &log),
            0)
      << log;
  log.clear();
  ASSERT_EQ(run(std::string(SHADETREE_CMAKE) + " --build " + build.string(), &log), 0) << log;

  const fs::path png = root / "marble.png";
  log.clear();
  ASSERT_EQ(run((build / "render_texture").string() + " " SHADETREE_SOURCE_DIR "/graphs/marble.json " + png.string() +
                    " 48 scale=9",
                &log),
            0)
      << log;
  Result<Image> image = read_image(png.string());
  ASSERT_TRUE(image.ok()) << image.error().to_string();
  EXPECT_EQ(image->width, 48);
  EXPECT_EQ(image->channels, 4);

  log.clear();
  EXPECT_EQ(run((build / "render_texture").string() + " " SHADETREE_SOURCE_DIR "/graphs/marble.json " + png.string() +
                    " 48 scale=-5",
                &log),
            2)
      << "a param out of range: " << log;
  EXPECT_NE(log.find("scale"), std::string::npos) << log;

  // The noisy sphere reaches about 1.35 from its centre: of 16^3 boxes of
  // [-1.4, 1.4]^3 the corners' are certainly empty (IntervalProgram.
  // NoisySphereSkipsTheBricksBeyondItsBumps finds 1639 of 4096 in its bounds).
  log.clear();
  ASSERT_EQ(run((build / "empty_space").string() + " " SHADETREE_SOURCE_DIR "/graphs/noisy_sphere.json 1.4 16", &log), 0)
      << log;
  EXPECT_NE(log.find(" of 4096 boxes of [-1.4, 1.4]^3 certainly empty"), std::string::npos) << log;
  EXPECT_GT(std::atol(log.c_str()), 1000) << log;
  log.clear();
  EXPECT_EQ(run((build / "empty_space").string() + " " SHADETREE_SOURCE_DIR "/graphs/marble.json 1 4", &log), 2) << log;
  EXPECT_NE(log.find("not a volume graph"), std::string::npos) << log;

  log.clear();
  ASSERT_EQ(run((build / "evaluate_graph").string() + " " SHADETREE_SOURCE_DIR "/graphs/marble.json", &log), 0) << log;
  EXPECT_NE(log.find("sample 3:"), std::string::npos) << log;
  fs::remove_all(root);
}

}  // namespace
}  // namespace shadetree
