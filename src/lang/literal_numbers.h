// Numbers a model writes out where a whole number is expected (group and
// view numbers, an L-system's label, settings written as a number), read so
// that one out of range is the model's error rather than a wrapped value.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "lang/model_ir.h"

namespace sylva::lang {

// A C++ integer literal (decimal, 0x hexadecimal, 0 octal or 0b binary, with
// any u/l suffix) as a whole number from 0 to INT_MAX; nothing when it is not
// one or does not fit.
std::optional<int> nonnegative_int(std::string_view literal);

// What is wrong with `expression` as the value of `what` (an int, which
// may be negative or not), when it is a number written out (a sign, a
// number, and parentheses around them); empty when it is fine or computed.
std::string range_error(std::string_view what, std::string_view expression, bool negative_allowed);

// What is wrong with `expression` as the value of a setting, when it is a
// number written out (a sign, a number, and parentheses around them: what is
// left once the preprocessor has replaced names it defines); empty when it
// is fine or computed (a computed value is checked when the run reads it).
// Derivation lengths and depths must fit an int; depths must not be negative.
std::string setting_range_error(Setting::Kind kind, std::string_view expression);

}  // namespace sylva::lang
