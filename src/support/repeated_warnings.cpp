#include "support/repeated_warnings.h"

namespace sylva {

bool RepeatedWarnings::is_warning(const std::string& text) {
  return text.rfind("warning: ", 0) == 0 || text.find(": warning: ") != std::string::npos;
}

void RepeatedWarnings::operator()(const std::string& text) {
  if (!is_warning(text)) {
    out_(text);
    return;
  }
  auto [it, first] = counts_.try_emplace(text, 0);
  if (++it->second > 1) return;
  order_.push_back(text);
  out_(text);
}

void RepeatedWarnings::finish() {
  for (const std::string& text : order_) {
    const std::size_t count = counts_[text];
    if (count < 2) continue;
    std::string line = text;
    while (!line.empty() && line.back() == '\n') line.pop_back();
    out_(line + " (" + std::to_string(count) + " times in all)\n");
  }
  counts_.clear();
  order_.clear();
}

}  // namespace sylva
