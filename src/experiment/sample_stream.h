// Random parameter values of a plan (`uniform = [a, b], samples = n`): a
// SplitMix64 stream keyed by the plan's seed and the parameter's name, so
// that the values do not depend on the platform's library, on the order of
// the parameters, or on anything but what the plan says.
#pragma once

#include <cstdint>
#include <string>

namespace sylva::experiment {

class SampleStream {
 public:
  SampleStream(long seed, const std::string& name) : state_(static_cast<std::uint64_t>(seed)) {
    for (unsigned char c : name) state_ = mix(state_ ^ c);  // the name's bytes, one by one
  }
  // Uniform in [0, 1), 53 bits.
  double next() { return static_cast<double>(mix(state_ += kGolden) >> 11) * 0x1.0p-53; }

 private:
  static constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ULL;
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

// The seed of replicate `replicate` of a plan seeded `seed`: well mixed, so
// that replicates' first draws differ as much as later ones (consecutive
// seeds start lpfg's generator from nearby states, whose first numbers are
// nearly equal), and in 1 .. 2^31 - 1, a seed every model's sran takes.
inline long replicate_seed(long seed, int replicate) {
  SampleStream stream(seed, "replicate " + std::to_string(replicate));
  return 1 + static_cast<long>(stream.next() * 2147483646.0);
}

}  // namespace sylva::experiment
