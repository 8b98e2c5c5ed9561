#include "render/image_output.h"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>

namespace shadetree {

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// The OpenImageIO module (render/image_io_module.cpp), loaded on first use
// from the folder of the running executable.
struct ImageIoModule {
  int (*write)(const char*, const char*, const float*, int, int, int, int, char*, std::size_t) = nullptr;
  float* (*read)(const char*, long long, int*, int*, int*, char*, std::size_t) = nullptr;
  void (*release)(float*) = nullptr;
  std::string error;
};

const ImageIoModule& image_io_module() {
  static ImageIoModule module;
  static std::once_flag loaded;
  std::call_once(loaded, [] {
    std::error_code error;
    const auto folder = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
    const std::string path = (folder / "libshadetree_image_io.so").string();
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* reason = ::dlerror();
      module.error = "cannot load image support (" + path + "): " + (reason ? reason : "unknown error");
      return;
    }
    module.write = reinterpret_cast<decltype(module.write)>(::dlsym(handle, "shadetree_image_io_write"));
    module.read = reinterpret_cast<decltype(module.read)>(::dlsym(handle, "shadetree_image_io_read"));
    module.release = reinterpret_cast<decltype(module.release)>(::dlsym(handle, "shadetree_image_io_free"));
    if (!module.write || !module.read || !module.release) module.error = "image support module " + path + " is incomplete";
  });
  return module;
}

}  // namespace

Status check_image_path(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  if (extension != ".png" && extension != ".exr")
    return invalid_input("output \"" + path + "\": unsupported extension (use .png or .exr)");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !std::filesystem::is_directory(folder, error))
    return failure("output \"" + path + "\": folder \"" + folder.string() + "\" does not exist");
  return success();
}

Status write_image(const Image& image, const std::string& path) {
  Status writable = check_image_path(path);
  if (!writable) return writable;
  const std::string extension = lowercase_extension(path);
  const ImageIoModule& module = image_io_module();
  if (!module.error.empty()) return failure(module.error);
  const std::filesystem::path target(path);
  const std::filesystem::path temporary =
      target.parent_path() / ("." + target.filename().string() + ".partial-" + std::to_string(::getpid()) + extension);
  char reason[512] = "";
  if (module.write(path.c_str(), temporary.c_str(), image.pixels.data(), image.width, image.height, image.channels,
                   extension == ".png", reason, sizeof reason) != 0) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return failure("output \"" + path + "\": " + reason);
  }
  std::error_code error;
  std::filesystem::rename(temporary, target, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return failure("output \"" + path + "\": cannot rename the finished image into place");
  }
  return success();
}

Result<Image> read_image(const std::string& path, long long max_pixels) {
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
