#include "schedule/frame_list.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <sstream>

#include "graph/parse.h"

namespace shadetree {
namespace {

// A whole number at text[at...], advancing `at`; none if there is no digit.
std::optional<long long> number_at(const std::string& text, std::size_t& at) {
  const std::size_t start = at;
  long long value = 0;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])) && value <= largest_frame)
    value = value * 10 + (text[at++] - '0');
  if (at == start || value > largest_frame) return std::nullopt;
  return value;
}

struct Range {
  long long first = 0, last = 0, step = 1;
};

// "A", "A..B", "A-B", each with an optional "xS" or ":S".
std::optional<Range> parse_range(const std::string& text) {
  std::size_t at = 0;
  Range range;
  const auto first = number_at(text, at);
  if (!first) return std::nullopt;
  range.first = range.last = *first;
  if (text.compare(at, 2, "..") == 0 || (at < text.size() && text[at] == '-')) {
    at += text[at] == '-' ? 1 : 2;
    const auto last = number_at(text, at);
    if (!last) return std::nullopt;
    range.last = *last;
    if (at < text.size() && (text[at] == 'x' || text[at] == ':')) {
      ++at;
      const auto step = number_at(text, at);
      if (!step || *step < 1) return std::nullopt;
      range.step = *step;
    }
  }
  if (at != text.size() || range.first > range.last) return std::nullopt;
  return range;
}

Diagnostic bad_list(const std::string& what, const std::string& text, const std::string& expected) {
  return invalid_input(what + " expects " + expected + ", got \"" + printable(text) + "\"");
}

}  // namespace

Result<std::vector<int>> parse_frame_list(const std::string& text) {
  const std::string expected =
      "frames and ranges FIRST..LAST or FIRST-LAST, each with an optional step xS, separated by commas (e.g. "
      "1-240x4), at most " + std::to_string(max_sequence_frames) + " frames";
  std::vector<int> frames;
  std::stringstream parts(text);
  std::string part;
  bool any = false;
  while (std::getline(parts, part, ',')) {
    any = true;
    const std::optional<Range> range = parse_range(part);
    if (!range) return bad_list("--frames", text, expected);
    for (long long frame = range->first; frame <= range->last; frame += range->step) {
      if (frames.size() >= static_cast<std::size_t>(max_sequence_frames)) return bad_list("--frames", text, expected);
      frames.push_back(static_cast<int>(frame));
    }
  }
  if (!any || text.empty() || text.back() == ',') return bad_list("--frames", text, expected);
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

Result<std::vector<int>> frame_chunk(const std::vector<int>& frames, const std::string& chunk) {
  const std::optional<Range> range = parse_range(chunk);
  if (!range || range->step != 1 || chunk.find_first_of("-.") == std::string::npos)
    return bad_list("--chunk", chunk, "START..END or START-END");
  std::vector<int> chosen;
  for (int frame : frames)
    if (frame >= range->first && frame <= range->last) chosen.push_back(frame);
  if (chosen.empty())
    return invalid_input("--chunk " + printable(chunk) + " holds no frame of --frames (" +
                         std::to_string(frames.front()) + " to " + std::to_string(frames.back()) + ")");
  return chosen;
}

}  // namespace shadetree
