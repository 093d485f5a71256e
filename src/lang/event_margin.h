// The margin of an event's condition: a number that is >= 0 where the
// condition holds and passes through zero where it starts to, so that the
// engine can locate the instant by root finding rather than bisection alone.
//   a >= b, a > b   ->  a - b          a <= b, a < b  ->  b - a
//   p && q          ->  min(p', q')    p || q         ->  max(p', q')
//   ( p )           ->  p'             anything else  ->  (p ? 1 : -1)
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "lang/model_ir.h"

namespace sylva::lang {

// The margin as C++: literal text and runs of the condition's own tokens
// (kept, so that the compiler's messages point into the model).
struct TokenRun {
  std::size_t begin, end;  // [begin, end) of the condition
};
using MarginPiece = std::variant<std::string, TokenRun>;

std::vector<MarginPiece> event_margin(const Code& condition);

// The pieces as one line of text, token runs written with single spaces (for tests).
std::string margin_text(const Code& condition, const std::vector<MarginPiece>& pieces);

}  // namespace sylva::lang
