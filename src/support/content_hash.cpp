#include "support/content_hash.h"

#include <cstring>

namespace sylva {
namespace {
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ULL;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBULL;
  x ^= x >> 31;
  return x;
}
}  // namespace

void ContentHash::add(std::string_view bytes) {
  std::size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t chunk;
    std::memcpy(&chunk, bytes.data() + i, 8);
    a_ = mix(a_ ^ chunk) + 0x9E3779B97F4A7C15ULL;
    b_ = mix(b_ + chunk) ^ 0xC2B2AE3D27D4EB4FULL;
  }
  std::uint64_t tail = 0;
  std::memcpy(&tail, bytes.data() + i, bytes.size() - i);
  a_ = mix(a_ ^ tail ^ (bytes.size() << 56));
  b_ = mix(b_ + tail + bytes.size());
  length_ += bytes.size();
}

void ContentHash::add(std::uint64_t value) {
  add(std::string_view(reinterpret_cast<const char*>(&value), sizeof value));
}

std::string ContentHash::hex() const {
  static const char digits[] = "0123456789abcdef";
  std::string text;
  for (std::uint64_t word : {mix(a_ ^ length_), mix(b_ + length_)})
    for (int shift = 60; shift >= 0; shift -= 4) text += digits[(word >> shift) & 15];
  return text;
}

}  // namespace sylva
