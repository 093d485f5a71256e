// The step each module was made at (Derivation::births): kept by walking the
// old and the new string side by side after each pass, so the derivation
// itself only notes the stretches it rewrote.
#include "derive/derivation.h"

namespace sylva::derive {

void Derivation::reset_births(std::uint32_t step) {
  rewrites_.clear();
  if (!tracking_births_) return;
  births_.assign(string_.count_modules(types_), step);
}

void Derivation::update_births(const ModuleString& old, std::uint32_t step) {
  if (!tracking_births_) return;
  const StringView before = old.view(types_), after = string_.view(types_);
  if (births_.size() != old.count_modules(types_)) births_.assign(old.count_modules(types_), 0);
  std::vector<std::uint32_t> births;
  births.reserve(births_.size());
  std::size_t from = before.begin, to = after.begin, index = 0;
  auto copy_until = [&](std::size_t end) {
    for (; from < end; from = before.next(from), to = after.next(to)) births.push_back(births_[index++]);
  };
  for (const Rewrite& r : rewrites_) {
    copy_until(r.source_begin);
    for (; from < r.source_end; from = before.next(from)) ++index;
    for (const std::size_t end = to + r.output_bytes; to < end; to = after.next(to)) births.push_back(step);
  }
  copy_until(before.end);
  births_ = std::move(births);
  rewrites_.clear();
}

}  // namespace sylva::derive
