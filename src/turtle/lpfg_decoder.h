// L+C's turtle modules (LPFG manual chapter 5): a predefined module and its
// parameters as a turtle command.
#pragma once

#include <string>

#include "lstring/module_types.h"
#include "turtle/command.h"
#include "turtle/turtle_settings.h"
#include "turtle/turtle_state.h"

namespace sylva::turtle {

class LpfgDecoder {
 public:
  explicit LpfgDecoder(const TurtleSettings& settings) : settings_(settings) {}

  // The turtle before the string's first module.
  static TurtleState initial_state(const TurtleSettings& settings);
  // Passes the command of module `id` to `emit` (CommandRunner,
  // CommandRecorder); false, and no command, when it is not a predefined
  // module (user modules are not the turtle's).
  template <class Emit>
  bool decode(ModuleId id, const unsigned char* params, Emit& emit) const;
  // The module as the trace writes it.
  static void append_text(std::string& out, ModuleId id, const unsigned char* params);
  // What closes a polygon the string left open.
  static command::EndPolygon end_polygon() { return {}; }

 private:
  const TurtleSettings& settings_;
};

}  // namespace sylva::turtle
