// Errors are values: a Diagnostic is produced where a fault is detected and
// printed once, by the command line, as one line:
//   error: marble.json: node "t2" input "p": expected vec3, got float
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace shadetree {

// Exit statuses of the shadetree command (documented in README.md).
enum class ExitStatus : int {
  ok = 0,
  failure = 1,        // I/O, backend or internal failure
  invalid_input = 2,  // usage, graph or parameter error
};

struct Diagnostic {
  ExitStatus status = ExitStatus::invalid_input;
  std::string file;     // graph file name as the user gave it; may be empty
  std::string node;     // node id; may be empty
  std::string input;    // input (port) name; may be empty
  std::string message;  // what was expected and what was found

  std::string to_string() const;
};

Diagnostic invalid_input(std::string message);

// `text` on one line of a terminal: line breaks, tabs and other control
// characters escaped (\n, \t, \r, \xNN). Names and messages echo what
// the user wrote; a newline in a node id must not split the line, nor a
// NUL end it, nor an escape sequence drive the terminal.
std::string printable(const std::string& text);
Diagnostic failure(std::string message);

// A value or the diagnostic that explains why there is none.
template <class T>
class Result {
 public:
  Result(T value) : state_(std::move(value)) {}
  Result(Diagnostic error) : state_(std::move(error)) {}

  bool ok() const { return state_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<0>(state_); }
  const T& value() const { return std::get<0>(state_); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Diagnostic& error() const { return std::get<1>(state_); }

 private:
  std::variant<T, Diagnostic> state_;
};

// For stages that produce nothing but may fail.
struct Done {};
using Status = Result<Done>;
inline Status success() { return Done{}; }

}  // namespace shadetree
