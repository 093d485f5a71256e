// clover (EnviroManual 3.2.1; the Virtual Laboratory's ENVIRO/clover): light
// from above reaching points on the ground, shaded by leaves. Its rules are
// the real program's:
//  - ?E(x) with one parameter, or ?E(0, ...): a light query at the turtle
//    position. Its answer: p1 = the light of the cell there (0 outside the
//    grid) and, for a module with two or more parameters, p2 = the image's
//    second value there (see clover_leaf_grid.h).
//  - ?E(1, a): a leaf of area a at the turtle position; ?E(v, a) for any
//    other v != 0 removes one. Leaves get no answer.
//  - Queries are read in string order: every leaf of a pass is placed (or
//    removed) first, then every light query of the pass is answered. Leaves
//    stay from pass to pass; with "remove old leaves: on" each pass starts
//    from an empty grid.
//  - The ground is x y ("z is up", the default) or x z; the .e file must send
//    two position values (three for x z), else the query gets no answer.
//  - A module without parameters gets no answer.
#include <cmath>
#include <iostream>

#include "env/programs/clover_leaf_grid.h"
#include "env/programs/clover_parameters.h"
#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"

namespace sylva::env {

namespace {

constexpr const char* kProgram = "clover";

class Clover : public Field {
 public:
  explicit Clover(const CloverParameters& parameters)
      : grid_(parameters),
        z_is_up_(parameters.z_is_up),
        remove_old_leaves_(parameters.remove_old_leaves),
        verbose_(parameters.verbose) {}

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    if (remove_old_leaves_) grid_.remove_all_leaves();
    std::vector<std::size_t> light_queries;
    std::size_t leaves = 0, without_position = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      const std::vector<float>& p = q.module.parameters;
      if (p.empty()) continue;
      if (q.turtle.position_count < (z_is_up_ ? 2 : 3)) {
        ++without_position;
        continue;
      }
      if (p.size() == 1 || p[0] == 0) {
        light_queries.push_back(i);
        continue;
      }
      const auto [u, v] = ground_point(q);
      grid_.change_leaf(u, v, p[1], p[0] == 1 ? 1 : -1);
      ++leaves;
    }
    for (std::size_t i : light_queries) {
      const auto [u, v] = ground_point(queries[i]);
      const std::optional<std::size_t> cell = grid_.cell_at(u, v);
      answers[i].assign(0, cell ? grid_.light(*cell) : 0.0f);
      if (queries[i].module.parameters.size() >= 2) answers[i].assign(1, cell ? grid_.second_value(*cell) : 0.0f);
    }
    if (without_position > 0 && !warned_position_) {
      warned_position_ = true;
      std::cerr << "warning: " << kProgram << ": " << without_position
                << " communication modules skipped: the .e file does not send the turtle position with "
                << (z_is_up_ ? "two" : "three") << " values ('turtle position: %f %f %f')\n";
    }
    if (verbose_)
      std::cerr << kProgram << ": pass before step " << step + 1 << ": " << light_queries.size() << " light queries, "
                << leaves << " leaves added or removed\n";
  }

 private:
  std::pair<float, float> ground_point(const Query& q) const {
    const std::array<float, 3>& p = q.turtle.position;
    return {p[0], z_is_up_ ? p[1] : p[2]};
  }

  LeafGrid grid_;
  bool z_is_up_;
  bool remove_old_leaves_;
  bool verbose_;
  bool warned_position_ = false;
};

}  // namespace

std::unique_ptr<Field> make_clover(const ProgramInvocation& invocation) {
  return std::make_unique<Clover>(
      read_clover_parameters(vlab_spec_file_path(invocation, kProgram), invocation.directory));
}

}  // namespace sylva::env
