// The keyed random mode: ran() in a rule body draws a number that depends
// only on the pass's seed, where the module being rewritten is (its offset in
// the old string, and for modules of successors being decomposed further,
// the offsets of the modules they came from) and how many numbers the body
// drew before. So a stochastic model derives the same string however the
// string is split among threads, or whichever body runs first.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sylva::derive::keyed_random {

// Where the body about to run is: set by the engine before every body.
struct Key {
  std::uint64_t level = 0;     // the successor being expanded (0: the old string)
  std::uint64_t position = 0;  // the module's offset in it
  std::uint32_t draw = 0;      // numbers the body drew so far
};

// This thread's key.
inline thread_local Key key;

// A good 64-bit mix of two numbers (splitmix64's finalizer on their sum).
inline std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  std::uint64_t z = a * 0x9E3779B97F4A7C15ULL + b + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

inline void at_module(std::size_t position) {
  key.position = position;
  key.draw = 0;
}

// The next number in [0,1) for the body at this thread's key.
inline double draw(std::uint64_t pass_seed) {
  const std::uint64_t h = mix(mix(mix(pass_seed, key.level), key.position), key.draw++);
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);  // 2^-53
}

}  // namespace sylva::derive::keyed_random
