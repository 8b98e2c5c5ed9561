// The `image` op: bilinear lookups of an image file (nodes/semantics/
// splines.h), its layout by the checker, and image files read from disk.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <stdlib.h>
#include <unistd.h>

#include "interp/interpreter.h"
#include "nodes/semantics/splines.h"
#include "pipeline/compile_graph.h"
#include "io/graph_files.h"
#include "io/image_output.h"
#include "support/graph_text.h"
#include "support/test_files.h"
#include "support/temp_folder.h"

namespace shadetree {
namespace {

namespace fs = std::filesystem;
using semantics::ImageWrap;

// A 2 x 2 RGB image, bottom row first: red channel 0, 1 / 2, 3.
const float rgb[] = {0, 10, 20, 1, 11, 21, 2, 12, 22, 3, 13, 23};

TEST(ImageLookup, PixelCentresGiveThePixels) {
  EXPECT_EQ(semantics::image(rgb, 2, 2, ImageWrap::clamp, 0.25f, 0.25f).x, 0.0f);
  EXPECT_EQ(semantics::image(rgb, 2, 2, ImageWrap::clamp, 0.75f, 0.25f).x, 1.0f);
  EXPECT_EQ(semantics::image(rgb, 2, 2, ImageWrap::clamp, 0.25f, 0.75f).x, 2.0f);
  EXPECT_EQ(semantics::image(rgb, 2, 2, ImageWrap::clamp, 0.75f, 0.75f).z, 23.0f);
}

TEST(ImageLookup, CentreOfFourPixelsIsTheirMean) {
  const auto centre = semantics::image(rgb, 2, 2, ImageWrap::repeat, 0.5f, 0.5f);
  EXPECT_FLOAT_EQ(centre.x, 1.5f);
  EXPECT_FLOAT_EQ(centre.y, 11.5f);
  EXPECT_FLOAT_EQ(centre.z, 21.5f);
}

// At u = 0 the lookup lies between the last column and the first when the
// image repeats, and on the first column when it is clamped.
TEST(ImageLookup, EdgesRepeatOrClamp) {
  EXPECT_FLOAT_EQ(semantics::image(rgb, 2, 2, ImageWrap::repeat, 0.0f, 0.25f).x, 0.5f);
  EXPECT_FLOAT_EQ(semantics::image(rgb, 2, 2, ImageWrap::clamp, 0.0f, 0.25f).x, 0.0f);
  EXPECT_FLOAT_EQ(semantics::image(rgb, 2, 2, ImageWrap::repeat, 1.75f, 0.25f).x, 1.0f);
  EXPECT_FLOAT_EQ(semantics::image(rgb, 2, 2, ImageWrap::repeat, -0.25f, 0.25f).x, 1.0f);
  EXPECT_FLOAT_EQ(semantics::image(rgb, 2, 2, ImageWrap::clamp, 7.0f, -3.0f).x, 1.0f);
}

TEST(ImageLookup, NonFiniteCoordinatesStayInsideTheImage) {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity(), 1e30f, -1e30f})
    for (ImageWrap wrap : {ImageWrap::repeat, ImageWrap::clamp}) {
      const float red = semantics::image(rgb, 2, 2, wrap, bad, bad).x;
      EXPECT_TRUE(red >= 0.0f && red <= 3.0f) << bad;
    }
}

// The colour at uv of a texture graph sampling `file`.
std::vector<float> sample(const std::string& file, float u, float v, const std::string& extra,
                          const GraphFiles& files = testing::test_files()) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "uv", "op": "uv"}, {"id": "img", "op": "image", "in": {"uv": "uv"}, "file": ")" +
                              file + "\"" + extra + "}",
                          R"("color": "img")"),
      "g.json", {}, {}, files);
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  if (!loaded) return {};
  float uv[2] = {u, v}, color[3] = {};
  SampleInputs inputs;
  inputs.planes[global_def(GlobalId::uv).first] = &uv[0];
  inputs.planes[global_def(GlobalId::uv).first + 1] = &uv[1];
  float* outputs[4] = {&color[0], &color[1], &color[2], nullptr};
  make_interpreted_kernel(loaded->ir)->bind(loaded->params.data(), UniformInputs{})->run(inputs, outputs, 1);
  return {color[0], color[1], color[2]};
}

// Files hold their top row first; v = 0 is the bottom of the image.
TEST(ImageOp, TopRowOfTheFileIsAtVOne) {
  const int bottom = 2;  // of rows 0 .. 2 from the top
  EXPECT_EQ(sample("4x3x3.png", 0.125f, 1.0f / 6.0f, ""),
            (std::vector<float>{testing::test_image_value(0, bottom, 0), testing::test_image_value(0, bottom, 1),
                                testing::test_image_value(0, bottom, 2)}));
  EXPECT_FLOAT_EQ(sample("4x3x3.png", 0.875f, 5.0f / 6.0f, "")[0], testing::test_image_value(3, 0, 0));
}

TEST(ImageOp, GreyImagesRepeatTheirChannelAndAlphaIsDropped) {
  EXPECT_EQ(sample("2x2x1.png", 0.25f, 0.75f, ""), std::vector<float>(3, testing::test_image_value(0, 0, 0)));
  EXPECT_EQ(sample("2x2x4.png", 0.25f, 0.75f, "")[2], testing::test_image_value(0, 0, 2));
}

TEST(ImageOp, WrapModeIsAnAttribute) {
  EXPECT_FLOAT_EQ(sample("2x1x3.png", 0.0f, 0.5f, R"(, "wrap": "clamp")")[0], testing::test_image_value(0, 0, 0));
  EXPECT_FLOAT_EQ(sample("2x1x3.png", 0.0f, 0.5f, "")[0],
                  (testing::test_image_value(0, 0, 0) + testing::test_image_value(1, 0, 0)) / 2);
}

// The checker's error for an image graph, as one line.
std::string error_of(const std::string& node_fields, const GraphFiles& files = testing::test_files()) {
  Result<LoadedGraph> loaded = compile_graph_text(
      testing::graph_text(R"({"id": "uv", "op": "uv"}, {"id": "img", "op": "image", "in": {"uv": "uv"})" +
                              node_fields + "}",
                          R"("color": "img")"),
      "g.json", {}, {}, files);
  EXPECT_FALSE(loaded.ok());
  return loaded ? "" : loaded.error().to_string();
}

TEST(ImageOp, BadAttributesAreOneLineErrorsOnTheNode) {
  EXPECT_EQ(error_of(""), R"(error: g.json: node "img": missing attribute "file" (the image file (any format )"
                          R"(OpenImageIO reads, at most 1024x1024 pixels), relative to the graph file))");
  EXPECT_EQ(error_of(R"(, "file": 3)"), R"(error: g.json: node "img": attribute "file" must be the path of an image file)");
  EXPECT_EQ(error_of(R"(, "file": "2x2x3.png", "wrap": "mirror")"),
            R"(error: g.json: node "img": attribute "wrap" must be one of: repeat, clamp)");
  EXPECT_EQ(error_of(R"(, "file": "2048x1024x3.png")"),
            R"(error: g.json: node "img": image "2048x1024x3.png" is 2048x1024; images of up to 1048576 pixels )"
            R"((1024x1024) can be sampled)");
  EXPECT_EQ(error_of(R"(, "file": "2x2x3.png")", GraphFiles{}),
            R"(error: g.json: node "img": image files cannot be read here (attribute "file"))");
}

// Image files on disk, through OpenImageIO.
class ImageFiles : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(folder_ / "graphs"); }

  std::string graph_file() const { return (folder_ / "graphs" / "g.json").string(); }
  testing::TempFolder temp_{"shadetree-image"};
  const fs::path& folder_ = temp_.path();
};

// EXR keeps 32-bit floats, so the pixels read back exactly.
TEST_F(ImageFiles, ExrPixelsReachTheKernelExactly) {
  Image image{3, 2, 3, {}};
  for (int i = 0; i < 18; ++i) image.pixels.push_back(0.1f * static_cast<float>(i) - 0.4f);
  ASSERT_TRUE(write_image(image, (folder_ / "graphs" / "six.exr").string()).ok());
  Result<Image> read = graph_files().image(graph_file(), "six.exr");
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(read->pixels, image.pixels);
  // The pixel in column 2 of the top row, at its centre.
  const std::vector<float> expected(image.pixels.begin() + 6, image.pixels.begin() + 9);
  GraphFiles beside_the_graph;
  beside_the_graph.image = [&](const std::string&, const std::string& path) {
    return graph_files().image(graph_file(), path);
  };
  EXPECT_EQ(sample("six.exr", 5.0f / 6.0f, 0.75f, "", beside_the_graph), expected);
}

TEST_F(ImageFiles, MissingBrokenHugeAndEscapingFilesAreInvalidInput) {
  std::ofstream(folder_ / "graphs" / "broken.png") << "not a png";
  std::ofstream(folder_ / "outside.png") << "not a png either";
  const ImageReader reader = graph_files().image;
  for (const char* path : {"missing.png", "broken.png", "../outside.png", "/etc/passwd"}) {
    Result<Image> read = reader(graph_file(), path);
    ASSERT_FALSE(read.ok()) << path;
    EXPECT_EQ(read.error().status, ExitStatus::invalid_input) << path;
    EXPECT_EQ(read.error().to_string().find('\n'), std::string::npos);
  }
  EXPECT_NE(reader(graph_file(), "../outside.png").error().message.find("outside the graph's folder"),
            std::string::npos);
  // An image over the limit is refused before its pixels are read.
  Image large{2048, 1024, 1, std::vector<float>(2048 * 1024, 0.5f)};
  ASSERT_TRUE(write_image(large, (folder_ / "graphs" / "large.exr").string()).ok());
  Result<Image> read = reader(graph_file(), "large.exr");
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find("2048x1024 pixels, more than the 1048576 allowed"), std::string::npos)
      << read.error().message;
}

// Issue 21: the limit counted pixels, not channels, so a small file of
// 1024x1024 pixels and 600 channels was decoded whole (59 s, 5 GB).
TEST_F(ImageFiles, ChannelsCountAgainstTheLimitAndOnlyRgbaIsKept) {
  Image wide{32, 32, 40, std::vector<float>(32 * 32 * 40, 0.25f)};
  for (int i = 0; i < 32 * 32; ++i) wide.pixels[static_cast<std::size_t>(i) * 40 + 3] = 0.75f;
  const std::string path = (folder_ / "graphs" / "wide.exr").string();
  ASSERT_TRUE(write_image(wide, path).ok());
  Result<Image> refused = read_image(path, 32 * 32 * 4);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("32x32 pixels of 40 channels, more values than 4096 RGBA pixels hold"),
            std::string::npos)
      << refused.error().message;
  Result<Image> read = read_image(path, 32 * 32 * 10);
  ASSERT_TRUE(read.ok()) << read.error().to_string();
  EXPECT_EQ(read->channels, 4);
  ASSERT_EQ(read->pixels.size(), 32u * 32u * 4u);
  EXPECT_EQ(read->pixels[2], 0.25f);
  EXPECT_EQ(read->pixels[3], 0.75f);
}

// Issue 21: EXR files embed the time they were written, so identical
// renders differed in bytes. SOURCE_DATE_EPOCH fixes that time.
TEST_F(ImageFiles, ExrFilesAreReproducibleUnderSourceDateEpoch) {
  Image image{4, 2, 3, std::vector<float>(24, 0.5f)};
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  const std::string first = (folder_ / "first.exr").string(), second = (folder_ / "second.exr").string();
  ASSERT_TRUE(write_image(image, first).ok());
  ASSERT_TRUE(write_image(image, second).ok());
  ::unsetenv("SOURCE_DATE_EPOCH");
  auto bytes = [](const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), {});
  };
  EXPECT_EQ(bytes(first), bytes(second));
  EXPECT_NE(bytes(first).find("2023:11:14 22:13:20"), std::string::npos);
}

}  // namespace
}  // namespace shadetree
