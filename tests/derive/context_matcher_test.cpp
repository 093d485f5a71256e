// Context matching on branching strings (LPFG manual, chapter 9 "Production
// Matching", with 3.1.2-3.1.3, 4.2, 4.3 and 5.4). The first half calls the
// matcher directly on hand-built strings; the second runs tiny L+C models
// through the engine. Every expected answer is worked out by hand from the
// manual's rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "derive/context_matcher.h"
#include "io/string_text.h"
#include "lstring/branch_index.h"
#include "lstring/built_branches.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"
#include "sylva/predefined_ids.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using derive::ContextCursor;
using derive::find_unmatched_end;
using derive::match_left_context;
using derive::match_left_context_here;
using derive::match_right_context;
using derive::match_right_context_here;
using derive::SkipTable;
using derive::skip_branch_backward;
using derive::skip_branch_forward;

// ---- direct tests of the matcher ---------------------------------------------

// Types: the predefined modules with their real ids, then A(int) B(int) C
// D(int) E. Strings are written as text: "[" is SB, "]" is EB, "A(1)" sets
// the int parameter.
class ContextMatcherTest : public ::testing::Test {
 protected:
  ContextMatcherTest() : types_(make_types()) {}

  static ModuleTypes make_types() {
    std::vector<ModuleTypes::Type> t;
#define SYLVA_MODULE(name, ...) t.push_back({#name, 0, nullptr});
#include <sylva/predefined_modules.def>
    for (const char* name : {"A", "B", "C", "D", "E"}) {
      const bool has_int = std::strcmp(name, "C") != 0 && std::strcmp(name, "E") != 0;
      t.push_back({name, has_int ? static_cast<std::uint32_t>(sizeof(int)) : 0u, nullptr});
    }
    return ModuleTypes(std::move(t));
  }

  ModuleId id(const std::string& name) const {
    if (name == "[") return rt::mid::SB;
    if (name == "]") return rt::mid::EB;
    auto found = types_.find(name);
    EXPECT_TRUE(found.has_value()) << name;
    return found.value_or(0);
  }

  ModuleString parse(const std::string& text) const {
    ModuleString s;
    std::istringstream in(text);
    for (std::string word; in >> word;) {
      const std::size_t paren = word.find('(');
      const ModuleId m = id(word.substr(0, paren));
      int value = paren == std::string::npos ? 0 : std::stoi(word.substr(paren + 1));
      s.append_module(m, &value, types_[m].param_size);
    }
    return s;
  }

  std::vector<ModuleId> pattern(const std::string& text) const {
    std::vector<ModuleId> ids;
    std::istringstream in(text);
    for (std::string word; in >> word;) ids.push_back(id(word));
    return ids;
  }

  // Byte offset of module number `index` (the end of the string past the last).
  std::size_t offset(const ModuleString& s, int index) const {
    const StringView v = s.view(types_);
    std::size_t at = v.begin;
    for (int k = 0; k < index && at < v.end; ++k) at = v.next(at);
    return at;
  }
  int index_at(const ModuleString& s, std::size_t byte_offset) const {
    const StringView v = s.view(types_);
    int k = 0;
    for (std::size_t at = v.begin; at < byte_offset && at < v.end; at = v.next(at)) ++k;
    return k;
  }

  // "index:Name(param) ..." for the modules the pattern was bound to, read
  // back from the parameter pointers; "no match" on failure.
  std::string describe(const ModuleString& s, bool ok, const std::vector<const unsigned char*>& params) const {
    if (!ok) return "no match";
    std::string out;
    for (const unsigned char* p : params) {
      const std::size_t at = static_cast<std::size_t>(p - s.data()) - 1;  // one-byte ids
      const ModuleId m = module_id_at(s.data(), at);
      std::string name = m == rt::mid::SB ? "[" : m == rt::mid::EB ? "]" : types_.name(m);
      if (types_[m].param_size == sizeof(int)) {
        int value;
        std::memcpy(&value, p, sizeof value);
        name += "(" + std::to_string(value) + ")";
      }
      out += (out.empty() ? "" : " ") + std::to_string(index_at(s, at)) + ":" + name;
    }
    return out;
  }

  // Right context `pat` from module number `pos` (the module just after the strict predecessor).
  std::string right(const std::string& str, int pos, const std::string& pat,
                    const std::vector<std::uint8_t>* skip = nullptr) const {
    return match(true, str, pos, pat, skip);
  }
  // Left context `pat` for the strict predecessor starting at module number `pos`.
  std::string left(const std::string& str, int pos, const std::string& pat,
                   const std::vector<std::uint8_t>* skip = nullptr) const {
    return match(false, str, pos, pat, skip);
  }
  std::string match(bool right, const std::string& str, int pos, const std::string& pat,
                    const std::vector<std::uint8_t>* skip) const {
    ModuleString s = parse(str);
    const std::vector<ModuleId> p = pattern(pat);
    std::vector<const unsigned char*> params(p.size()), quick_params(p.size());
    const StringView v = s.view(types_);
    const int n = static_cast<int>(p.size());
    const SkipTable table = skip ? skip->data() : nullptr;
    ContextCursor walked{offset(s, pos), false}, quick = walked;
    const bool ok = right ? match_right_context(v, walked, p.data(), n, table, params.data())
                          : match_left_context(v, walked, p.data(), n, table, params.data());
    // The inline first try decides as the walk does, and leaves the cursor where it does.
    const bool quick_ok = right ? match_right_context_here(v, quick, p.data(), n, table, quick_params.data())
                                : match_left_context_here(v, quick, p.data(), n, table, quick_params.data());
    EXPECT_EQ(quick_ok, ok) << str << (right ? " > " : " < ") << pat;
    if (ok) {
      EXPECT_EQ(quick_params, params) << str << (right ? " > " : " < ") << pat;
      EXPECT_EQ(quick.at, walked.at) << str << (right ? " > " : " < ") << pat;
    }
    return describe(s, ok, params);
  }

  // Tables as written, without clearing SB/EB: the matcher must still count them.
  std::vector<std::uint8_t> ignoring(const std::string& names) const {
    std::vector<std::uint8_t> t(types_.size(), 0);
    for (ModuleId m : pattern(names)) t[m] = 1;
    return t;
  }
  std::vector<std::uint8_t> considering(const std::string& names) const {
    std::vector<std::uint8_t> t(types_.size(), 1);
    for (ModuleId m : pattern(names)) t[m] = 0;
    return t;
  }

  // A random branching string of `modules` modules, brackets mostly
  // balanced, with stray ]s and [s left open.
  ModuleString random_tree(unsigned seed, int modules) const {
    std::mt19937 random(seed);
    ModuleString s;
    int open = 0;
    for (int k = 0; k < modules; ++k) {
      const unsigned roll = random() % 100;
      int value = k;
      ModuleId m;
      if (roll < 22) m = rt::mid::SB, ++open;
      else if (roll < 42 && open > 0) m = rt::mid::EB, --open;
      else if (roll < 43) m = rt::mid::EB;  // a stray ]
      else m = id(std::string(1, static_cast<char>('A' + random() % 5)));
      s.append_module(m, &value, types_[m].param_size);
    }
    return s;
  }

  ModuleTypes types_;
};

// Strict predecessor: "must match exactly" is the engine's job; here the
// types line up with predefined_modules.def as the matcher assumes.
TEST_F(ContextMatcherTest, PredefinedIdsLineUpWithTheDefFile) {
  EXPECT_EQ(types_.name(rt::mid::SB), "SB");
  EXPECT_EQ(types_.name(rt::mid::EB), "EB");
  EXPECT_EQ(types_.name(rt::mid::Cut), "Cut");
  EXPECT_EQ(*types_.find("A"), rt::mid::PredefinedCount);
}

// Skip helpers: a whole branch forward (past its ]), nested branches included.
TEST_F(ContextMatcherTest, SkipBranchForwardGoesPastTheMatchingBracket) {
  ModuleString s = parse("A [ B [ C ] ] D");  // 0 A, 1 [, 2 B, 3 [, 4 C, 5 ], 6 ], 7 D
  const StringView v = s.view(types_);
  EXPECT_EQ(index_at(s, skip_branch_forward(v, offset(s, 1))), 7);
  EXPECT_EQ(index_at(s, skip_branch_forward(v, offset(s, 3))), 6);
  ModuleString open = parse("A [ B");  // never closed: the end of the string
  EXPECT_EQ(skip_branch_forward(open.view(types_), offset(open, 1)), open.size_bytes());
}

// Skip helpers: the first unmatched ] ("skipping to the first unmatched ]").
TEST_F(ContextMatcherTest, FindUnmatchedEndSkipsNestedBranches) {
  ModuleString s = parse("A [ B [ C ] D ] E");  // 0 A, 1 [, 2 B, 3 [, 4 C, 5 ], 6 D, 7 ], 8 E
  const StringView v = s.view(types_);
  EXPECT_EQ(index_at(s, find_unmatched_end(v, offset(s, 2))), 7);  // the ] of [C] is matched
  EXPECT_EQ(index_at(s, find_unmatched_end(v, offset(s, 4))), 5);
  EXPECT_EQ(find_unmatched_end(v, offset(s, 8)), s.size_bytes());  // top level: the end
}

// Skip helpers: from a ] back to its [.
TEST_F(ContextMatcherTest, SkipBranchBackwardFindsTheOpeningBracket) {
  ModuleString s = parse("A [ B [ C ] ] D");
  const StringView v = s.view(types_);
  EXPECT_EQ(index_at(s, skip_branch_backward(v, offset(s, 6))), 1);
  EXPECT_EQ(index_at(s, skip_branch_backward(v, offset(s, 5))), 3);
}

// Right context, rule 1: a [ where the pattern does not expect one skips the whole branch.
TEST_F(ContextMatcherTest, RightContextSkipsLateralBranch) {
  EXPECT_EQ(right("A(1) [ B(2) C ] D(3)", 1, "D"), "5:D(3)");
  EXPECT_EQ(right("A(1) [ B(2) ] [ C ] [ D(9) ] D(3)", 1, "D"), "10:D(3)");  // several branches
  EXPECT_EQ(right("A(1) [ B(2) [ D(8) ] ] D(3)", 1, "D"), "7:D(3)");        // nested ones inside
}

// Right context, rule 1: the lateral branch is not "to the right" unless [ is written.
TEST_F(ContextMatcherTest, RightContextDoesNotLookIntoBranchWithoutBracket) {
  EXPECT_EQ(right("A(1) [ B(2) ] D(3)", 1, "B"), "no match");
  EXPECT_EQ(right("A(1) [ B(2) ] D(3)", 1, "[ B"), "1:[ 2:B(2)");
}

// Right context, rule 3 (Figure 4): only the first of several lateral branches is tested.
TEST_F(ContextMatcherTest, RightContextChecksOnlyFirstLateralBranch) {
  EXPECT_EQ(right("A [ B(1) ] [ C ] D", 1, "[ C"), "no match");
  EXPECT_EQ(right("A [ C ] [ B(1) ] D", 1, "[ C"), "1:[ 2:C");
}

// Right context, Figure 5: enumerating brackets reaches the second branch.
TEST_F(ContextMatcherTest, RightContextEnumeratedBracketsReachLaterBranches) {
  // [ ] : enter the first branch and leave it at once (the rest, B(1), is skipped).
  EXPECT_EQ(right("A [ B(1) ] [ C ] D", 1, "[ ] [ C"), "1:[ 3:] 4:[ 5:C");
  EXPECT_EQ(right("A [ B(1) ] [ C ] D", 1, "[ B ] [ C ] D"), "1:[ 2:B(1) 3:] 4:[ 5:C 6:] 7:D(0)");
}

// Right context with explicit SB..EB: `A > [B] C`.
TEST_F(ContextMatcherTest, RightContextExplicitBranchThenParentAxis) {
  EXPECT_EQ(right("A(1) [ B(2) ] C", 1, "[ B ] C"), "1:[ 2:B(2) 3:] 4:C");
  EXPECT_EQ(right("A(1) [ B(2) ] D(3) C", 1, "[ B ] C"), "no match");  // D is in the way
  EXPECT_EQ(right("A(1) B(2) C", 1, "[ B ] C"), "no match");           // no branch at all
}

// Right context, rule 2 (Figure 3): after an expected ], the rest of the
// branch is skipped up to the first unmatched ].
TEST_F(ContextMatcherTest, RightContextBracketSkipsRestOfBranch) {
  EXPECT_EQ(right("A [ B(2) C D(4) ] E", 1, "[ B ] E"), "1:[ 2:B(2) 5:] 6:E");
  // A nested branch in the rest: its ] is not the unmatched one.
  EXPECT_EQ(right("A [ B(2) C [ D(5) ] E ] D(7)", 1, "[ B ] D"), "1:[ 2:B(2) 8:] 9:D(7)");
  // The pattern's ] alone: from inside a branch, to its end.
  EXPECT_EQ(right("A [ B(2) C D(4) ] E", 3, "] E"), "5:] 6:E");
}

// Right context fails at the end of a branch: the module after ] is not to the right.
TEST_F(ContextMatcherTest, RightContextFailsAtEndOfBranch) {
  EXPECT_EQ(right("A [ B(2) ] C", 3, "C"), "no match");
  EXPECT_EQ(right("A [ B(2) ] C", 3, "] C"), "3:] 4:C");
}

// Right context failure cases: a different module, the end of the string, a missing [.
TEST_F(ContextMatcherTest, RightContextFailures) {
  EXPECT_EQ(right("A B(1) C", 1, "C"), "no match");
  EXPECT_EQ(right("A B(1)", 1, "B C"), "no match");
  EXPECT_EQ(right("A B(1) [ C ]", 1, "[ C"), "no match");
  EXPECT_EQ(right("A", 1, "B"), "no match");
  EXPECT_EQ(right("A B(1) C", 1, "B C"), "1:B(1) 2:C");  // control: two modules in a row
}

// Left context, rule 1 (Figure 6): [ is skipped, the parent lies before the branch.
TEST_F(ContextMatcherTest, LeftContextSkipsOpeningBracket) {
  EXPECT_EQ(left("A(1) [ B(2) C ] D(3)", 2, "A"), "0:A(1)");
  EXPECT_EQ(left("A(1) [ [ B(2) ] ]", 3, "A"), "0:A(1)");  // several [ in a row
}

// Left context, rule 2 (Figure 7): a sibling branch ending in ] is skipped whole.
TEST_F(ContextMatcherTest, LeftContextSkipsWholeSiblingBranches) {
  EXPECT_EQ(left("A(1) [ B(2) C ] D(3)", 5, "A"), "0:A(1)");
  EXPECT_EQ(left("A(1) [ B(2) C ] D(3)", 5, "C"), "no match");  // the sibling is not the parent
  // Both branches of a branching point have A as parent (Figure 6/7 together).
  EXPECT_EQ(left("A(1) [ B(2) ] [ C ] D(3)", 5, "A"), "0:A(1)");
  EXPECT_EQ(left("A(1) [ B(2) [ D(4) ] ] D(3)", 7, "A"), "0:A(1)");  // nested inside the sibling
}

// Left context sees the path to the root, across [ and whole branches.
TEST_F(ContextMatcherTest, LeftContextFollowsPathToRoot) {
  // 0 A, 1 B, 2 [, 3 C, 4 [, 5 D(4), 6 ], 7 E, 8 ], 9 [, 10 B, 11 ], 12 C, 13 D(6)
  const std::string s = "A(1) B(2) [ C [ D(4) ] E ] [ B(5) ] C D(6)";
  EXPECT_EQ(left(s, 5, "A B C"), "0:A(1) 1:B(2) 3:C");
  EXPECT_EQ(left(s, 13, "A B C"), "0:A(1) 1:B(2) 12:C");
  EXPECT_EQ(left(s, 13, "B C"), "1:B(2) 12:C");
  EXPECT_EQ(left(s, 7, "B C"), "1:B(2) 3:C");  // E follows the branch [D(4)] off C
  EXPECT_EQ(left(s, 13, "E C"), "no match");
}

// Left context failures: a different module, the start of the string.
TEST_F(ContextMatcherTest, LeftContextFailures) {
  EXPECT_EQ(left("A(1) B(2)", 0, "C"), "no match");
  EXPECT_EQ(left("A(1) B(2)", 1, "C"), "no match");
  EXPECT_EQ(left("A(1) B(2)", 1, "D A"), "no match");
  EXPECT_EQ(left("[ B(2) ]", 1, "A"), "no match");  // a branch at the very start has no parent
}

// 4.2 ignore: listed modules are passed over on both sides.
TEST_F(ContextMatcherTest, IgnoredModulesArePassedOver) {
  const auto ignore_c = ignoring("C");
  EXPECT_EQ(right("A(1) C B(2) C D(3)", 1, "B D"), "no match");
  EXPECT_EQ(right("A(1) C B(2) C D(3)", 1, "B D", &ignore_c), "2:B(2) 4:D(3)");
  EXPECT_EQ(left("A(1) C B(2) C D(3)", 4, "A B", &ignore_c), "0:A(1) 2:B(2)");
  // An ignored module is still matched when the pattern names it.
  EXPECT_EQ(right("A(1) C B(2)", 1, "C B", &ignore_c), "1:C 2:B(2)");
}

// 4.2 consider: only listed modules count (the manual's C < D > E example).
TEST_F(ContextMatcherTest, ConsiderCountsOnlyListedModules) {
  const auto cde = considering("C D E");
  // C(1) A(10) D(2) B(5) E(3): D at index 2.
  EXPECT_EQ(left("C A(10) D(2) B(5) E", 2, "C", &cde), "0:C");
  EXPECT_EQ(right("C A(10) D(2) B(5) E", 3, "E", &cde), "4:E");
  EXPECT_EQ(right("C A(10) D(2) B(5) E", 3, "E"), "no match");
}

// 4.2: SB and EB always count, even if a table marks them skipped.
TEST_F(ContextMatcherTest, BracketsCountEvenWhenFiltered) {
  const auto ad = considering("A D");              // SB and EB not listed
  const auto brackets = ignoring("[ ] B C");        // SB and EB listed
  // [ still opens a lateral branch that is skipped whole: D(2) inside is not seen.
  EXPECT_EQ(right("A [ D(2) ] D(3)", 1, "D", &ad), "4:D(3)");
  EXPECT_EQ(right("A [ D(2) ] D(3)", 1, "D", &brackets), "4:D(3)");
  // ] still ends the branch: nothing after it is to the right of B.
  EXPECT_EQ(right("A [ B(2) ] D(3)", 3, "D", &ad), "no match");
  EXPECT_EQ(right("A [ B(2) ] D(3)", 3, "D", &brackets), "no match");
  // Left: a ] still means a sibling branch to skip, not modules to look through.
  EXPECT_EQ(left("A(1) [ D(2) ] D(3)", 4, "D", &ad), "no match");
  EXPECT_EQ(left("A(1) [ D(2) ] D(3)", 4, "A", &brackets), "0:A(1)");
  // Filtering combines with branch skipping: B ignored, then the branch, then D.
  EXPECT_EQ(right("A B(1) [ C ] D(3)", 1, "D", &ad), "5:D(3)");
}

// ---- the branch index --------------------------------------------------------

// Both ways of keeping partners: in 4 bytes (strings under 4 GiB) and in 8.
constexpr std::size_t kNarrow = std::size_t{1} << 32, kWide = 0;

// Partners worked by hand: offsets are 8 bytes for A(int) and B(int) ([id]
// [int][id]), 2 for C, [ and ].
TEST_F(ContextMatcherTest, BranchIndexPairsEachBracketWithItsPartner) {
  for (std::size_t narrow_below : {kNarrow, kWide}) {
    ModuleString s = parse("A(1) [ B(2) [ C ] ] C");  // A 0, [ 6, B 7, [ 13, C 14, ] 15, ] 16, C 17
    BranchIndex index(narrow_below);
    index.prepare(s.view(types_));
    EXPECT_EQ(index.partner(6), 16u);
    EXPECT_EQ(index.partner(13), 15u);
    EXPECT_EQ(index.partner(15), 13u);
    EXPECT_EQ(index.partner(16), 6u);
    ModuleString stray = parse("] C [ C");  // ] 0, C 1, [ 2, C 3
    index.prepare(stray.view(types_));
    EXPECT_EQ(index.partner(0), BranchIndex::kUnmatched);
    EXPECT_EQ(index.partner(2), BranchIndex::kUnmatched);
  }
}

// Skips and matches through the index give what walking the string gives,
// on a random tree with deep and long branches, stray brackets, filters and
// patterns that enter and leave branches.
TEST_F(ContextMatcherTest, BranchIndexGivesTheWalksAnswers) {
  const ModuleString s = random_tree(11, 40000);
  const StringView walked = s.view(types_);
  BranchIndex index;
  index.prepare(walked);
  StringView indexed = walked;
  indexed.branches = &index;
  std::vector<std::size_t> starts;
  for (std::size_t at = walked.begin; at < walked.end; at = walked.next(at)) starts.push_back(at);

  std::size_t long_skips = 0;
  for (std::size_t at : starts) {
    const ModuleId m = walked.id_at(at);
    if (m == rt::mid::SB) {
      const std::size_t past = skip_branch_forward(walked, at);
      ASSERT_EQ(skip_branch_forward(indexed, at), past) << at;
      if (index_at(s, past) - index_at(s, at) > 100) ++long_skips;
    }
    if (m == rt::mid::EB) {
      ASSERT_EQ(skip_branch_backward(indexed, at), skip_branch_backward(walked, at)) << at;
    }
    ASSERT_EQ(find_unmatched_end(indexed, at), find_unmatched_end(walked, at)) << at;
  }
  EXPECT_GT(long_skips, 100u);  // the index was asked, not only the first modules walked

  const auto ignore_b = ignoring("B");
  for (const char* text : {"A", "[ B ] C", "B [ C ] A", "[ A [ B ] ] D", "A ] C", "[ [ A ] B ] C"})
    for (const std::vector<std::uint8_t>* skip : {static_cast<const std::vector<std::uint8_t>*>(nullptr), &ignore_b}) {
      const std::vector<ModuleId> p = pattern(text);
      const int n = static_cast<int>(p.size());
      for (std::size_t k = 0; k < starts.size(); k += 3) {
        std::vector<const unsigned char*> by_walk(p.size()), by_index(p.size());
        const std::uint8_t* table = skip ? skip->data() : nullptr;
        const bool r = match_right_context(walked, starts[k], p.data(), n, table, by_walk.data());
        ASSERT_EQ(match_right_context(indexed, starts[k], p.data(), n, table, by_index.data()), r) << text << k;
        if (r) {
          ASSERT_EQ(by_index, by_walk) << text << k;
        }
        const bool l = match_left_context(walked, starts[k], p.data(), n, table, by_walk.data());
        ASSERT_EQ(match_left_context(indexed, starts[k], p.data(), n, table, by_index.data()), l) << text << k;
        if (l) {
          ASSERT_EQ(by_index, by_walk) << text << k;
        }
      }
    }
}

// The inline first try decides every match as the walk does, on a string
// whose neighbours are often brackets, ignored modules or its ends.
TEST_F(ContextMatcherTest, TheInlineFirstTryAgreesWithTheWalk) {
  const ModuleString s = random_tree(5, 20000);
  const StringView v = s.view(types_);
  const auto ignore_b = ignoring("B");
  int matches = 0;
  for (const char* text : {"A", "B", "A C", "C D E", "[ A", "A ]", "E A B"})
    for (const std::uint8_t* table : {static_cast<const std::uint8_t*>(nullptr), ignore_b.data()}) {
      const std::vector<ModuleId> p = pattern(text);
      const int n = static_cast<int>(p.size());
      std::vector<const unsigned char*> walked_params(p.size()), quick_params(p.size());
      for (std::size_t at = v.begin; at <= v.end; at = at < v.end ? v.next(at) : at + 1) {
        for (bool right : {true, false}) {
          ContextCursor walked{at, false}, quick{at, false};
          const bool ok = right ? match_right_context(v, walked, p.data(), n, table, walked_params.data())
                                : match_left_context(v, walked, p.data(), n, table, walked_params.data());
          const bool quick_ok = right ? match_right_context_here(v, quick, p.data(), n, table, quick_params.data())
                                      : match_left_context_here(v, quick, p.data(), n, table, quick_params.data());
          ASSERT_EQ(quick_ok, ok) << text << " at " << at;
          if (!ok) continue;
          ++matches;
          ASSERT_EQ(quick_params, walked_params) << text << " at " << at;
          ASSERT_EQ(quick.at, walked.at) << text << " at " << at;
        }
      }
    }
  EXPECT_GT(matches, 1000);
}

// Built in parts (as a parallel pass builds it), the index pairs every
// bracket as the one-pass build does, wherever the parts are cut.
TEST_F(ContextMatcherTest, BranchIndexBuiltInPartsPairsAsBuiltWhole) {
  const ModuleString s = random_tree(5, 30000);
  const StringView v = s.view(types_);
  std::vector<std::size_t> brackets, starts;
  for (std::size_t at = v.begin; at < v.end; at = v.next(at)) {
    starts.push_back(at);
    if (v.id_at(at) == rt::mid::SB || v.id_at(at) == rt::mid::EB) brackets.push_back(at);
  }
  BranchIndex whole;
  whole.prepare(v);
  std::mt19937 random(3);
  for (std::size_t count : {1u, 2u, 7u, 64u}) {
    std::vector<std::size_t> parts{v.begin};
    for (std::size_t k = 1; k < count; ++k) parts.push_back(starts[random() % starts.size()]);
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    for (std::size_t narrow_below : {kNarrow, kWide}) {
      BranchIndex in_parts(narrow_below);
      in_parts.prepare(v);
      in_parts.build_in_parts(parts, [](std::size_t n, const std::function<void(std::size_t)>& task) {
        for (std::size_t k = n; k-- > 0;) task(k);  // any order
      });
      ASSERT_TRUE(in_parts.built());
      for (std::size_t b : brackets)
        ASSERT_EQ(in_parts.partner(b), whole.partner(b)) << count << " parts, at " << b << ", " << narrow_below;
    }
  }
}

// The brackets of a string being built, followed as it grows: appended to
// (asked from an EB) and prepended to (asked from an SB), caught up at
// random moments, give what walking the string gives, or say they cannot
// tell (kUnknown) for pairs older than those they keep.
TEST_F(ContextMatcherTest, BuiltBranchesGiveTheWalksAnswersAsTheStringGrows) {
  const ModuleString whole = random_tree(9, 60000);
  const StringView all = whole.view(types_);
  std::vector<std::size_t> starts;
  for (std::size_t at = all.begin; at < all.end; at = all.next(at)) starts.push_back(at);
  std::mt19937 random(4);
  std::size_t answered = 0, unknown = 0;

  BuiltBranches appended;
  appended.restart(BuiltBranches::Growth::kAtEnd);
  for (std::size_t k = 0; k < starts.size(); k += 1 + random() % 40) {
    StringView built = all;
    built.end = starts[k];  // the string built so far
    appended.catch_up(built);
    ASSERT_EQ(appended.eb_of(0), BranchPartners::kUnknown);  // appending: asked from EBs only
    for (std::size_t back = 0, at = built.end; back < 30 && at > built.begin; ++back) {
      at = built.previous(at);
      if (built.id_at(at) != rt::mid::EB) continue;
      const std::size_t sb = appended.sb_of(at);
      if (sb == BranchPartners::kUnknown) {
        ++unknown;
        continue;
      }
      ++answered;
      const std::size_t walked = skip_branch_backward(built, at);
      ASSERT_EQ(sb == BranchPartners::kUnmatched ? built.begin : sb, walked) << at;
    }
  }

  BuiltBranches prepended;
  prepended.restart(BuiltBranches::Growth::kAtStart);
  for (std::size_t k = starts.size(); k > 0;) {
    k -= std::min<std::size_t>(k, 1 + random() % 40);
    StringView built = all;
    built.begin = starts[k];  // the string built so far, from its end
    prepended.catch_up(built);
    for (std::size_t ahead = 0, at = built.begin; ahead < 30 && at < built.end; ++ahead, at = built.next(at)) {
      if (built.id_at(at) != rt::mid::SB) continue;
      const std::size_t eb = prepended.eb_of(at);
      if (eb == BranchPartners::kUnknown) {
        ++unknown;
        continue;
      }
      ++answered;
      const std::size_t walked = skip_branch_forward(built, at);
      ASSERT_EQ(eb == BranchPartners::kUnmatched ? built.end : built.next(eb), walked) << at;
    }
  }
  EXPECT_GT(answered, 1000u);
}

// ---- end-to-end tests through the engine -------------------------------------

std::string write_model(const std::string& test, const std::string& body) {
  return write_temp_file("matching-" + test, "model.l",
                         "#include <lpfgall.h>\n"
                         "module A(int); module B(int); module C(int); module D(int); module E(int);\n" +
                             body);
}

// A tiny model (after the declarations of A ... E, each with an int) and
// its string after `steps` steps (-1: its derivation length).
struct ModelCase {
  std::string name;
  std::string body;
  int steps;
  std::string expected;
};

const std::string kCutRules =
    "derivation length: 1;\naxiom: A(1) SB() B(1) Cut() B(2) SB() B(3) EB() B(4) EB() B(5) Cut() B(6);\n"
    "B(x): { produce B(x+10); }\n";
const std::string kMultiModuleRules =
    "derivation length: 1;\naxiom: A(1) B(2) C(3) A(4) B(5) B(6);\n"
    "A(x) B(y) > C(z): { produce D(x+y+z); }\n"
    "A(x) B(y): { produce E(x*y); }\n"
    "B(y): { produce B(y+100); }\n";
const std::string kDecompositionRule = "A(x): { if (x > 0) produce B(1) A(x-1); }\n";

const std::vector<ModelCase> kModelCases = {
    // 3.1.3: << reads the new string, so one forward step propagates along it.
    // A(1) is copied; B#1 sees A(1) -> B(1); B#2 sees the new B(1) -> B(2); B#3 -> B(3).
    // (With old context < every B would have seen B(0) or A(1).)
    {"newleft",
     "derivation length: 1;\naxiom: A(1) B(0) B(0) B(0);\n"
     "A(x) << B(y): { produce B(x); }\n"
     "B(x) << B(y): { produce B(x+1); }\n",
     -1, "A(1) B(1) B(2) B(3)"},
    // 3.1.3: >> reads the new string under Backward(), built from the right.
    // Right to left: A(1) copied; the last B sees A(1) -> B(1); then B(2); then B(3).
    {"newright",
     "Start: { Backward(); }\n"
     "derivation length: 1;\naxiom: B(0) B(0) B(0) A(1);\n"
     "B(y) >> A(x): { produce B(x); }\n"
     "B(y) >> B(x): { produce B(x+1); }\n",
     -1, "B(3) B(2) B(1) A(1)"},
    // 3.1.3: a new context never matches in the wrong direction; the next rule is tried.
    // Backward: A(x) << B(y) cannot match, B(y) falls to the plain rule -> B(100).
    {"newleft-backward",
     "Start: { Backward(); }\n"
     "derivation length: 1;\naxiom: A(1) B(0);\n"
     "A(x) << B(y): { produce B(x); }\n"
     "B(y): { produce B(y+100); }\n",
     -1, "A(1) B(100)"},
    // Forward: B(y) >> A(x) cannot match, B(y) falls to the plain rule -> B(100).
    {"newright-forward",
     "derivation length: 1;\naxiom: B(0) A(1);\n"
     "B(y) >> A(x): { produce B(x); }\n"
     "B(y): { produce B(y+100); }\n",
     -1, "B(100) A(1)"},
    // 5.4: Cut removes itself and the rest of its branch (up to the unmatched EB,
    // kept) or of the string; it has no effect under Backward().
    // Forward: "Cut() B(2) [B(3)] B(4)" goes (the EB stays), B(5) is rewritten, "Cut() B(6)" goes.
    {"cut", kCutRules, -1, "A(1) SB B(11) EB B(15)"},
    // Backward: Cut stays and everything is rewritten.
    {"cut-backward", "Start: { Backward(); }\n" + kCutRules, -1,
     "A(1) SB B(11) Cut B(12) SB B(13) EB B(14) EB B(15) Cut B(16)"},
    // 4.2: ignore: applies to the following productions until `ignore: ;`.
    // D(2): left C(1) past A(10), right E(3) past B(5) -> D(1+2+3) = D(6).
    // E(3): the rule after `ignore: ;` sees B(5) on its left, not D -> unchanged.
    {"ignore",
     "derivation length: 1;\naxiom: C(1) A(10) D(2) B(5) E(3);\n"
     "ignore: A B;\n"
     "C(x) < D(y) > E(z): { produce D(x+y+z); }\n"
     "ignore: ;\n"
     "D(x) < E(y): { produce E(99); }\n",
     -1, "C(1) A(10) D(6) B(5) E(3)"},
    // 4.2: consider: only the listed modules count; SB and EB always do.
    // Right of D(2): [ E(7) ] is a lateral branch, skipped whole; B(5) is not
    // considered; E(3) matches -> D(1+2+3). (Were SB ignored, E(7) would give D(10).)
    {"consider",
     "derivation length: 1;\naxiom: C(1) A(10) D(2) SB() E(7) EB() B(5) E(3);\n"
     "consider: C D E;\n"
     "C(x) < D(y) > E(z): { produce D(x+y+z); }\n",
     -1, "C(1) A(10) D(6) SB E(7) EB B(5) E(3)"},
    // Listing SB and EB in ignore: has no effect: the same answer.
    {"ignore-brackets",
     "derivation length: 1;\naxiom: C(1) A(10) D(2) SB() E(7) EB() B(5) E(3);\n"
     "ignore: A B SB EB;\n"
     "C(x) < D(y) > E(z): { produce D(x+y+z); }\n",
     -1, "C(1) A(10) D(6) SB E(7) EB B(5) E(3)"},
    // Chapter 9 / 3.2.1: productions are tried in file order; a body that ends
    // without produce does not apply, and the next one is tried.
    // A(1): rule 1 applies (rule 3 would too) -> B(1). A(2): rule 1 returns
    // without produce, rule 2 -> B(20). A(3): rules 1 and 2 fall through -> B(303).
    {"order",
     "derivation length: 1;\naxiom: A(1) A(2) A(3);\n"
     "A(x): { if (x == 1) produce B(1); }\n"
     "A(x): { if (x == 2) produce B(20); return; }\n"
     "A(x): { produce B(300+x); }\n",
     -1, "B(1) B(20) B(303)"},
    // 3.2.2: nproduce builds the successor; without a final produce the partial
    // successor is dropped and the next rule is tried.
    // A(1): rule 1 nproduces B(99) but never produces -> dropped; rule 2 gives
    // B(1) [ C(1) ] D(1). A(7): rule 1 produces -> B(99) B(99) E(7).
    {"nproduce",
     "derivation length: 1;\naxiom: A(1) A(7);\n"
     "A(x): { nproduce B(99); if (x > 5) { nproduce B(99); produce E(x); } }\n"
     "A(x): { nproduce B(x); nproduce SB() C(x) EB(); produce D(x); }\n",
     -1, "B(1) SB C(1) EB D(1) B(99) B(99) E(7)"},
    // 3.2.2 with 3.1.3: modules nproduced by a rule that did not apply are not
    // part of the new string seen by a later rule's << (even when they made the
    // new string grow).
    // B(5) is copied. A(1): rule 1 nproduces 200 C's and gives up; rule 2's
    // new left context is B(5) -> A(5).
    {"nproduce-newleft",
     "derivation length: 1;\naxiom: B(5) A(1);\n"
     "A(x): { for (int i = 0; i < 200; ++i) nproduce C(i); }\n"
     "B(y) << A(x): { produce A(y); }\n",
     -1, "B(5) A(5)"},
    // 3.2.1: `produce;` erases the strict predecessor (unlike ending without produce).
    // A(1) erased by produce;, B(2) erased, A(3) falls through every rule and stays.
    {"erase",
     "derivation length: 1;\naxiom: A(1) B(2) A(3);\n"
     "A(x): { if (x == 1) produce; }\n"
     "B(x): { produce; }\n",
     -1, "A(3)"},
    // 3.1.1: a strict predecessor of several modules is replaced as a whole,
    // forward and backward.
    // A(1) B(2) > C(3) -> D(6); C(3) copied; A(4) B(5) has B(6), not C, on its
    // right -> the plain A B rule, E(4*5); B(6) alone -> B(106). The B's inside
    // a matched A B are consumed, not rewritten by B(y).
    {"multi", kMultiModuleRules, -1, "D(6) C(3) E(20) B(106)"},
    // Backward (right to left) finds the same matches.
    {"multi-backward", "Start: { Backward(); }\n" + kMultiModuleRules, -1, "D(6) C(3) E(20) B(106)"},
    // Chapter 9 through the engine: lateral branches in right and left context.
    // A(1) > B(y): the branch [B(2)] is skipped -> y = 3 -> A(3).
    // A(x) < B(y): B(2) (first in the branch) and B(3) (after the branch) both have A(1) as parent.
    // C(x) > [B(y)] B(z): C(4) sees [B(5)] then B(6) -> C(11).
    {"branching",
     "derivation length: 1;\n"
     "axiom: A(1) SB() B(2) EB() B(3) C(4) SB() B(5) EB() B(6);\n"
     "A(x) > B(y): { produce A(y); }\n"
     "A(x) < B(y): { produce B(y+10*x); }\n"
     "C(x) > [ B(y) ] B(z): { produce C(x+y+z); }\n",
     -1, "A(3) SB B(12) EB B(13) C(15) SB B(5) EB B(6)"},
    // 4.3.1: decomposition recurses up to `maximum depth` levels (default 1), after
    // the axiom and after every step.
    // Depth 3: A(5) -> B A(4) -> B B A(3) -> B B B A(2), then the limit.
    {"depth3", "axiom: A(5);\ndecomposition:\nmaximum depth: 3;\n" + kDecompositionRule, 0, "B(1) B(1) B(1) A(2)"},
    // One (empty) step later A(2) decomposes again: B B A(0), and A(0) produces nothing.
    {"depth3-step", "axiom: A(5);\ndecomposition:\nmaximum depth: 3;\n" + kDecompositionRule, 1,
     "B(1) B(1) B(1) B(1) B(1) A(0)"},
    // Default depth 1: one application only.
    {"depth1", "axiom: A(5);\ndecomposition:\n" + kDecompositionRule, 0, "B(1) A(4)"},
};

class ContextMatchingModel : public ::testing::TestWithParam<ModelCase> {};

TEST_P(ContextMatchingModel, DerivesTheExpectedString) {
  const ModelCase& c = GetParam();
  EXPECT_EQ(derive_string(write_model(c.name, c.body), c.steps), c.expected);
}

INSTANTIATE_TEST_SUITE_P(Table, ContextMatchingModel, ::testing::ValuesIn(kModelCases),
                         [](const ::testing::TestParamInfo<ModelCase>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

// 4.3.2: interpretation rules only feed the turtle; the string keeps the
// modules, and the next step's productions see them.
TEST(ContextMatchingInterpretation, InterpretationIsNotStoredInString) {
  // A(1) -> A(2) -> A(3) by the production; interpretation shows A(3) as B(3) C(3).
  const std::string model = write_model("interpretation",
                                        "derivation length: 2;\naxiom: A(1);\n"
                                        "A(x): { produce A(x+1); }\n"
                                        "interpretation:\n"
                                        "A(x): { produce B(x) C(x); }\n");
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(model, options);
  simulation.run();
  EXPECT_EQ(io::format_string(simulation.string(), simulation.types()), "A(3)\n");
  EXPECT_EQ(io::format_string(simulation.interpreted(0), simulation.types()), "B(3) C(3)\n");
  EXPECT_EQ(io::format_string(simulation.string(), simulation.types()), "A(3)\n");
}

}  // namespace
}  // namespace sylva::test
