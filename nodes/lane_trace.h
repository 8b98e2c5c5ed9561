// Lane primitives that write GLSL: F = TraceF, I = TraceI, M = TraceM. An
// op's semantics instantiated with them do not compute a value; each
// primitive appends the GLSL statement that computes it to the active
// Trace and returns the name of its result. So `emit --glsl`
// (glslgen/) translates every op from its one definition, as the JIT and
// emit --cpp do, in the same operations and the same order.
//
// A primitive whose operands are all constants is folded here, in the
// float and int32 arithmetic GLSL specifies for them (round to nearest,
// wrapping ints), and a repeated expression in scope reuses its
// temporary. Table lookups name a GLSL array registered for the table's
// memory (Trace::add_table); a constant index reads the entry itself.
// loop_while writes one rolled GLSL loop; any() of a mask that is not a
// constant answers true, which runs the remaining steps for no lane (see
// loop_while in nodes/lane_scalar.h).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "nodes/lane_scalar.h"

namespace shadetree::lanes {

enum class TraceType { float_, int_, bool_ };

// The statements of one GLSL function body, written by the traced lanes
// and by the emitter that drives them.
class Trace {
 public:
  // A name for `expression` of `type`: a temporary declared here, or one
  // declared earlier in an enclosing scope for the same expression.
  std::string temporary(TraceType type, const std::string& expression);
  // A fresh mutable variable (loop state), initialized to `value`.
  std::string variable(TraceType type, const std::string& value);
  void statement(const std::string& text);
  // `header {`, and a scope of its own until close().
  void open(const std::string& header);
  void close();

  // Lookups into [begin, begin + count) become `name[...]`.
  void add_table(const void* begin, std::size_t count, std::string name);
  // The element `index` (a GLSL int expression) of the table holding
  // `entry`; throws std::logic_error for memory of no table.
  std::string element(const void* entry, const std::string& index);
  // Whether a lookup named the table `name`.
  bool used(const std::string& name) const { return used_.contains(name); }

  const std::string& text() const { return text_; }
  long statements() const { return statements_; }

 private:
  std::string text_;
  std::vector<std::map<std::string, std::string>> scopes_{1};
  struct Table {
    const char* begin;
    const char* end;
    std::string name;
  };
  std::vector<Table> tables_;
  std::set<std::string> used_;
  long statements_ = 0;
  int next_name_ = 0;
};

// The trace the traced lanes write to on this thread, while a
// TraceActivation for it lives.
Trace& active_trace();
class TraceActivation {
 public:
  explicit TraceActivation(Trace& trace);
  ~TraceActivation();
  TraceActivation(const TraceActivation&) = delete;
  TraceActivation& operator=(const TraceActivation&) = delete;

 private:
  Trace* previous_;
};

// GLSL literals that read back as exactly these values.
std::string glsl_float(float value);
std::string glsl_int(std::int32_t value);

// A traced value: a constant, or the GLSL name (or literal) holding it.
template <class T, TraceType type_>
struct Traced {
  static constexpr TraceType type = type_;
  std::string text;
  bool constant = true;
  T value{};

  Traced() : text(literal(T{})) {}
  Traced(T constant_value) : text(literal(constant_value)), value(constant_value) {}
  static Traced named(std::string name) {
    Traced traced;
    traced.text = std::move(name);
    traced.constant = false;
    return traced;
  }
  static Traced of(const std::string& expression) { return named(active_trace().temporary(type, expression)); }

  static std::string literal(T v) {
    if constexpr (type_ == TraceType::float_) return glsl_float(v);
    else if constexpr (type_ == TraceType::int_) return glsl_int(v);
    else return v ? "true" : "false";
  }
};

using TraceF = Traced<float, TraceType::float_>;
using TraceI = Traced<std::int32_t, TraceType::int_>;
using TraceM = Traced<bool, TraceType::bool_>;

namespace trace_detail {
// int32 arithmetic wraps in GLSL; in C++ only unsigned arithmetic does.
inline std::int32_t wrap(std::uint32_t v) { return static_cast<std::int32_t>(v); }
inline std::uint32_t bits(std::int32_t v) { return static_cast<std::uint32_t>(v); }

template <class R, class A, class B, class Fold>
R binary(const A& a, const char* op, const B& b, Fold fold) {
  if (a.constant && b.constant) return R(fold(a.value, b.value));
  return R::of(a.text + " " + op + " " + b.text);
}

// a op b where b is the op's right identity for every a, including -0
// and NaN (x - 0 and x * 1 are; x + 0 is not, for x = -0).
template <class A>
bool is_right_identity(const char* op, const A& b) {
  if (!b.constant) return false;
  const std::string o = op;
  if constexpr (A::type == TraceType::float_) {
    if (o == "-") return b.value == 0.0f && !std::signbit(b.value);
    return (o == "*" || o == "/") && b.value == 1.0f;
  } else {
    if (o == "+" || o == "-" || o == "|" || o == "^" || o == "<<" || o == ">>") return b.value == 0;
    if (o == "*") return b.value == 1;
    return o == "&" && b.value == -1;
  }
}

template <class R, class A, class Fold>
R arithmetic(const A& a, const char* op, const A& b, Fold fold) {
  if constexpr (std::is_same_v<R, A>)
    if (is_right_identity(op, b)) return a;
  return binary<R>(a, op, b, fold);
}
}  // namespace trace_detail

#define SHADETREE_TRACE_BINARY(R, A, op, fold)                                                         \
  inline R operator op(const A& a, const A& b) {                                                       \
    return trace_detail::arithmetic<R>(a, #op, b, [](auto x, auto y) { return fold; });                \
  }

SHADETREE_TRACE_BINARY(TraceF, TraceF, +, x + y)
SHADETREE_TRACE_BINARY(TraceF, TraceF, -, x - y)
SHADETREE_TRACE_BINARY(TraceF, TraceF, *, x * y)
SHADETREE_TRACE_BINARY(TraceF, TraceF, /, x / y)
SHADETREE_TRACE_BINARY(TraceM, TraceF, <, x < y)
SHADETREE_TRACE_BINARY(TraceM, TraceF, <=, x <= y)
SHADETREE_TRACE_BINARY(TraceM, TraceF, >, x > y)
SHADETREE_TRACE_BINARY(TraceM, TraceF, >=, x >= y)
SHADETREE_TRACE_BINARY(TraceM, TraceF, ==, x == y)
SHADETREE_TRACE_BINARY(TraceM, TraceF, !=, x != y)
SHADETREE_TRACE_BINARY(TraceI, TraceI, +, trace_detail::wrap(trace_detail::bits(x) + trace_detail::bits(y)))
SHADETREE_TRACE_BINARY(TraceI, TraceI, -, trace_detail::wrap(trace_detail::bits(x) - trace_detail::bits(y)))
SHADETREE_TRACE_BINARY(TraceI, TraceI, *, trace_detail::wrap(trace_detail::bits(x) * trace_detail::bits(y)))
SHADETREE_TRACE_BINARY(TraceI, TraceI, &, x & y)
SHADETREE_TRACE_BINARY(TraceI, TraceI, |, x | y)
SHADETREE_TRACE_BINARY(TraceI, TraceI, ^, x ^ y)
SHADETREE_TRACE_BINARY(TraceI, TraceI, <<, trace_detail::wrap(trace_detail::bits(x) << (y & 31)))
SHADETREE_TRACE_BINARY(TraceI, TraceI, >>, x >> (y & 31))
SHADETREE_TRACE_BINARY(TraceM, TraceI, <, x < y)
SHADETREE_TRACE_BINARY(TraceM, TraceI, <=, x <= y)
SHADETREE_TRACE_BINARY(TraceM, TraceI, >, x > y)
SHADETREE_TRACE_BINARY(TraceM, TraceI, >=, x >= y)
SHADETREE_TRACE_BINARY(TraceM, TraceI, ==, x == y)
SHADETREE_TRACE_BINARY(TraceM, TraceI, !=, x != y)
#undef SHADETREE_TRACE_BINARY

inline TraceF operator-(const TraceF& a) { return a.constant ? TraceF(-a.value) : TraceF::of("-" + a.text); }
inline TraceI operator-(const TraceI& a) {
  return a.constant ? TraceI(trace_detail::wrap(0u - trace_detail::bits(a.value))) : TraceI::of("-" + a.text);
}

inline TraceF select(const TraceM& mask, const TraceF& a, const TraceF& b) {
  if (mask.constant) return mask.value ? a : b;
  return TraceF::of(mask.text + " ? " + a.text + " : " + b.text);
}
inline TraceI select(const TraceM& mask, const TraceI& a, const TraceI& b) {
  if (mask.constant) return mask.value ? a : b;
  return TraceI::of(mask.text + " ? " + a.text + " : " + b.text);
}
inline bool any(const TraceM& mask) { return !mask.constant || mask.value; }
inline TraceM both(const TraceM& a, const TraceM& b) {
  return trace_detail::binary<TraceM>(a, "&&", b, [](bool x, bool y) { return x && y; });
}
inline TraceM either(const TraceM& a, const TraceM& b) {
  return trace_detail::binary<TraceM>(a, "||", b, [](bool x, bool y) { return x || y; });
}
inline TraceM differ(const TraceM& a, const TraceM& b) {
  return trace_detail::binary<TraceM>(a, "!=", b, [](bool x, bool y) { return x != y; });
}
inline TraceM negate(const TraceM& a) { return a.constant ? TraceM(!a.value) : TraceM::of("!" + a.text); }

namespace trace_detail {
template <class R, class A, class Fold>
R call(const char* function, const A& a, Fold fold) {
  if (a.constant) return R(fold(a.value));
  return R::of(std::string(function) + "(" + a.text + ")");
}
}  // namespace trace_detail

inline TraceF floor(const TraceF& x) { return trace_detail::call<TraceF>("floor", x, [](float v) { return floor(v); }); }
inline TraceF abs(const TraceF& x) { return trace_detail::call<TraceF>("abs", x, [](float v) { return abs(v); }); }
inline TraceF sqrt(const TraceF& x) { return trace_detail::call<TraceF>("sqrt", x, [](float v) { return sqrt(v); }); }
// As the lanes define them (a < b ? a : b), not GLSL's min and max, whose
// results for NaN are undefined.
inline TraceF min(const TraceF& a, const TraceF& b) { return select(a < b, a, b); }
inline TraceF max(const TraceF& a, const TraceF& b) { return select(a > b, a, b); }
inline TraceI min(const TraceI& a, const TraceI& b) { return select(a < b, a, b); }
inline TraceI max(const TraceI& a, const TraceI& b) { return select(a > b, a, b); }
inline TraceI to_int(const TraceF& x) {
  return trace_detail::call<TraceI>("int", x, [](float v) { return to_int(v); });
}
inline TraceF to_float(const TraceI& i) {
  return trace_detail::call<TraceF>("float", i, [](std::int32_t v) { return to_float(v); });
}
inline TraceI to_bits(const TraceF& x) {
  return trace_detail::call<TraceI>("floatBitsToInt", x, [](float v) { return to_bits(v); });
}
inline TraceF from_bits(const TraceI& bits) {
  return trace_detail::call<TraceF>("intBitsToFloat", bits, [](std::int32_t v) { return from_bits(v); });
}

template <class T>
Traced<T, std::is_same_v<T, float> ? TraceType::float_ : TraceType::int_> traced_gather(const T* table,
                                                                                       const TraceI& index) {
  using R = Traced<T, std::is_same_v<T, float> ? TraceType::float_ : TraceType::int_>;
  if (index.constant) return R(table[index.value]);
  return R::of(active_trace().element(table, index.text));
}
inline TraceF gather(const float* table, const TraceI& index) { return traced_gather(table, index); }
inline TraceI gather(const std::int32_t* table, const TraceI& index) { return traced_gather(table, index); }
inline TraceF gather256(const float* table, const TraceI& index) { return traced_gather(table, index); }
inline TraceI gather256(const std::int32_t* table, const TraceI& index) { return traced_gather(table, index); }
template <class T>
auto gather256_pair(const T* table, const TraceI& index) {
  return std::array{traced_gather(table, index), traced_gather(table, index + 1)};
}
inline TraceF gather_small(const float* table, std::int32_t, std::int32_t stride, const TraceI& index) {
  return traced_gather(table, index * stride);
}

namespace trace_detail {
// A loop state as a traced lane: traced lanes as they are, plain floats
// (counters such as turbulence's scale) as float lanes.
inline const TraceF& as_traced(const TraceF& x) { return x; }
inline const TraceI& as_traced(const TraceI& x) { return x; }
inline const TraceM& as_traced(const TraceM& x) { return x; }
inline TraceF as_traced(float x) { return TraceF(x); }

template <class T>
auto state_variable(const T& initial) {
  const auto& traced = as_traced(initial);
  using L = std::decay_t<decltype(traced)>;
  return L::named(active_trace().variable(L::type, traced.text));
}

// The variable's value after the loop, where the semantics can take it.
template <class L>
void set_after_loop(L& state, const L& variable) {
  state = variable;
}
inline void set_after_loop(float&, const TraceF&) {}
}  // namespace trace_detail

// loop_while (nodes/lane_scalar.h) as one GLSL loop: each state becomes a
// variable, the condition and the step are traced once, inside
//   for (int i = 0; i < cap; ++i) { ...; if (!active) break; ...; }
// and the new states are assigned at the end of the step.
template <class Condition, class Step, class... Rest>
void loop_while(int cap, Condition condition, Step step, TraceF& first, Rest&... rest) {
  Trace& trace = active_trace();
  auto variables = std::make_tuple(trace_detail::state_variable(first), trace_detail::state_variable(rest)...);
  const std::string counter = trace.variable(TraceType::int_, "0");
  trace.open("for (; " + counter + " < " + glsl_int(cap) + "; ++" + counter + ")");
  std::apply(
      [&](auto&... state) {
        auto next = std::make_tuple(state...);
        std::apply(
            [&](auto&... updated) {
              const TraceM active = condition(TraceF::of("float(" + counter + ")"), updated...);
              if (active.constant && !active.value) {
                trace.statement("break;");
                return;
              }
              if (!active.constant) trace.statement("if (!" + active.text + ") break;");
              step(active, updated...);
              // A new value that is another state's variable is copied
              // first: no assignment may read a variable assigned before it.
              const std::set<std::string> variables_of_states{state.text...};
              auto settle = [&](const auto& variable, auto& value) {
                if (value.text != variable.text && variables_of_states.contains(value.text))
                  value = std::decay_t<decltype(value)>::of(value.text);
              };
              (settle(state, updated), ...);
              auto assign = [&](const auto& variable, const auto& value) {
                if (variable.text != value.text) trace.statement(variable.text + " = " + value.text + ";");
              };
              (assign(state, updated), ...);
            },
            next);
      },
      variables);
  trace.close();
  std::apply(
      [&](const auto& first_variable, const auto&... rest_variables) {
        trace_detail::set_after_loop(first, first_variable);
        (trace_detail::set_after_loop(rest, rest_variables), ...);
      },
      variables);
}

}  // namespace shadetree::lanes
