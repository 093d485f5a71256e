// Module parameters as saved-string text, written by the engine from the
// parameters' type table (abi::ParamField) rather than by code compiled into
// each model: one formatter for every model, numbers written with
// std::to_chars.
//
// The text is the one sylva/runtime/modules.h describes for compiled
// printers: numbers comma-separated; floating-point numbers in the shortest
// form that reads back to the same value; bool as 0 or 1; vectors as
// (x,y,z), arrays as [a,b], structs as {field=value,...}; text quoted with
// \" and \\ escaped; a value of unknown layout as # and its bytes in hex.
// cpfg's modules are written as cpfg writes them: each float as %g.
#pragma once

#include <span>
#include <string>

#include "sylva/abi.h"

namespace sylva {

enum class NumberStyle {
  kExact,  // shortest text that reads back to the same value (lpfg models)
  kCpfg,   // %g: six significant digits (cpfg models)
};

// Whether append_params_text can write these parameters: every type is
// known, every struct's fields are located, and in cpfg's style there is no
// text (cpfg quotes a label's text with C escapes of its own).
bool params_text_from_table(std::span<const abi::ParamField> params, NumberStyle style);

// Appends "p1,p2,..." for the parameter block at `params`.
void append_params_text(std::span<const abi::ParamField> params, const unsigned char* block, NumberStyle style,
                        std::string& out);

// Reads back what append_params_text writes in the exact style, as a
// model's own reader would (sylva/runtime/parse_params.h): the values
// separated by commas into `block`, each struct with all its fields by name
// in any order, stopping before the closing parenthesis. False, with
// `in->expected` and `in->at` saying what was expected where, on bad text,
// and for text (a pointer cannot be read back).
bool read_params_text(std::span<const abi::ParamField> params, abi::TextSource* in, unsigned char* block);

}  // namespace sylva
