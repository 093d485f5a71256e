// cpfg's turtle symbols (CPFG manual, chapter 6): a cpfg module and its
// float parameters as a turtle command, through the model's symbol table
// (cpfg_symbols.h). A command may be read a character a module (@ G c(3)
// for @Gc(3)): the decoder keeps the characters read so far.
//
// cpfg's turtle (interpret.c) starts with H = +y, L = -x and U = -z: its
// frame is left-handed (U = L x H). The turtle's frame is lpfg's, with U =
// H x L, so cpfg's U is -frame.up throughout. Turns and pitches come out as
// lpfg's corrected + - & ^ do; cpfg's / rolls L towards its U, the other way
// from lpfg's corrected /. lpfg's "corrected rotation" does not apply: cpfg
// has no such setting.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lstring/module_types.h"
#include "turtle/command.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/turtle_settings.h"
#include "turtle/turtle_state.h"

namespace sylva::turtle {

class CpfgDecoder {
 public:
  CpfgDecoder(const TurtleSettings& settings, const ModuleTypes& types);

  // The turtle before the string's first module.
  static TurtleState initial_state(const TurtleSettings& settings);
  // Passes the command of module `id` (module `source_index` of the string,
  // for errors) to `emit` (CommandRunner, CommandRecorder); false, and no
  // command, when it makes none: not a turtle symbol, or a character of a
  // longer command still being read.
  template <class Emit>
  bool decode(ModuleId id, const unsigned char* params, std::uint32_t source_index, Emit& emit);
  // The module as the trace writes it.
  void append_text(std::string& out, ModuleId id, const unsigned char* params) const;
  // What closes a polygon the string left open.
  static command::EndPolygon end_polygon() { return {true}; }

 private:
  // The operation of module `id`, joined to the characters read before it.
  CpfgOp read_op(ModuleId id);

  const TurtleSettings& settings_;
  const ModuleTypes& types_;
  // The model's symbol table: the settings' own, or built here.
  std::shared_ptr<const CpfgSymbols> symbols_;
  // The characters so far of a command read a character a module.
  std::string pending_;
  // @L's text, formatted from its values; its command refers to it.
  std::string label_;
  std::vector<float> label_values_;
};

}  // namespace sylva::turtle
