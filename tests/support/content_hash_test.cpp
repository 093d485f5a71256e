// The cache's content hash: equal input, equal key; any change to the bytes,
// their order or where one piece ends and the next begins, another key.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "support/content_hash.h"

namespace sylva {
namespace {

std::string hash_of(std::initializer_list<std::string_view> pieces) {
  ContentHash h;
  for (std::string_view p : pieces) h.add(p);
  return h.hex();
}

TEST(ContentHash, ThirtyTwoHexDigits) {
  const std::string hex = hash_of({"model"});
  EXPECT_EQ(hex.size(), 32u);
  EXPECT_EQ(hex.find_first_not_of("0123456789abcdef"), std::string::npos) << hex;
}

TEST(ContentHash, SameInputSameKey) {
  EXPECT_EQ(hash_of({"module A;", "g++"}), hash_of({"module A;", "g++"}));
  EXPECT_EQ(hash_of({}), hash_of({}));
}

TEST(ContentHash, EveryDifferenceChangesTheKey) {
  const std::string long_text(1000, 'x');
  std::string one_bit = long_text;
  one_bit[517] ^= 1;
  const std::set<std::string> keys = {
      hash_of({}),
      hash_of({""}),  // an empty piece still counts
      hash_of({"", ""}),
      hash_of({"ab", "c"}),
      hash_of({"a", "bc"}),  // the same bytes split elsewhere
      hash_of({"c", "ab"}),  // in another order
      hash_of({"abc"}),
      hash_of({"abcdefgh"}),  // one 8-byte chunk
      hash_of({"abcdefgi"}),
      hash_of({long_text}),
      hash_of({one_bit}),
  };
  EXPECT_EQ(keys.size(), 11u);
}

TEST(ContentHash, NumbersHashAsTheirBytes) {
  ContentHash number, bytes;
  const std::uint64_t value = 0x0102030405060708ULL;
  number.add(value);
  bytes.add(std::string_view(reinterpret_cast<const char*>(&value), sizeof value));
  EXPECT_EQ(number.hex(), bytes.hex());
  ContentHash other;
  other.add(std::uint64_t{0x0102030405060709ULL});
  EXPECT_NE(number.hex(), other.hex());
}

}  // namespace
}  // namespace sylva
