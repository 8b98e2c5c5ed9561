#include "io/image_output.h"

#include <filesystem>

#include "graph/file_path.h"
#include "io/exr_file.h"
#include "platform/loadable_module.h"
#include "io/output_file.h"
#include "io/png_file.h"

namespace shadetree {

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// The OpenImageIO module (io/image_io_module.cpp), loaded on the first
// read: image inputs come in every format, outputs only as PNG and EXR,
// which are written without it.
struct ImageIoModule {
  LoadableModule module{"libshadetree_image_io.so", "image support"};
  float* (*read)(const char*, long long, int*, int*, int*, char*, std::size_t) =
      module.function<float*(const char*, long long, int*, int*, int*, char*, std::size_t)>("shadetree_image_io_read");
  void (*release)(float*) = module.function<void(float*)>("shadetree_image_io_free");
  const std::string& error = module.error();
};

const ImageIoModule& image_io_module() {
  static ImageIoModule module;
  return module;
}

}  // namespace

Status check_image_path(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  if (extension != ".png" && extension != ".exr")
    return invalid_input("output \"" + path + "\": unsupported extension (use .png or .exr)");
  return check_output_folder(path);
}

Status write_image(const Image& image, const std::string& path, int png_bits) {
  Status writable = check_image_path(path);
  if (!writable) return writable;
  const bool png = lowercase_extension(path) == ".png";
  return write_then_rename(path, [&](const std::string& temporary) {
    return png ? write_png(image, temporary, png_bits) : write_exr(image, temporary);
  });
}

Result<Image> read_image(const std::string& path, long long max_pixels) {
  if (Status text = check_path_text(path, "image"); !text) return text.error();
  const ImageIoModule& module = image_io_module();
  if (!module.error.empty()) return failure(module.error);
  Image image;
  char reason[512] = "";
  float* pixels = module.read(path.c_str(), max_pixels, &image.width, &image.height, &image.channels, reason, sizeof reason);
  if (!pixels) return failure("cannot read image \"" + path + "\": " + reason);
  image.pixels.assign(pixels, pixels + static_cast<std::size_t>(image.width) * image.height * image.channels);
  module.release(pixels);
  return image;
}

}  // namespace shadetree
