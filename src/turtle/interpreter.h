// The 3D turtle (LPFG manual chapter 5): interprets the string, module by
// module after interpretation rules, into a Scene. Query modules (GetPos ...)
// found in the string receive the turtle's state.
#pragma once

#include <string>

#include "derive/derivation.h"
#include "geometry/scene.h"
#include "turtle/turtle_settings.h"

namespace sylva::turtle {

class TurtleInterpreter : public derive::InterpretedModuleVisitor {
 public:
  // `scene` may be null (only the turtle's state matters: query modules);
  // `trace`, when given, receives one line per turtle command (sylva run --turtle).
  TurtleInterpreter(const TurtleSettings& settings, const ModuleTypes& types, geometry::Scene* scene,
                    std::string* trace = nullptr);
  ~TurtleInterpreter() override;

  void visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string) override;
  // Closes what the string left open (polygons, generalized cylinders).
  void finish();

  // The turtle between two visits: what an environmental program is told
  // about a communication module (E1, ?E ...) just visited.
  struct Pose {
    geometry::Vec3 position, heading, left, up;
    float width = 1;
    float scale = 1;  // cpfg's turtle scale; 1 for L+C
  };
  Pose pose() const;
  // The values of the query modules met in the string so far (GetPos ...,
  // cpfg's ?P ...), for Derivation::write_parameters.
  const derive::ParameterWrites& query_answers() const;

  TurtleInterpreter(const TurtleInterpreter&) = delete;
  TurtleInterpreter& operator=(const TurtleInterpreter&) = delete;

 private:
  struct Impl;
  Impl* impl_;
};

// Interprets the derivation's current string, as view `view` shows it, into a Scene.
geometry::Scene interpret_scene(derive::Derivation& derivation, int view, const TurtleSettings& settings,
                                std::string* trace = nullptr);

// Walks `string` as it stands, without interpretation rules (module k of the
// string is the provenance of what it draws), drawing into `scene` when given;
// `query_answers`, when given, receives what its query modules would be told.
void walk_string(const ModuleString& string, const ModuleTypes& types, const TurtleSettings& settings,
                 geometry::Scene* scene, std::string* trace = nullptr, derive::ParameterWrites* query_answers = nullptr);

// The values of the string's query modules (the query pass): the string
// interpreted with view 0's rules (LPFG manual 5.12).
derive::ParameterWrites query_answers(derive::Derivation& derivation, const TurtleSettings& settings);

}  // namespace sylva::turtle
