// The text of `sylva run --turtle`: one line per module the turtle acts on,
// the module as written (numbers short: 6 significant digits) and what the
// turtle did. The interpreter writes each line from the command stream: the
// module's text, then each command's (command_trace.cpp).
#pragma once

#include <string>

#include "geometry/vec3.h"
#include "sylva/abi.h"
#include "turtle/command.h"

namespace sylva::turtle {

class CommandDispatcher;

void append_number(std::string& out, double value);
void append_vector(std::string& out, geometry::Vec3 v);
// "Name(p1,p2,...)" for an L+C predefined module; "Name" when it has no parameters.
void append_module(std::string& out, abi::ModuleId id, const unsigned char* params);
// A cpfg module: its symbol and `count` float parameters; @L's (`label`)
// text first, quoted.
void append_cpfg_module(std::string& out, const std::string& symbol, const unsigned char* params, int count,
                        bool label);
// What `command` did (`result`), the turtle as it left it (`turtle`).
void append_command(std::string& out, const TurtleCommand& command, const CommandResult& result,
                    const CommandDispatcher& turtle);

}  // namespace sylva::turtle
