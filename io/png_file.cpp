#include "io/png_file.h"

#include <png.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace shadetree {

namespace {

// A value on [0,1] as the nearest of `steps` + 1 levels; NaN and negatives
// are 0, as OpenImageIO wrote them before.
unsigned quantize(float value, float steps) {
  if (!(value > 0.0f)) return 0;
  if (value >= 1.0f) return static_cast<unsigned>(steps);
  return static_cast<unsigned>(value * steps + 0.5f);
}

struct PngWriter {
  std::FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  char error[256] = "";

  ~PngWriter() {
    png_destroy_write_struct(&png, &info);
    if (file) std::fclose(file);
  }
};

[[noreturn]] void keep_error(png_structp png, png_const_charp message) {
  auto* writer = static_cast<PngWriter*>(png_get_error_ptr(png));
  std::snprintf(writer->error, sizeof writer->error, "%s", message);
  png_longjmp(png, 1);
}

void ignore_warning(png_structp, png_const_charp) {}

// libpng reports an error by a longjmp back here, so this function holds
// no object whose destructor the jump could skip.
bool write_rows(PngWriter& writer, int width, int height, int color_type, int bits, png_bytepp rows) {
  if (setjmp(png_jmpbuf(writer.png))) return false;
  png_init_io(writer.png, writer.file);
  png_set_IHDR(writer.png, writer.info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bits,
               color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_text software{};
  software.compression = PNG_TEXT_COMPRESSION_NONE;
  software.key = const_cast<char*>("Software");
  software.text = const_cast<char*>("shadetree");
  png_set_text(writer.png, writer.info, &software, 1);
  png_write_info(writer.png, writer.info);
  // PNG stores 16-bit samples big-endian; the rows hold them in host order.
  if (bits == 16 && std::endian::native == std::endian::little) png_set_swap(writer.png);
  png_write_image(writer.png, rows);
  png_write_end(writer.png, nullptr);
  return true;
}

}  // namespace

std::string write_png(const Image& image, const std::string& file, int bits) {
  static constexpr int color_types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                        PNG_COLOR_TYPE_RGB_ALPHA};
  if (image.channels < 1 || image.channels > 4) return "PNG holds 1 to 4 channels, not " + std::to_string(image.channels);
  if (bits != 8 && bits != 16) return "PNG samples are 8 or 16 bits, not " + std::to_string(bits);

  const std::size_t row_values = static_cast<std::size_t>(image.width) * image.channels;
  const std::size_t row_bytes = row_values * (bits / 8);
  std::vector<unsigned char> samples(row_bytes * image.height);
  const float steps = bits == 8 ? 255.0f : 65535.0f;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const unsigned level = quantize(image.pixels[i], steps);
    if (bits == 8) {
      samples[i] = static_cast<unsigned char>(level);
    } else {
      const auto wide = static_cast<std::uint16_t>(level);
      std::memcpy(&samples[2 * i], &wide, 2);
    }
  }
  std::vector<png_bytep> rows(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = samples.data() + y * row_bytes;

  PngWriter writer;
  writer.file = std::fopen(file.c_str(), "wb");
  if (!writer.file) return "cannot create the file";
  writer.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &writer, keep_error, ignore_warning);
  if (writer.png) writer.info = png_create_info_struct(writer.png);
  if (!writer.info) return "out of memory";
  if (!write_rows(writer, image.width, image.height, color_types[image.channels - 1], bits, rows.data()))
    return std::string("write failed: ") + writer.error;
  const int closed = std::fclose(writer.file);
  writer.file = nullptr;
  return closed == 0 ? std::string() : std::string("write failed: the file could not be closed");
}

}  // namespace shadetree
