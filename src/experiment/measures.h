// The measures of an experiment: expressions over a derived string and its
// drawing, one number each (docs/experiments.md).
//
//   count(A)            modules named A ("count(\"+\")" for cpfg's symbols)
//   sum(A, k) mean(A, k) min(A, k) max(A, k)
//                       of the k-th number of A's parameters (k from 1)
//   modules             every module of the string
//   height width depth  the drawing's extent along y, x and z: segment ends,
//                       polygon and surface vertices, discs and spheres
//                       (line widths not included)
//   segment_length segments   the drawn segments' total length, their number
//   leaf_area           the area of polygons, rhombi, triangles and surfaces
//   an earlier measure's name, numbers, + - * / ^, ( ), sqrt log exp abs
//
// A mean, min or max over no modules is not a number (the table's NA).
#pragma once

#include <memory>
#include <vector>

#include "experiment/plan.h"
#include "geometry/scene.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"

namespace sylva::experiment {

class Measures {
 public:
  // Parses the expressions and checks them against the model's modules:
  // ModelError at the plan's line and the column of what is wrong.
  Measures(const std::vector<MeasureSpec>& specs, const ModuleTypes& types);
  ~Measures();
  Measures(Measures&&) noexcept;

  // Whether a measure needs the string interpreted (the drawing).
  bool needs_scene() const;
  // The measures' values, in the plan's order. `scene` may be null when
  // !needs_scene().
  std::vector<double> evaluate(const ModuleString& string, const ModuleTypes& types, const geometry::Scene* scene) const;

  struct Expression;

 private:
  std::vector<std::unique_ptr<Expression>> expressions_;
  std::vector<std::pair<ModuleId, int>> wanted_;  // (module, parameter number; 0: the count)
  std::vector<std::vector<int>> feeds_;            // by module id: the wanted_ entries it feeds
  bool needs_scene_ = false;
};

// The drawing's measures, on their own for tests.
struct SceneMeasures {
  double height = 0, width = 0, depth = 0;
  double segment_length = 0;
  double segments = 0;
  double leaf_area = 0;
};
SceneMeasures measure_scene(const geometry::Scene& scene);

}  // namespace sylva::experiment
