// cpfg's turtle symbols (CPFG manual, chapter 6) by module id: the table
// cpfg_decoder.h reads to make turtle commands of a cpfg model's modules.
//
// In a cpfg model every (symbol, parameter count) is its own module type
// whose name is the symbol ("+", "F", "@O", "?P"), and every parameter is a
// float. The table below is built once per model from its module types, so
// interpreting a module is one lookup by id rather than a string comparison.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lstring/module_types.h"

namespace sylva::turtle {

enum class CpfgOp : std::uint8_t {
  None,  // not a turtle symbol: cpfg ignores it when drawing
  Push, Pop,
  Forward, Move, ForwardNoVertex, MoveNoVertex,  // F f G g
  MoveTo,                                          // @M
  Left, Right, Down, Up, RollLeft, RollRight,      // + - & ^ \ /
  TurnAround,                                      // |
  RollToVertical,                                  // @v and $
  SetHeading,                                      // @R
  WidthUp, WidthDown,                              // # !
  ColorUp, ColorDown,                              // ; ,
  PolygonOrCylinderStart, PolygonOrCylinderEnd, VertexOrCylinderPoint,  // { } .
  CircleScreen, CircleHL, CircleScreenBoundary, CircleHLBoundary,      // @o @c @bo @bc
  Sphere,                                                               // @O
  CylinderStart, CylinderPoint, CylinderEnd,                            // @Gs @Gc @Ge
  CylinderTangents,                                                     // @Gt
  CylinderRadiusTangents,                                               // @Gr
  Contour, ContourSides,                                                // @# @!
  SetScale, ScaleUp, ScaleDown,                                         // @D @Di @Dd
  Texture,                                                              // @Tx
  SurfaceInit, SurfacePoint, SurfaceDraw,                               // @PS @PC @PD
  ElasticitySet, ElasticityUp, ElasticityDown,                          // @Ts @T @Td
  QueryPosition, QueryHeading, QueryLeft, QueryUp,                      // ?P ?H ?L ?U
  SubLsystemCall,                                                       // ?(label,s)
  SubLsystemReturn,                                               // $
  PredefinedSurface,                                                    // ~id
  Label,                                                                // @L("format",p1,...)
  MinimizeTwist, ForceTwist,                                            // @Tp @Tf
  BackColorUp, BackColorDown,                                           // @; @,
  // @, ? or ~ alone: the start of a command whose other characters are the
  // modules that follow (cpfg's string holds a module a character).
  Prefix,
};

// The operation of a symbol, by its name (the symbol as written).
CpfgOp cpfg_op(const std::string& symbol);
// Whether `start` begins a longer command (@G of @Gc, @ of @O).
bool cpfg_command_prefix(const std::string& start);

// @L's text: `format` printf-style with the `count` values. Only %f %F %e %E
// %g %G %a %A (the value) and %d %i %o %u %x %X (its integer part) with
// flags, a width and a precision of up to three digits each consume a value;
// %% is '%'; any other conversion, or one past the last value, is written as
// it stands.
std::string format_cpfg_label(std::string_view format, const float* values, int count);

// True for ?P ?H ?L ?U: modules the turtle writes its state into.
inline bool is_query(CpfgOp op) { return op >= CpfgOp::QueryPosition && op <= CpfgOp::QueryUp; }

class CpfgSymbols {
 public:
  explicit CpfgSymbols(const ModuleTypes& types);

  std::size_t size() const { return ops_.size(); }
  CpfgOp op(ModuleId id) const { return id < ops_.size() ? ops_[id] : CpfgOp::None; }
  // Number of float parameters of a module of this type (@L's after its string).
  int params(ModuleId id) const { return id < params_.size() ? params_[id] : 0; }
  // The module ids of ?P ?H ?L ?U, for the derivation's query pass; with
  // queries read split (? P(x,y,z)), those of P, H, L and U.
  std::vector<ModuleId> query_modules() const;

 private:
  std::vector<CpfgOp> ops_;
  std::vector<ModuleId> split_queries_;
  std::vector<std::uint8_t> params_;
};

}  // namespace sylva::turtle
