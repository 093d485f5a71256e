#include "lang/event_margin.h"

namespace sylva::lang {
namespace {

class MarginBuilder {
 public:
  explicit MarginBuilder(const Code& c) : c_(c) {}

  void margin(std::size_t b, std::size_t e) {
    while (wrapped_in_parentheses(b, e)) ++b, --e;
    if (const std::size_t at = top_level(b, e, {"||"}).last; at != e) return combine("::std::max", b, at, e);
    if (const std::size_t at = top_level(b, e, {"&&"}).last; at != e) return combine("::std::min", b, at, e);
    // One comparison alone: with several (`<` of a template argument, a
    // chain) or a `?:` the margin would not be what the condition says.
    if (const TopLevel found = top_level(b, e, {">=", ">", "<=", "<", "?"});
        found.count == 1 && found.last != b && found.last + 1 != e && !c_[found.last].is_punct("?")) {
      const std::size_t at = found.last;
      const bool greater = c_[at].text[0] == '>';
      difference(greater ? TokenRun{b, at} : TokenRun{at + 1, e}, greater ? TokenRun{at + 1, e} : TokenRun{b, at});
      return;
    }
    out.emplace_back(std::string("(("));
    out.emplace_back(TokenRun{b, e});
    out.emplace_back(std::string(") ? 1.0 : -1.0)"));
  }

  std::vector<MarginPiece> out;

 private:
  bool wrapped_in_parentheses(std::size_t b, std::size_t e) const {
    if (e - b < 2 || !c_[b].is_punct("(") || !c_[e - 1].is_punct(")")) return false;
    int depth = 0;
    for (std::size_t k = b; k < e; ++k) {
      if (is_open(c_[k])) ++depth;
      if (is_close(c_[k]) && --depth == 0 && k + 1 != e) return false;  // `(a) < (b)`
    }
    return true;
  }

  // The operators of `ops` outside brackets in [b, e): the last (so that a
  // chain splits left-associatively; e if none) and how many.
  struct TopLevel {
    std::size_t last, count;
  };
  TopLevel top_level(std::size_t b, std::size_t e, std::initializer_list<const char*> ops) const {
    int depth = 0;
    TopLevel found{e, 0};
    for (std::size_t k = b; k < e; ++k) {
      if (is_open(c_[k])) ++depth;
      if (is_close(c_[k])) --depth;
      if (depth != 0) continue;
      for (const char* op : ops)
        if (c_[k].is_punct(op)) found = {k, found.count + 1};
    }
    return found;
  }

  void combine(const char* function, std::size_t b, std::size_t at, std::size_t e) {
    out.emplace_back(std::string(function) + "(static_cast<double>(");
    margin(b, at);
    out.emplace_back(std::string("), static_cast<double>("));
    margin(at + 1, e);
    out.emplace_back(std::string("))"));
  }

  void difference(TokenRun larger, TokenRun smaller) {
    out.emplace_back(std::string("(static_cast<double>("));
    out.emplace_back(larger);
    out.emplace_back(std::string(") - static_cast<double>("));
    out.emplace_back(smaller);
    out.emplace_back(std::string("))"));
  }

  const Code& c_;
};

}  // namespace

std::vector<MarginPiece> event_margin(const Code& condition) {
  MarginBuilder builder(condition);
  builder.margin(0, condition.size());
  return std::move(builder.out);
}

std::string margin_text(const Code& condition, const std::vector<MarginPiece>& pieces) {
  std::string text;
  for (const MarginPiece& piece : pieces) {
    if (const auto* literal = std::get_if<std::string>(&piece)) {
      text += *literal;
      continue;
    }
    const TokenRun run = std::get<TokenRun>(piece);
    for (std::size_t k = run.begin; k < run.end; ++k) text += (k == run.begin ? "" : " ") + condition[k].text;
  }
  return text;
}

}  // namespace sylva::lang
