// Warnings that come again and again (a depth limit reached for the same
// module in every step, say) would bury the ones that matter: each distinct
// warning is passed on the first time only, and at the end one line says how
// many times each repeated warning came in all. Other messages (a model's
// Printf output) pass through untouched.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sylva {

class RepeatedWarnings {
 public:
  using Sink = std::function<void(const std::string&)>;
  explicit RepeatedWarnings(Sink out) : out_(std::move(out)) {}

  void operator()(const std::string& text);
  // The counts of the warnings that came more than once, in the order they
  // first came; then counting starts afresh.
  void finish();
  // Each distinct warning passed on since the last finish(), in order.
  const std::vector<std::string>& distinct() const { return order_; }

  // "warning: ..." or "file:line: warning: ...".
  static bool is_warning(const std::string& text);

 private:
  Sink out_;
  std::map<std::string, std::size_t> counts_;
  std::vector<std::string> order_;
};

}  // namespace sylva
