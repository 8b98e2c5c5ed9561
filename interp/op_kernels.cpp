// The interpreter's glue: each op kernel walks the lanes of a block and
// calls the op's semantics (nodes/semantics/) with F = float. Nothing here
// computes anything of its own beyond reading and writing register planes.
#include <array>

#include "interp/exec_context.h"
#include "nodes/semantics/arithmetic.h"
#include "nodes/semantics/noise.h"
#include "nodes/semantics/patterns.h"
#include "nodes/semantics/soft_objects.h"
#include "nodes/semantics/splines.h"
#include "nodes/semantics/vector.h"

namespace shadetree::interp {
namespace {

namespace sem = shadetree::semantics;
using sem::Vec3;

// Componentwise ops: out[c] = f(in0[c], in1[c], ...) for each component.
template <float (*Function)(float)>
void componentwise(const ExecContext& context) {
  for (int c = 0; c < context.out_components(); ++c) {
    const float* a = context.in(0, c);
    float* out = context.out(c);
    for_lanes(context.lanes, [&](int i) { out[i] = Function(a[i]); });
  }
}
template <float (*Function)(float, float)>
void componentwise(const ExecContext& context) {
  for (int c = 0; c < context.out_components(); ++c) {
    const float *a = context.in(0, c), *b = context.in(1, c);
    float* out = context.out(c);
    for_lanes(context.lanes, [&](int i) { out[i] = Function(a[i], b[i]); });
  }
}
template <float (*Function)(float, float, float)>
void componentwise(const ExecContext& context) {
  for (int c = 0; c < context.out_components(); ++c) {
    const float *a = context.in(0, c), *b = context.in(1, c), *d = context.in(2, c);
    float* out = context.out(c);
    for_lanes(context.lanes, [&](int i) { out[i] = Function(a[i], b[i], d[i]); });
  }
}
template <float (*Function)(float, float, float, float, float)>
void componentwise(const ExecContext& context) {
  for (int c = 0; c < context.out_components(); ++c) {
    const float *a = context.in(0, c), *b = context.in(1, c), *d = context.in(2, c), *e = context.in(3, c),
                *f = context.in(4, c);
    float* out = context.out(c);
    for_lanes(context.lanes, [&](int i) { out[i] = Function(a[i], b[i], d[i], e[i], f[i]); });
  }
}

// Bools are stored as 0 / 1.
inline float stored(bool mask) { return mask ? 1.0f : 0.0f; }
inline bool loaded(float value) { return value != 0.0f; }

template <bool (*Compare)(float, float)>
void comparison(const ExecContext& context) {
  const float *a = context.in(0), *b = context.in(1);
  float* out = context.out();
  for_lanes(context.lanes, [&](int i) { out[i] = stored(Compare(a[i], b[i])); });
}

// The component planes of a vec3 argument, fetched once per instruction.
struct Planes3 {
  const float *x, *y, *z;
  Vec3<float> at(int i) const { return {x[i], y[i], z[i]}; }
};

Planes3 planes3(const ExecContext& context, int arg) {
  return {context.in(arg, 0), context.in(arg, 1), context.in(arg, 2)};
}

Vec3<float> load3(const ExecContext& context, int arg, int i) { return planes3(context, arg).at(i); }

void store3(const ExecContext& context, int i, const Vec3<float>& value) {
  context.out(0)[i] = value.x;
  context.out(1)[i] = value.y;
  context.out(2)[i] = value.z;
}

void copy_plane(const float* from, float* to, const Lanes& lanes) {
  for_lanes(lanes, [&](int i) { to[i] = from[i]; });
}

void fill_plane(float value, float* to, const Lanes& lanes) {
  for_lanes(lanes, [&](int i) { to[i] = value; });
}

template <int Components>
void varying_input(const ExecContext& context, const float* const* planes) {
  for (int c = 0; c < Components; ++c) copy_plane(planes[c], context.out(c), context.lanes);
}

// The input of each library op, by OpId, for the table below.
OpKernel kernel_of(OpId op) {
  switch (op) {
    case OpId::P: return [](const ExecContext& x) { varying_input<3>(x, x.inputs->P); };
    case OpId::N: return [](const ExecContext& x) { varying_input<3>(x, x.inputs->N); };
    case OpId::uv: return [](const ExecContext& x) { varying_input<2>(x, x.inputs->uv); };
    case OpId::filter_width: return [](const ExecContext& x) { varying_input<1>(x, &x.inputs->filter_width); };
    case OpId::density: return [](const ExecContext& x) { varying_input<1>(x, &x.inputs->density); };
    case OpId::time: return [](const ExecContext& x) { fill_plane(x.inputs->time, x.out(), x.lanes); };
    case OpId::frame: return [](const ExecContext& x) { fill_plane(x.inputs->frame, x.out(), x.lanes); };

    case OpId::noise:
      return [](const ExecContext& x) {
        const Planes3 p = planes3(x, 0);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = sem::noise(*x.tables, p.x[i], p.y[i], p.z[i]); });
      };
    case OpId::dnoise:
      return [](const ExecContext& x) {
        const Planes3 p = planes3(x, 0);
        for_lanes(x.lanes, [&](int i) { store3(x, i, sem::dnoise(*x.tables, p.x[i], p.y[i], p.z[i])); });
      };
    case OpId::vnoise:
      return [](const ExecContext& x) {
        const Planes3 p = planes3(x, 0);
        for_lanes(x.lanes, [&](int i) { store3(x, i, sem::vnoise(*x.tables, p.x[i], p.y[i], p.z[i])); });
      };
    case OpId::noise_improved:
      return [](const ExecContext& x) {
        const Planes3 p = planes3(x, 0);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = sem::noise_improved(p.x[i], p.y[i], p.z[i]); });
      };
    case OpId::turbulence:
      return [](const ExecContext& x) {
        const Planes3 p = planes3(x, 0);
        const float *octaves = x.in(1), *filter_width = x.in(2);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) {
          out[i] = sem::turbulence(*x.tables, p.x[i], p.y[i], p.z[i], octaves[i], filter_width[i]);
        });
      };
    case OpId::fbm:
      return [](const ExecContext& x) {
        const Planes3 p = planes3(x, 0);
        const float *octaves = x.in(1), *lacunarity = x.in(2), *gain = x.in(3), *filter_width = x.in(4);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) {
          out[i] = sem::fbm(*x.tables, p.x[i], p.y[i], p.z[i], octaves[i], lacunarity[i], gain[i], filter_width[i]);
        });
      };
    case OpId::sines:
      return [](const ExecContext& x) {
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = sem::sines(x.in(0, 0)[i], x.in(0, 1)[i], x.in(1)[i], x.in(2)[i]); });
      };
    case OpId::swave: return componentwise<sem::swave<float>>;
    case OpId::julia:
      return [](const ExecContext& x) {
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) {
          out[i] = sem::julia(x.in(0, 0)[i], x.in(0, 1)[i], x.in(1, 0)[i], x.in(1, 1)[i], x.in(2)[i]);
        });
      };
    case OpId::checker:
      return [](const ExecContext& x) {
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = sem::checker(x.in(0, 0)[i], x.in(0, 1)[i], x.in(0, 2)[i]); });
      };

    case OpId::add: return componentwise<sem::add<float>>;
    case OpId::sub: return componentwise<sem::sub<float>>;
    case OpId::mul: return componentwise<sem::mul<float>>;
    case OpId::div: return componentwise<sem::div<float>>;
    case OpId::neg: return componentwise<sem::neg<float>>;
    case OpId::min: return componentwise<sem::minimum<float>>;
    case OpId::max: return componentwise<sem::maximum<float>>;
    case OpId::clamp: return componentwise<sem::clamp<float>>;
    case OpId::abs: return componentwise<sem::absolute<float>>;
    case OpId::floor: return componentwise<sem::floor_of<float>>;
    case OpId::fract: return componentwise<sem::fract<float>>;
    case OpId::mod: return componentwise<sem::mod<float>>;
    case OpId::pow: return componentwise<sem::power<float>>;
    case OpId::sqrt: return componentwise<sem::square_root<float>>;
    case OpId::exp: return componentwise<sem::exponential<float>>;
    case OpId::log: return componentwise<sem::logarithm<float>>;
    case OpId::sin: return componentwise<sem::sine<float>>;
    case OpId::cos: return componentwise<sem::cosine<float>>;
    case OpId::mix: return componentwise<sem::mix<float>>;
    case OpId::step: return componentwise<sem::step<float>>;
    case OpId::smoothstep: return componentwise<sem::smoothstep<float>>;
    case OpId::bias: return componentwise<sem::bias<float>>;
    case OpId::gain: return componentwise<sem::gain<float>>;
    case OpId::remap: return componentwise<sem::remap<float>>;

    case OpId::dot:
    case OpId::length:
    case OpId::normalize:
      return [](const ExecContext& x) {
        const int components = component_count(x.ir->code[x.instr->args[0]].type);
        const OpId op = x.instr->op;
        for_lanes(x.lanes, [&](int i) {
          float a[3], b[3], normalized[3];
          for (int c = 0; c < components; ++c) {
            a[c] = x.in(0, c)[i];
            b[c] = op == OpId::dot ? x.in(1, c)[i] : 0.0f;
          }
          if (op == OpId::dot) x.out()[i] = sem::dot_n(a, b, components);
          if (op == OpId::length) x.out()[i] = sem::length_n(a, components);
          if (op != OpId::normalize) return;
          sem::normalize_n(a, components, normalized);
          for (int c = 0; c < components; ++c) x.out(c)[i] = normalized[c];
        });
      };
    case OpId::cross:
      return [](const ExecContext& x) {
        for_lanes(x.lanes, [&](int i) { store3(x, i, sem::cross(load3(x, 0, i), load3(x, 1, i))); });
      };
    case OpId::vec2:
    case OpId::vec3:
    case OpId::color:
      return [](const ExecContext& x) {
        for (int c = 0; c < x.out_components(); ++c) copy_plane(x.in(c), x.out(c), x.lanes);
      };
    case OpId::to_color:
    case OpId::to_vec3:
      return [](const ExecContext& x) {
        for (int c = 0; c < 3; ++c) copy_plane(x.in(0, c), x.out(c), x.lanes);
      };
    case OpId::split: return nullptr;  // lowered to extract instructions

    case OpId::lt: return comparison<sem::less<float>>;
    case OpId::le: return comparison<sem::less_equal<float>>;
    case OpId::gt: return comparison<sem::greater<float>>;
    case OpId::ge: return comparison<sem::greater_equal<float>>;
    case OpId::eq: return comparison<sem::equal<float>>;
    case OpId::ne: return comparison<sem::not_equal<float>>;
    case OpId::and_:
      return [](const ExecContext& x) {
        const float *a = x.in(0), *b = x.in(1);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = stored(lanes::both(loaded(a[i]), loaded(b[i]))); });
      };
    case OpId::or_:
      return [](const ExecContext& x) {
        const float *a = x.in(0), *b = x.in(1);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = stored(lanes::either(loaded(a[i]), loaded(b[i]))); });
      };
    case OpId::not_:
      return [](const ExecContext& x) {
        const float* a = x.in(0);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = stored(lanes::negate(loaded(a[i]))); });
      };
    case OpId::select:
    case OpId::if_:
      return [](const ExecContext& x) {
        const float* condition = x.in(0);
        for (int c = 0; c < x.out_components(); ++c) {
          const float *a = x.in(1, c), *b = x.in(2, c);
          float* out = x.out(c);
          for_lanes(x.lanes, [&](int i) { out[i] = lanes::select(loaded(condition[i]), a[i], b[i]); });
        }
      };

    case OpId::spline:
      return [](const ExecContext& x) {
        const int components = x.instr->immediate[0];
        const auto basis = static_cast<sem::SplineBasis>(x.instr->immediate[1]);
        const int count = x.instr->data_count / components;
        const float* t = x.in(0);
        for (int c = 0; c < components; ++c) {
          float* out = x.out(c);
          for_lanes(x.lanes, [&](int i) { out[i] = sem::spline(x.data(), count, components, c, basis, t[i]); });
        }
      };
    case OpId::color_table:
      return [](const ExecContext& x) {
        const int components = x.instr->immediate[0], count = x.instr->immediate[1];
        const float* entries = x.data();
        const float* prefix = entries + count * components;
        const float *t = x.in(0), *width = x.in(1);
        for (int c = 0; c < components; ++c) {
          float* out = x.out(c);
          for_lanes(x.lanes, [&](int i) {
            out[i] = sem::color_table(entries, prefix, count, components, c, t[i], width[i]);
          });
        }
      };
    case OpId::table1d:
      return [](const ExecContext& x) {
        const float* t = x.in(0);
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) { out[i] = sem::table1d(x.data(), x.instr->immediate[0], t[i]); });
      };
    case OpId::table2d:
      return [](const ExecContext& x) {
        const float *u = x.in(0), *v = x.in(1);
        float* out = x.out();
        for_lanes(x.lanes,
                  [&](int i) { out[i] = sem::table2d(x.data(), x.instr->immediate[0], x.instr->immediate[1], u[i], v[i]); });
      };

    case OpId::sphere:
      return [](const ExecContext& x) {
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) {
          out[i] = sem::soft_sphere(load3(x, 0, i), load3(x, 1, i), x.in(2)[i], x.in(3)[i]);
        });
      };
    case OpId::box:
      return [](const ExecContext& x) {
        float* out = x.out();
        for_lanes(x.lanes,
                  [&](int i) { out[i] = sem::soft_box(load3(x, 0, i), load3(x, 1, i), load3(x, 2, i), x.in(3)[i]); });
      };
    case OpId::torus:
      return [](const ExecContext& x) {
        float* out = x.out();
        for_lanes(x.lanes, [&](int i) {
          out[i] = sem::soft_torus(load3(x, 0, i), load3(x, 1, i), x.in(2)[i], x.in(3)[i], x.in(4)[i]);
        });
      };
    case OpId::intersect: return componentwise<sem::soft_intersect<float>>;
    case OpId::union_: return componentwise<sem::soft_union<float>>;
    case OpId::difference: return componentwise<sem::soft_difference<float>>;
    case OpId::complement: return componentwise<sem::soft_complement<float>>;
  }
  return nullptr;
}

const std::array<OpKernel, op_count> kernels = [] {
  std::array<OpKernel, op_count> table{};
  for (int op = 0; op < op_count; ++op) table[op] = kernel_of(static_cast<OpId>(op));
  return table;
}();

}  // namespace

OpKernel op_kernel(OpId op) { return kernels[static_cast<std::size_t>(op)]; }

}  // namespace shadetree::interp
