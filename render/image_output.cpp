#include "render/image_output.h"

#include <unistd.h>

#include <filesystem>

#include <OpenImageIO/imageio.h>

namespace shadetree {

namespace {
std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}
}  // namespace

Status write_image(const Image& image, const std::string& path) {
  const std::string extension = lowercase_extension(path);
  OIIO::TypeDesc format;
  if (extension == ".png") {
    format = OIIO::TypeDesc::UINT8;
  } else if (extension == ".exr") {
    format = OIIO::TypeDesc::FLOAT;
  } else {
    return invalid_input("output \"" + path + "\": unsupported extension (use .png or .exr)");
  }
  const std::filesystem::path target(path);
  const std::filesystem::path temporary =
      target.parent_path() / ("." + target.filename().string() + ".partial-" + std::to_string(::getpid()) + extension);
  auto output = OIIO::ImageOutput::create(path);
  if (!output) return failure("output \"" + path + "\": " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, image.channels, format);
  spec.attribute("Software", "shadetree");
  if (!output->open(temporary.string(), spec)) {
    return failure("output \"" + path + "\": cannot write: " + output->geterror());
  }
  const bool written = output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  const bool closed = output->close();
  if (!written || !closed) {
    const std::string reason = output->geterror();
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return failure("output \"" + path + "\": write failed: " + reason);
  }
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return failure("output \"" + path + "\": cannot rename the finished image into place");
  }
  return success();
}

Result<Image> read_image(const std::string& path) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) return failure("cannot read image \"" + path + "\": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    return failure("cannot read image \"" + path + "\": " + input->geterror());
  return image;
}

}  // namespace shadetree
