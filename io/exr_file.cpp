#include "io/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <string>
#include <thread>

namespace shadetree {

namespace {

// The time to record, as EXR's capDate writes it ("YYYY:MM:DD HH:MM:SS",
// in UTC, with a utcOffset of 0): SOURCE_DATE_EPOCH's (the
// reproducible-builds convention, seconds since 1970) when it is set and
// well formed, else now.
std::string capture_date() {
  std::time_t time = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch && *epoch) {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (*end == '\0' && seconds >= 0) time = static_cast<std::time_t>(seconds);
  }
  std::tm utc{};
  if (!gmtime_r(&time, &utc)) return "1970:01:01 00:00:00";
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &utc);
  return text;
}

// Y for a single channel; else R, G, B, A and then channel4, channel5...
// (OpenImageIO's names, which it reads back in this order).
std::string channel_name(int channels, int c) {
  static const char* const rgba[] = {"R", "G", "B", "A"};
  if (channels == 1) return "Y";
  return c < 4 ? rgba[c] : "channel" + std::to_string(c);
}

}  // namespace

std::string write_exr(const Image& image, const std::string& file) {
  if (image.channels < 1) return "an image without channels";
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.insert("software", Imf::StringAttribute("shadetree"));
    Imf::addCapDate(header, capture_date());
    Imf::addUtcOffset(header, 0.0f);
    Imf::FrameBuffer frame;
    const std::size_t pixel = sizeof(float) * image.channels;
    for (int c = 0; c < image.channels; ++c) {
      const std::string name = channel_name(image.channels, c);
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
      // Slices point into the pixels; OpenEXR only reads through them.
      char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data() + c));
      frame.insert(name, Imf::Slice(Imf::FLOAT, base, pixel, pixel * image.width));
    }
    // Blocks of scanlines are compressed on every core (OpenEXR's pool, made
    // once): alone, ZIP took 5 of the 7 s of a 4096x4096 render.
    static const int threads = [] {
      Imf::setGlobalThreadCount(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
      return Imf::globalThreadCount();
    }();
    Imf::OutputFile output(file.c_str(), header, threads);
    output.setFrameBuffer(frame);
    output.writePixels(image.height);
  } catch (const std::exception& error) {
    const std::string message = error.what();
    return "write failed: " + message.substr(0, message.find('\n'));
  }
  return {};
}

}  // namespace shadetree
