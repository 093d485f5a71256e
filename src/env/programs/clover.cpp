// clover: direct light from above reaching points on the ground, shaded by
// leaves (EnviroManual 3.2.1). A module ?E(p1) or ?E(0, p2) asks for the light
// at the turtle position; ?E(1, a) adds a leaf, a disk of area a, there and
// ?E(2, a) removes one. All leaves of a pass are entered first, then every
// light query of the pass is answered in p1 (p2 and the leaf modules are left
// as they were). Leaves stay from step to step unless "remove old leaves:
// yes", which clears them after each pass.
#include <cmath>
#include <iostream>
#include <sstream>

#include "env/programs/clover_leaf_grid.h"
#include "env/programs/clover_parameters.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"

namespace sylva::env {

namespace {

enum class CloverAction { query, add_leaf, remove_leaf };

class Clover : public Field {
 public:
  explicit Clover(const CloverParameters& parameters)
      : grid_(parameters), z_is_up_(parameters.z_is_up), remove_old_leaves_(parameters.remove_old_leaves),
        verbose_(parameters.verbose) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<std::size_t> light_queries;
    std::size_t added = 0, removed = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      if (q.module.parameters.empty()) continue;
      CloverAction action = action_of(q);
      if (action == CloverAction::query) {
        light_queries.push_back(i);
        continue;
      }
      auto [u, v] = ground_point(q);
      grid_.change_leaf(u, v, q.module.parameters[1], action == CloverAction::add_leaf ? 1 : -1);
      ++(action == CloverAction::add_leaf ? added : removed);
    }
    for (std::size_t i : light_queries) {
      auto [u, v] = ground_point(queries[i]);
      answers[i].assign(0, static_cast<float>(grid_.light_at(u, v)));
    }
    if (verbose_) {
      std::cerr << "clover: step " << step << ": " << light_queries.size() << " light queries, " << added
                << " leaves added, " << removed << " removed\n";
    }
    if (remove_old_leaves_) grid_.remove_all_leaves();
  }

 private:
  // One parameter: a light query. Two or more: p1 says what to do.
  static CloverAction action_of(const Query& q) {
    if (q.module.parameters.size() == 1) return CloverAction::query;
    float p1 = q.module.parameters[0];
    if (p1 == 0) return CloverAction::query;
    if (p1 == 1) return CloverAction::add_leaf;
    if (p1 == 2) return CloverAction::remove_leaf;
    std::ostringstream problem;
    problem << "asks for action " << p1 << "; expected 0 (light query), 1 (add a leaf) or 2 (remove a leaf)";
    fail_module("clover", q, problem.str());
  }

  std::pair<double, double> ground_point(const Query& q) const {
    const std::array<float, 3>& p = turtle_position(q, "clover");
    return {p[0], z_is_up_ ? p[1] : p[2]};
  }

  LeafGrid grid_;
  bool z_is_up_;
  bool remove_old_leaves_;
  bool verbose_;
};

}  // namespace

std::unique_ptr<Field> make_clover(const ProgramInvocation& invocation) {
  return std::make_unique<Clover>(read_clover_parameters(parameter_file_path(invocation, "clover", ParameterDialect::light)));
}

}  // namespace sylva::env
