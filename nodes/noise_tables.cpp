#include "nodes/noise_tables.h"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>

namespace shadetree {
namespace {

// splitmix64 (Steele, Lea & Flood 2014): small, seedable and the same on
// every platform, which std::uniform_*_distribution is not.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [-1, 1], from the top 53 bits.
  double symmetric_unit() { return (next() >> 11) * (2.0 / 9007199254740992.0) - 1.0; }
  std::uint32_t below(std::uint32_t bound) { return static_cast<std::uint32_t>(next() % bound); }

 private:
  std::uint64_t state_;
};

}  // namespace

NoiseTables make_noise_tables(std::uint32_t seed) {
  NoiseTables tables{};
  SplitMix64 random(seed);
  for (int i = 0; i < noise_table_size; ++i) tables.permutation[i] = i;
  for (int i = noise_table_size - 1; i > 0; --i)
    std::swap(tables.permutation[i], tables.permutation[random.below(i + 1)]);

  // 1989 section 2.3: (1) coordinates uniform in [-1,1], (2) retry if
  // |v| > 1, (3) normalize. Tiny vectors are retried too, so that
  // normalizing them cannot amplify rounding.
  for (int i = 0; i < noise_table_size; ++i) {
    double x, y, z, length_squared;
    do {
      x = random.symmetric_unit();
      y = random.symmetric_unit();
      z = random.symmetric_unit();
      length_squared = x * x + y * y + z * z;
    } while (length_squared > 1.0 || length_squared < 1e-4);
    const double length = std::sqrt(length_squared);
    tables.gradient_x[i] = static_cast<float>(x / length);
    tables.gradient_y[i] = static_cast<float>(y / length);
    tables.gradient_z[i] = static_cast<float>(z / length);
  }
  for (int i = 0; i < noise_table_size; ++i) {
    tables.hashed_gradient_x[i] = tables.gradient_x[tables.permutation[i]];
    tables.hashed_gradient_y[i] = tables.gradient_y[tables.permutation[i]];
    tables.hashed_gradient_z[i] = tables.gradient_z[tables.permutation[i]];
  }
  for (GradientTable* table : {&tables.gradient_x, &tables.gradient_y, &tables.gradient_z, &tables.hashed_gradient_x,
                               &tables.hashed_gradient_y, &tables.hashed_gradient_z})
    (*table)[noise_table_size] = (*table)[0];
  tables.permutation[noise_table_size] = tables.permutation[0];
  for (int i = 0; i <= noise_table_size; ++i) {
    tables.hashed_gradient_xyzw[4 * i + 0] = tables.hashed_gradient_x[i];
    tables.hashed_gradient_xyzw[4 * i + 1] = tables.hashed_gradient_y[i];
    tables.hashed_gradient_xyzw[4 * i + 2] = tables.hashed_gradient_z[i];
    tables.hashed_gradient_xyzw[4 * i + 3] = tables.gradient_x[i];
  }
  return tables;
}

const NoiseTables& noise_tables(std::uint32_t seed) {
  static std::mutex mutex;
  static std::map<std::uint32_t, std::unique_ptr<NoiseTables>> cache;
  std::lock_guard lock(mutex);
  auto& slot = cache[seed];
  if (!slot) slot = std::make_unique<NoiseTables>(make_noise_tables(seed));
  return *slot;
}

}  // namespace shadetree
