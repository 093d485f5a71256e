#include "derive/in_body_context.h"

namespace sylva::derive {

bool InBodyContext::answer(void* self, int part, const ModuleId* pattern, int n, const unsigned char** params) {
  return static_cast<InBodyContext*>(self)->test(part, pattern, n, params);
}

bool InBodyContext::test(int part, const ModuleId* pattern, int n, const unsigned char** params) {
  switch (part) {
    case abi::kLeft:
      return match_left_context(*string_, *left_, pattern, n, skipped_, params);
    case abi::kRight:
      return match_right_context(*string_, *right_, pattern, n, skipped_, params);
    case abi::kNewLeft: {
      if (!built_) return false;
      // A view made now: the body may have grown (and moved) the buffer; what
      // it appended to this rule's own successor is not context.
      const StringView built{built_->data(), 0, built_end_, sizes_, false, built_branches_};
      return match_left_context(built, *new_left_, pattern, n, skipped_, params);
    }
    case abi::kNewRight:
      return new_right_string_ && match_right_context(*new_right_string_, *new_right_, pattern, n, skipped_, params);
    default:
      return false;
  }
}

}  // namespace sylva::derive
