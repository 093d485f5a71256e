// The text of `sylva run --turtle`: one line per turtle command, the module
// as written (numbers short: 6 significant digits) and what the turtle did.
#pragma once

#include <string>

#include "geometry/vec3.h"
#include "sylva/abi.h"

namespace sylva::turtle {

void append_number(std::string& out, double value);
void append_vector(std::string& out, geometry::Vec3 v);
// "Name(p1,p2,...)" for a predefined module; "Name" when it has no parameters.
void append_module(std::string& out, abi::ModuleId id, const unsigned char* params);

}  // namespace sylva::turtle
