// Image inputs through OpenImageIO, built as a loadable module
// (libshadetree_image_io.so) so that only commands that read images pay
// for loading OpenImageIO: Debian's build of it pulls in some
// 250 shared libraries (GDAL, OpenVDB, Xerces...), a quarter of a second of
// dynamic linking at every start. io/image_output.cpp loads it.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

#include <OpenImageIO/imageio.h>

namespace {

// OpenImageIO's errors can span lines (its own and the format library's
// restatement); the first says what is wrong.
void set_error(char* error, std::size_t size, const std::string& message) {
  std::snprintf(error, size, "%s", message.substr(0, message.find('\n')).c_str());
}

// libpng prints "libpng error: ..." on stderr itself once OpenImageIO's
// error handler has kept the message and returned, which would put a
// second line before shadetree's one-line error: stderr is pointed at
// /dev/null while a file is read (one read at a time, so that the real
// stderr is always put back).
class StderrMuted {
 public:
  StderrMuted() : lock_(mutex()) {
    std::fflush(stderr);
    saved_ = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 2);
    if (null >= 0) ::close(null);
  }
  ~StderrMuted() {
    std::fflush(stderr);
    if (saved_ >= 0) {
      ::dup2(saved_, 2);
      ::close(saved_);
    }
  }
  StderrMuted(const StderrMuted&) = delete;
  StderrMuted& operator=(const StderrMuted&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex instance;
    return instance;
  }
  std::lock_guard<std::mutex> lock_;
  int saved_ = -1;
};

}  // namespace

// Reads any image OpenImageIO knows as float pixels (malloc'ed; release
// with shadetree_image_io_free), its first four channels at most. Null on
// failure, and for an image of more than `max_pixels` pixels or more than
// 4 * `max_pixels` values in all channels (when positive), before its
// pixels are read.
extern "C" float* shadetree_image_io_read(const char* path, long long max_pixels, int* width, int* height,
                                          int* channels, char* error, std::size_t error_size) {
  const StderrMuted muted;
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    set_error(error, error_size, OIIO::geterror());
    return nullptr;
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
    set_error(error, error_size, "the image has no pixels");
    return nullptr;
  }
  if (max_pixels > 0 && static_cast<long long>(spec.width) * spec.height > max_pixels) {
    set_error(error, error_size,
              std::to_string(spec.width) + "x" + std::to_string(spec.height) + " pixels, more than the " +
                  std::to_string(max_pixels) + " allowed");
    return nullptr;
  }
  // Decoding reads every channel of the file: the limit counts them, as
  // RGBA pixels' worth of values (a 616 KB TIFF of 1024x1024 pixels and
  // 600 channels took 59 s and 5 GB). Only RGBA is kept.
  if (max_pixels > 0 && static_cast<long long>(spec.width) * spec.height * spec.nchannels > 4 * max_pixels) {
    set_error(error, error_size,
              std::to_string(spec.width) + "x" + std::to_string(spec.height) + " pixels of " +
                  std::to_string(spec.nchannels) + " channels, more values than " + std::to_string(max_pixels) +
                  " RGBA pixels hold");
    return nullptr;
  }
  const int kept = std::min(spec.nchannels, 4);
  const std::size_t count = static_cast<std::size_t>(spec.width) * spec.height * kept;
  auto* pixels = static_cast<float*>(std::malloc(count * sizeof(float)));
  if (!pixels || !input->read_image(0, 0, 0, kept, OIIO::TypeDesc::FLOAT, pixels)) {
    set_error(error, error_size, pixels ? input->geterror() : std::string("out of memory"));
    std::free(pixels);
    return nullptr;
  }
  *width = spec.width;
  *height = spec.height;
  *channels = kept;
  return pixels;
}

extern "C" void shadetree_image_io_free(float* pixels) { std::free(pixels); }
