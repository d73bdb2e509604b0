#pragma once
// Seeded random numbers with a fixed algorithm (xoshiro256**, Box-Muller) so that results do not
// depend on the standard library's distributions.
#include <cmath>
#include <cstdint>
#include <string_view>

namespace stride::sim {

class NoiseSource {
 public:
  explicit NoiseSource(std::uint64_t seed) {
    for (auto& s : s_) s = splitmix(seed);
  }
  // A stream for one named device: independent of how many other devices exist.
  static NoiseSource for_stream(std::uint64_t seed, std::string_view name) {
    std::uint64_t h = 1469598103934665603ull;
    for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return NoiseSource(seed ^ h);
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  double gaussian(double stddev) {
    if (stddev == 0) return 0;
    if (has_spare_) {
      has_spare_ = false;
      return spare_ * stddev;
    }
    double u1 = uniform01();
    while (u1 <= 0) u1 = uniform01();
    const double u2 = uniform01();
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2 * M_PI * u2);
    has_spare_ = true;
    return r * std::cos(2 * M_PI * u2) * stddev;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitmix(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  std::uint64_t s_[4];
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace stride::sim
