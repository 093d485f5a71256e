// A 128-bit content hash for the compiled-model cache. Not cryptographic:
// it tells apart models, not adversaries.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace sylva {

class ContentHash {
 public:
  void add(std::string_view bytes);
  void add(std::uint64_t value);
  std::string hex() const;

 private:
  std::uint64_t a_ = 0x9E3779B97F4A7C15ULL;
  std::uint64_t b_ = 0xD1B54A32D192ED03ULL;
  std::uint64_t length_ = 0;
};


}  // namespace sylva
