#include "bench/ratio_table_reporter.h"

#include <algorithm>
#include <cstdio>
#include <ostream>

#include "platform/cpu_model.h"

namespace shadetree {
namespace {

void add_once(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

RatioTableReporter::RatioTableReporter(benchmark::BenchmarkReporter* display, std::string prefix,
                                       std::string reference, std::string caption)
    : display_(display),
      prefix_(std::move(prefix)),
      reference_(std::move(reference)),
      caption_(std::move(caption)) {}

bool RatioTableReporter::ReportContext(const Context& context) { return display_->ReportContext(context); }

void RatioTableReporter::ReportRuns(const std::vector<Run>& runs) {
  display_->ReportRuns(runs);
  for (const Run& run : runs) record(run);
}

void RatioTableReporter::Finalize() {
  display_->Finalize();
  if (measurements_.empty()) return;
  // Beside a console the table reads as more output; it would break JSON.
  if (dynamic_cast<benchmark::ConsoleReporter*>(display_))
    print_table(display_->GetOutputStream());
  else
    print_table(display_->GetErrorStream());
}

void RatioTableReporter::record(const Run& run) {
  const std::string& name = run.run_name.function_name;
  if (name.rfind(prefix_, 0) != 0) return;
  const std::size_t slash = name.find('/', prefix_.size());
  if (slash == std::string::npos) return;
  const std::string kernel = name.substr(prefix_.size(), slash - prefix_.size()), variant = name.substr(slash + 1);
  add_once(kernels_, kernel);
  if (variant != reference_) add_once(variants_, variant);
  Measurement& measurement = measurements_[{kernel, variant}];
  if (run.error_occurred) {
    measurement.error = run.error_message;
    return;
  }
  const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
  if ((run.run_type == Run::RT_Aggregate && !median) || (measurement.median && !median)) return;
  const auto rate = run.counters.find("items_per_second");
  if (rate == run.counters.end()) return;
  measurement.items_per_second = rate->second.value;
  measurement.median = median;
  measurement.label = run.report_label;
}

void RatioTableReporter::print_table(std::ostream& out) const {
  auto measured = [&](const std::string& kernel, const std::string& variant) -> const Measurement* {
    const auto found = measurements_.find({kernel, variant});
    return found != measurements_.end() && found->second.error.empty() && found->second.items_per_second > 0.0
               ? &found->second
               : nullptr;
  };
  const bool medians = std::all_of(measurements_.begin(), measurements_.end(),
                                   [](const auto& entry) { return entry.second.median || !entry.second.error.empty(); });
  // Google Benchmark's context names the clock and caches, not the model.
  out << "\n" << caption_ << " on " << cpu_model_name() << ", " << (medians ? "medians of the repetitions" : "single runs")
      << ".\nEach cell: " << reference_ << "'s samples per second over the column's, and the column's million samples per "
      << "second.\n";
  constexpr int column_width = 22;
  auto cell = [&](const std::string& text) {
    out << text << std::string(static_cast<std::size_t>(std::max(1, column_width - static_cast<int>(text.size()))), ' ');
  };
  std::vector<std::string> columns{reference_};
  columns.insert(columns.end(), variants_.begin(), variants_.end());
  cell("kernel");
  for (const std::string& variant : columns) cell(variant == reference_ ? reference_ + " (M/s)" : variant);
  out << "\n";
  for (const std::string& kernel : kernels_) {
    const Measurement* reference = measured(kernel, reference_);
    cell(kernel);
    for (const std::string& variant : columns) {
      const Measurement* measurement = measured(kernel, variant);
      const double millions = measurement ? measurement->items_per_second * 1e-6 : 0.0;
      if (!measurement)
        cell(measurements_.count({kernel, variant}) ? "error" : "-");
      else if (variant == reference_)
        cell(format("%.1f", millions));
      else if (!reference)
        cell(format("- (%.1f)", millions));
      else
        cell(format("%.2fx", reference->items_per_second / measurement->items_per_second) + format(" (%.1f)", millions));
    }
    out << "\n";
  }
  for (const std::string& kernel : kernels_)
    for (const std::string& variant : columns) {
      const auto found = measurements_.find({kernel, variant});
      if (found == measurements_.end()) continue;
      const Measurement& measurement = found->second;
      if (!measurement.error.empty())
        out << "  " << kernel << "/" << variant << ": error: " << measurement.error << "\n";
      else if (!measurement.label.empty())
        out << "  " << kernel << "/" << variant << ": " << measurement.label << "\n";
    }
}

}  // namespace shadetree
