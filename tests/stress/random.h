// A seeded random source with a fixed algorithm (SplitMix64), so that a seed names the same case
// with every compiler and standard library: std::uniform_*_distribution are not portable across
// library versions, so every value is derived here from the raw 64-bit stream.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hullcook::stress {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  // Uniform in [low, high], both included (the modulo bias is below 2^-32 for these ranges).
  int integer(int low, int high) {
    const std::uint64_t span = static_cast<std::uint64_t>(high - low) + 1;
    return low + static_cast<int>(next() % span);
  }

  bool chance(double probability) { return uniform() < probability; }

  template <typename T>
  const T& pick(const std::vector<T>& values) {
    return values[static_cast<std::size_t>(integer(0, static_cast<int>(values.size()) - 1))];
  }

 private:
  std::uint64_t state_;
};

// Mixes two values into one seed (SplitMix64's finaliser over their combination), so that the
// streams of (seed, family) pairs are unrelated.
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t salt) {
  Random random(seed ^ (salt * 0xD1B54A32D192ED03ull));
  return random.next();
}

}  // namespace hullcook::stress
