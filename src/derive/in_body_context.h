// InLeftContext(...), InRightContext(...), InNewLeftContext(...) and
// InNewRightContext(...) in a rule body (LPFG manual 3.3).
//
// Each test matches its pattern with the same context matcher (and the same
// ignore:/consider:, branches and ring) as the rule's predecessor, and reads
// the string like a stream: a left test begins just before the left context
// the predecessor matched (or the strict predecessor), a right test just after
// the right context; every test that succeeds moves its side's starting point
// past what it matched, and a failed test moves nothing.
//
// New context needs the string being built. Forward productions and
// decomposition rules have it on the left (the new string, or the
// decomposition, so far), backward productions on the right. Where it does
// not exist the test is false, as a predecessor with that context would not
// match: InNewRightContext going forward, InNewLeftContext going backward,
// and both in interpretation rules, whose output goes to the turtle rather
// than into a string.
#pragma once

#include <cstddef>
#include <cstdint>

#include "derive/context_matcher.h"
#include "lstring/module_string.h"
#include "sylva/abi.h"

namespace sylva::derive {

class InBodyContext {
 public:
  // `string` is the string the predecessor matched in; `left` and `right`
  // where its context ended on each side. The tests move the cursors
  // themselves: a body runs once per rule applied, so this object only
  // points at what the caller has (all of it outlives the body).
  InBodyContext(const StringView& string, SkipTable skipped, ContextCursor& left, ContextCursor& right)
      : string_(&string), skipped_(skipped), left_(&left), right_(&right) {}

  // The new string being built to the left (forward derivation): its first
  // `end` bytes, read when a test runs (the body may move the buffer by
  // appending). `from` is where the predecessor's new left context began.
  // `branches`: its brackets' partners, if the pass follows them.
  void set_new_left(const ModuleString& built, std::size_t end, const std::uint32_t* sizes, ContextCursor& from,
                    const BranchPartners* branches) {
    built_ = &built;
    built_end_ = end;
    sizes_ = sizes;
    new_left_ = &from;
    built_branches_ = branches;
  }
  // The new string built to the right (backward derivation).
  void set_new_right(const StringView& built, ContextCursor& from) {
    new_right_string_ = &built;
    new_right_ = &from;
  }

  // Lets the body's tests reach this object.
  void attach(abi::RuleCall& call) {
    call.context = this;
    call.in_context = &InBodyContext::answer;
  }

 private:
  static bool answer(void* self, int part, const ModuleId* pattern, int n, const unsigned char** params);
  bool test(int part, const ModuleId* pattern, int n, const unsigned char** params);

  const StringView* string_;
  SkipTable skipped_;
  ContextCursor* left_;
  ContextCursor* right_;
  const ModuleString* built_ = nullptr;  // null: no new string on the left
  std::size_t built_end_ = 0;
  const std::uint32_t* sizes_ = nullptr;
  const BranchPartners* built_branches_ = nullptr;
  ContextCursor* new_left_ = nullptr;
  const StringView* new_right_string_ = nullptr;  // null: no new string on the right
  ContextCursor* new_right_ = nullptr;
};

}  // namespace sylva::derive
