#include "nodes/lane_trace.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace shadetree::lanes {
namespace {

thread_local Trace* active = nullptr;

const char* type_name(TraceType type) {
  switch (type) {
    case TraceType::int_: return "int";
    case TraceType::bool_: return "bool";
    default: return "float";
  }
}

}  // namespace

Trace& active_trace() {
  if (!active) throw std::logic_error("traced lanes used with no active Trace");
  return *active;
}

TraceActivation::TraceActivation(Trace& trace) : previous_(active) { active = &trace; }
TraceActivation::~TraceActivation() { active = previous_; }

std::string Trace::temporary(TraceType type, const std::string& expression) {
  const std::string key = std::string(type_name(type)) + " " + expression;
  for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
    if (auto found = scope->find(key); found != scope->end()) return found->second;
  std::string name = "t" + std::to_string(next_name_++);
  statement(std::string(type_name(type)) + " " + name + " = " + expression + ";");
  scopes_.back().emplace(key, name);
  return name;
}

std::string Trace::variable(TraceType type, const std::string& value) {
  std::string name = "s" + std::to_string(next_name_++);
  statement(std::string(type_name(type)) + " " + name + " = " + value + ";");
  return name;
}

void Trace::statement(const std::string& text) {
  text_.append(2 * (scopes_.size() + 1), ' ').append(text).append("\n");
  ++statements_;
}

void Trace::open(const std::string& header) {
  statement(header + " {");
  scopes_.emplace_back();
}

void Trace::close() {
  scopes_.pop_back();
  statement("}");
}

void Trace::add_table(const void* begin, std::size_t count, std::string name) {
  const char* first = static_cast<const char*>(begin);
  tables_.push_back({first, first + count * sizeof(float), std::move(name)});
}

std::string Trace::element(const void* entry, const std::string& index) {
  const char* address = static_cast<const char*>(entry);
  for (const Table& table : tables_) {
    if (address < table.begin || address >= table.end) continue;
    const std::size_t offset = static_cast<std::size_t>(address - table.begin) / sizeof(float);
    used_.insert(table.name);
    return table.name + "[" + (offset == 0 ? index : index + " + " + std::to_string(offset)) + "]";
  }
  throw std::logic_error("a table lookup in memory that no GLSL array holds");
}

std::string glsl_float(float value) {
  if (std::isnan(value)) return "uintBitsToFloat(0x7fc00000u)";
  if (std::isinf(value)) return value > 0 ? "uintBitsToFloat(0x7f800000u)" : "uintBitsToFloat(0xff800000u)";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  std::string literal = text;
  if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
  return std::signbit(value) ? "(" + literal + ")" : literal;
}

std::string glsl_int(std::int32_t value) {
  if (value == std::numeric_limits<std::int32_t>::min()) return "(-2147483647 - 1)";
  return value < 0 ? "(" + std::to_string(value) + ")" : std::to_string(value);
}

}  // namespace shadetree::lanes
