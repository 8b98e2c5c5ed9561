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

namespace {
constexpr std::array<std::int32_t, 256> reference_permutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
    8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
    117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
    71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
    55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
    18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
    124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
    28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
    129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
    242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
    67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

std::array<std::int32_t, 512> doubled(const std::array<std::int32_t, 256>& table) {
  std::array<std::int32_t, 512> result{};
  for (int i = 0; i < 512; ++i) result[i] = table[i % 256];
  return result;
}
}  // namespace

const std::array<std::int32_t, 512> improved_noise_permutation = doubled(reference_permutation);

}  // namespace shadetree
