#include "schedule/progress.h"

#include <unistd.h>

#include <cstdio>

namespace shadetree {
namespace {

// 1234567 -> "1.23 M", 34567 -> "34.6 k", 512 -> "512".
std::string per_second(double rate) {
  char text[32];
  if (rate >= 1e6) std::snprintf(text, sizeof text, "%.2f M", rate / 1e6);
  else if (rate >= 1e3) std::snprintf(text, sizeof text, "%.1f k", rate / 1e3);
  else std::snprintf(text, sizeof text, "%.0f", rate);
  return text;
}

}  // namespace

ProgressReporter::ProgressReporter(std::string label, std::string parts, std::string items)
    : label_(std::move(label)),
      parts_(std::move(parts)),
      items_(std::move(items)),
      start_(std::chrono::steady_clock::now()),
      enabled_(::isatty(2) != 0) {}

ProgressReporter::~ProgressReporter() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
}

void ProgressReporter::update(const ProgressCount& count) {
  if (!enabled_ || count.total <= 0) return;
  const auto elapsed = std::chrono::steady_clock::now() - start_;
  if (elapsed < std::chrono::seconds(1)) return;
  std::lock_guard lock(mutex_);
  const double fraction = static_cast<double>(count.done) / static_cast<double>(count.total);
  const int percent = static_cast<int>(fraction * 100.0);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  shown_ = true;
  // The time left if the rest goes as fast as what is done.
  const double seconds = std::chrono::duration<double>(elapsed).count();
  const double left = fraction > 0.0 ? seconds * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s %3d%% (%ld/%ld %s), %s %s/s, %.0f s elapsed, about %.0f s left\033[K", label_.c_str(),
               percent, count.done, count.total, parts_.c_str(),
               per_second(static_cast<double>(count.items) / seconds).c_str(), items_.c_str(), seconds, left);
  std::fflush(stderr);
}

}  // namespace shadetree
