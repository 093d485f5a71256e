// The packed module string: [id][parameters][id] per module, or [id] alone
// without parameters, walked forward and backward with nothing but the table
// of sizes; views of part of it; growth, moves and copies of the bytes; the
// buffer built from its end.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "derive/context_matcher.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"
#include "sylva/predefined_ids.h"

namespace sylva::test {
namespace {

// SB, EB, then P with a double, Q with nothing, R with three ints: modules of
// 10, 1 and 14 bytes (one-byte ids), so a walk that got a size wrong lands
// off a boundary.
class ModuleStringTest : public ::testing::Test {
 protected:
  static constexpr ModuleId kSB = 0, kEB = 1, kP = 2, kQ = 3, kR = 4;
  ModuleTypes types_{{{"SB", 0}, {"EB", 0}, {"P", sizeof(double)}, {"Q", 0}, {"R", 3 * sizeof(int)}}};

  static void add_p(ModuleString& s, double v) { s.append_module(kP, &v, sizeof v); }
  static void add_r(ModuleString& s, int a, int b, int c) {
    const int v[3] = {a, b, c};
    s.append_module(kR, v, sizeof v);
  }
  static void add(ModuleString& s, ModuleId id) { s.append_module(id, nullptr, 0); }

  // P(1.5) Q R(1,2,3) [ Q ] P(-2)
  ModuleString sample() const {
    ModuleString s;
    add_p(s, 1.5);
    add(s, kQ);
    add_r(s, 1, 2, 3);
    add(s, kSB);
    add(s, kQ);
    add(s, kEB);
    add_p(s, -2);
    return s;
  }

  std::vector<ModuleId> forward_ids(const StringView& v) const {
    std::vector<ModuleId> ids;
    for (std::size_t at = v.begin; at < v.end; at = v.next(at)) ids.push_back(v.id_at(at));
    return ids;
  }
  std::vector<ModuleId> backward_ids(const StringView& v) const {
    std::vector<ModuleId> ids;
    for (std::size_t at = v.end; at > v.begin; at = v.previous(at)) ids.push_back(module_id_before(v.data, at));
    return ids;
  }
};

TEST_F(ModuleStringTest, EachModuleIsItsIdItsParametersAndItsIdAgain) {
  ModuleString s;
  add_r(s, 7, 8, 9);
  ASSERT_EQ(s.size_bytes(), 1 + 3 * sizeof(int) + 1);
  EXPECT_EQ(module_id_at(s.data(), 0), kR);
  int params[3];
  std::memcpy(params, module_params(s.data(), 0), sizeof params);
  EXPECT_EQ(params[0], 7);
  EXPECT_EQ(params[2], 9);
  EXPECT_EQ(module_id_before(s.data(), s.size_bytes()), kR);
  EXPECT_EQ(types_.encoded_size(kR), s.size_bytes());
}

TEST_F(ModuleStringTest, AModuleWithoutParametersIsItsIdAlone) {
  ModuleString s;
  add(s, kQ);
  ASSERT_EQ(s.size_bytes(), 1u);
  EXPECT_EQ(types_.encoded_size(kQ), 1u);
  EXPECT_EQ(module_id_at(s.data(), 0), kQ);
  EXPECT_EQ(module_id_before(s.data(), s.size_bytes()), kQ);
  add_p(s, 4);
  add(s, kQ);
  const StringView v = s.view(types_);
  EXPECT_EQ(forward_ids(v), (std::vector<ModuleId>{kQ, kP, kQ}));
  EXPECT_EQ(backward_ids(v), (std::vector<ModuleId>{kQ, kP, kQ}));
  EXPECT_EQ(v.previous(v.previous(v.end)), 1u);
}

// Ids from 255 on: 0xFF and the id's two bytes (low first) at the start, the
// two bytes and 0xFF at the end, and 0xFF id 0xFF without parameters; so
// they walk both ways beside one-byte ids, even where a parameter or the id
// itself holds a 0xFF byte.
TEST(ModuleStringWideIds, TakeThreeBytesAtEachEnd) {
  std::vector<ModuleTypes::Type> table(600);
  for (std::size_t k = 0; k < table.size(); ++k) table[k].name = "M" + std::to_string(k);
  table[0x1FF].param_size = sizeof(float);
  const ModuleTypes types(std::move(table));
  EXPECT_EQ(types.encoded_size(254), 1u);
  EXPECT_EQ(types.encoded_size(255), 4u);
  EXPECT_EQ(types.encoded_size(0x1FF), 4u + 6u);

  ModuleString s;
  const float param = -1;  // bits 0xBF800000
  s.append_module(0x1FF, &param, sizeof param);
  s.append_module(7, nullptr, 0);
  s.append_module(0x12C, nullptr, 0);
  s.append_module(254, nullptr, 0);
  const unsigned char expected[] = {0xFF, 0xFF, 0x01, 0x00, 0x00, 0x80, 0xBF, 0xFF, 0x01, 0xFF,
                                    7,    0xFF, 0x2C, 0x01, 0xFF, 254};
  ASSERT_EQ(s.size_bytes(), sizeof expected);
  EXPECT_EQ(std::memcmp(s.data(), expected, sizeof expected), 0);

  const StringView v = s.view(types);
  std::vector<ModuleId> forward, backward;
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) forward.push_back(v.id_at(at));
  for (std::size_t at = v.end; at > v.begin; at = v.previous(at)) backward.push_back(module_id_before(v.data, at));
  EXPECT_EQ(forward, (std::vector<ModuleId>{0x1FF, 7, 0x12C, 254}));
  EXPECT_EQ(backward, (std::vector<ModuleId>{254, 0x12C, 7, 0x1FF}));
  float read;
  std::memcpy(&read, module_params(s.data(), 0), sizeof read);
  EXPECT_EQ(read, -1.0f);
}

TEST_F(ModuleStringTest, WalksForwardAndBackward) {
  const ModuleString s = sample();
  const StringView v = s.view(types_);
  EXPECT_EQ(forward_ids(v), (std::vector<ModuleId>{kP, kQ, kR, kSB, kQ, kEB, kP}));
  EXPECT_EQ(backward_ids(v), (std::vector<ModuleId>{kP, kEB, kQ, kSB, kR, kQ, kP}));
  EXPECT_EQ(s.count_modules(types_), 7u);
  // 10 + 1 + 14 + 1 + 1 + 1 + 10 bytes.
  EXPECT_EQ(s.size_bytes(), 38u);
  double last;
  std::memcpy(&last, module_params(s.data(), v.previous(v.end)), sizeof last);
  EXPECT_EQ(last, -2);
}

TEST_F(ModuleStringTest, AViewCoversPartOfTheString) {
  const ModuleString s = sample();
  StringView part = s.view(types_);
  part.begin = 10 + 1;  // from R
  part.end = part.begin + 14 + 1 + 1 + 1;  // through the branch
  EXPECT_EQ(forward_ids(part), (std::vector<ModuleId>{kR, kSB, kQ, kEB}));
  EXPECT_EQ(backward_ids(part), (std::vector<ModuleId>{kEB, kQ, kSB, kR}));
}

TEST_F(ModuleStringTest, BranchesAreSkippedWholeWhateverTheModuleSizes) {
  // P [ R(1,2,3) [ P(0) ] Q ] Q: 0 P, 1 [, 2 R, 3 [, 4 P, 5 ], 6 Q, 7 ], 8 Q
  ModuleString s;
  add_p(s, 5);
  add(s, kSB);
  add_r(s, 1, 2, 3);
  add(s, kSB);
  add_p(s, 0);
  add(s, kEB);
  add(s, kQ);
  add(s, kEB);
  add(s, kQ);
  const StringView v = s.view(types_);
  std::vector<std::size_t> at = {v.begin};
  while (at.back() < v.end) at.push_back(v.next(at.back()));
  // These helpers find the brackets by the predefined ids.
  ASSERT_EQ(kSB, rt::mid::SB);
  ASSERT_EQ(kEB, rt::mid::EB);
  EXPECT_EQ(derive::skip_branch_forward(v, at[1]), at[8]);
  EXPECT_EQ(derive::skip_branch_forward(v, at[3]), at[6]);
  EXPECT_EQ(derive::skip_branch_backward(v, at[7]), at[1]);
  EXPECT_EQ(derive::find_unmatched_end(v, at[2]), at[7]);
}

TEST_F(ModuleStringTest, GrowsKeepingWhatItHolds) {
  ModuleString s;
  for (int k = 0; k < 10000; ++k) add_r(s, k, -k, 2 * k);
  EXPECT_EQ(s.count_modules(types_), 10000u);
  const StringView v = s.view(types_);
  std::size_t at = v.begin;
  for (int k = 0; k < 9999; ++k) at = v.next(at);
  int params[3];
  std::memcpy(params, module_params(s.data(), at), sizeof params);
  EXPECT_EQ(params[0], 9999);
  EXPECT_EQ(params[1], -9999);
  EXPECT_EQ(params[2], 19998);
}

TEST_F(ModuleStringTest, MovesAssignsAndTruncates) {
  ModuleString s = sample();
  const std::size_t size = s.size_bytes();
  ModuleString moved = std::move(s);
  EXPECT_EQ(moved.size_bytes(), size);
  EXPECT_TRUE(s.empty());  // NOLINT: a moved-from string is empty and usable
  add(s, kQ);
  EXPECT_EQ(s.count_modules(types_), 1u);

  ModuleString copy;
  copy.assign(moved.data(), moved.size_bytes());
  EXPECT_EQ(std::memcmp(copy.data(), moved.data(), size), 0);
  copy.truncate(10 + 1);  // P(1.5) Q
  EXPECT_EQ(forward_ids(copy.view(types_)), (std::vector<ModuleId>{kP, kQ}));
  copy.clear();
  EXPECT_TRUE(copy.empty());
}

// Swapped, two strings exchange modules, known starts and buffers, and
// each goes on growing in the buffer it took.
TEST_F(ModuleStringTest, SwapsExchangeEverything) {
  ModuleString mapped;
  mapped.reserve_unwritten(2 << 20);
  ModuleString own = sample();  // own: P 0, Q 10, R 11, [ 25, Q 26, ] 27, P 28
  own.set_known_module_starts({0, 11});
  add(mapped, kQ);
  const unsigned char* own_data = own.data();
  const unsigned char* mapped_data = mapped.data();
  swap(mapped, own);
  EXPECT_EQ(mapped.data(), own_data);
  EXPECT_EQ(mapped.known_module_starts(), (std::vector<std::size_t>{0, 11}));
  EXPECT_EQ(forward_ids(mapped.view(types_)), forward_ids(sample().view(types_)));
  EXPECT_EQ(own.data(), mapped_data);
  EXPECT_GE(own.reserved_bytes(), std::size_t{2} << 20);
  EXPECT_TRUE(own.known_module_starts().empty());
  EXPECT_EQ(forward_ids(own.view(types_)), std::vector<ModuleId>{kQ});
  for (int k = 0; k < 420; ++k) add_p(own, k);
  EXPECT_EQ(own.data(), mapped_data);
  EXPECT_EQ(own.count_modules(types_), 421u);
}

// A string written in place (a parallel pass's parts copied into it): the
// bytes written survive its growth, and set_written_size makes them its
// modules.
TEST_F(ModuleStringTest, BytesWrittenInPlaceSurviveGrowth) {
  ModuleString whole;
  whole.reserve_unwritten(2 << 20);
  ModuleString part;
  add_p(part, 1.5);
  std::memcpy(whole.data_for_writing(), part.data(), part.size_bytes());
  whole.reserve_unwritten_keeping(64 << 20);
  EXPECT_GE(whole.reserved_bytes(), std::size_t{64} << 20);
  double value;
  std::memcpy(&value, module_params(whole.data(), 0), sizeof value);
  EXPECT_EQ(value, 1.5);
  whole.set_written_size(10);
  EXPECT_EQ(forward_ids(whole.view(types_)), std::vector<ModuleId>{kP});
}

// Module starts a parallel pass knows: kept while the string only grows,
// cut with it, dropped when it is replaced or emptied, carried by moves.
TEST_F(ModuleStringTest, KnownModuleStartsFollowTheString) {
  ModuleString s = sample();  // P 0, Q 10, R 11, [ 25, Q 26, ] 27, P 28
  s.set_known_module_starts({0, 11, 26});
  add(s, kQ);
  EXPECT_EQ(s.known_module_starts(), (std::vector<std::size_t>{0, 11, 26}));
  s.truncate(25);
  EXPECT_EQ(s.known_module_starts(), (std::vector<std::size_t>{0, 11}));
  ModuleString moved = std::move(s);
  EXPECT_EQ(moved.known_module_starts(), (std::vector<std::size_t>{0, 11}));
  moved.assign(sample().data(), sample().size_bytes());
  EXPECT_TRUE(moved.known_module_starts().empty());
  moved.set_known_module_starts({0});
  moved.clear();
  EXPECT_TRUE(moved.known_module_starts().empty());
}

// A pass notes where modules start as it writes, no closer together than
// asked: P (10 bytes) at 0, Q (1 byte) at 10, R at 11.
TEST_F(ModuleStringTest, NotedModuleStartsAreSpacedAsAsked) {
  ModuleString s;
  s.note_module_start(11);
  add_p(s, 1);
  s.note_module_start(11);  // 10 bytes after the last: not noted
  add(s, kQ);
  s.note_module_start(11);  // 11 bytes after: noted
  add(s, kQ);
  EXPECT_EQ(s.known_module_starts(), (std::vector<std::size_t>{0, 11}));
  s.truncate(11);  // the module noted at 11 is gone
  EXPECT_EQ(s.known_module_starts(), (std::vector<std::size_t>{0}));
}

TEST_F(ModuleStringTest, PrependBufferBuildsFromTheEnd) {
  ModuleString p, q;
  add_p(p, 3);
  add(q, kQ);
  PrependBuffer b;
  for (int k = 0; k < 1000; ++k) {
    b.prepend(q.data(), q.size_bytes());
    b.prepend(p.data(), p.size_bytes());
  }
  EXPECT_EQ(b.size_bytes(), 1000 * (10u + 1u));
  const StringView v{b.data(), b.begin(), b.end(), types_.encoded_sizes()};
  const std::vector<ModuleId> ids = forward_ids(v);
  ASSERT_EQ(ids.size(), 2000u);
  EXPECT_EQ(ids.front(), kP);  // the last prepended comes first
  EXPECT_EQ(ids.back(), kQ);
  b.clear();
  EXPECT_EQ(b.size_bytes(), 0u);
}

// A string takes what a PrependBuffer built, buffer and all; the
// PrependBuffer, emptied, builds on in the string's old buffer.
TEST_F(ModuleStringTest, AStringTakesWhatAPrependBufferBuilt) {
  ModuleString q;
  add(q, kQ);
  PrependBuffer b;
  b.reserve_more(1 << 21);  // mapped: larger than a megabyte
  for (int k = 0; k < 3; ++k) b.prepend(q.data(), q.size_bytes());
  ModuleString p;
  add_p(p, 3);
  b.prepend(p.data(), p.size_bytes());
  ModuleString s = sample();
  s.take(b);
  EXPECT_EQ(forward_ids(s.view(types_)), (std::vector<ModuleId>{kP, kQ, kQ, kQ}));
  EXPECT_EQ(b.size_bytes(), 0u);
  b.prepend(q.data(), q.size_bytes());
  EXPECT_EQ(b.size_bytes(), 1u);
  add(s, kSB);  // the string grows on in the buffer it took
  EXPECT_EQ(backward_ids(s.view(types_)), (std::vector<ModuleId>{kSB, kQ, kQ, kQ, kP}));
}

}  // namespace
}  // namespace sylva::test
