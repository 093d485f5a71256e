// ecosystem (EnviroManual 3.1.2; the Virtual Laboratory's ENVIRO/ecosystem):
// collisions between disks (or spheres with "3d case: on") of different
// sizes, e.g. plants in a field. Computed as the real program computes it.
//
// Specification file (read as the real program reads it, vlab_spec_file.h):
//   grid size: x y [z]   voxels per axis, read with atoi (below 1: 1); default 1 1 1
//   3d case: on|yes      spheres in x y z; otherwise disks in x and z
//   vigor: on            the second parameter is a vigor
//   verbose: on|1
// Keywords are matched exactly: "3D case" is not "3d case" (ignored with a
// warning, as the real program ignores it).
// Query:  ?E(radius[, p2]) at the turtle position, which the .e file must send
//         with three values; without vigor p2 is a group (truncated to an
//         integer, 0 when absent), with vigor p2 is the vigor (1 when absent).
// Answer: p1 = 0 when the object collides with one that beats it, else 1.
//
// The rule, as the real program has it:
//  - Two objects of one group collide when their centres are at most the sum
//    of their radii apart (squared, in float): touching collides.
//  - Without vigor an object loses to any colliding object whose radius is
//    equal or larger: two equal objects stop each other.
//  - With vigor the objects are tested in string order; an object loses to a
//    colliding object with a higher vigor, or an equal vigor and a strictly
//    larger radius, unless that object has already lost in this pass.
//  - Only objects sharing a voxel are compared. Each object is entered in the
//    voxels its bounding box covers, widened by one voxel each way, of a grid
//    fitted around the objects. The program fits the grid with one slip: in
//    2D, the first object's extent along the second axis is taken from the
//    turtle's y, not its z. Objects outside the grid lie in its border voxels,
//    or, when entirely below it along an axis, in none: they meet nothing.
//  - A query without three position values or with too few parameters gets
//    no answer and takes no part.
// Objects are compared within one pass only.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <iostream>
#include <limits>

#include "env/programs/program_inputs.h"
#include "env/programs/programs.h"
#include "env/programs/vlab_spec_file.h"

namespace sylva::env {
namespace {

constexpr const char* kProgram = "ecosystem";
constexpr const char* kDelimiters = "x,; \t:\n";

struct EcosystemSettings {
  std::array<int, 3> grid_size{1, 1, 1};
  bool three_d = false;
  bool vigor = false;
  bool verbose = false;
};

EcosystemSettings read_ecosystem_settings(const std::filesystem::path& path) {
  EcosystemSettings settings;
  read_vlab_spec_file(path, kProgram, {"verbose", "grid size", "3d case", "vigor"},
                      [&](std::size_t keyword, SpecLineTokens& line) {
                        switch (keyword) {
                          case 0: line.next_switch(kDelimiters, {"on", "1"}, {"off", "0"}, true, settings.verbose); break;
                          case 1:
                            // Each number replaces its axis as it is read; a line
                            // with two keeps the third.
                            for (int& size : settings.grid_size) {
                              const std::optional<int> value = line.next_integer(kDelimiters);
                              if (!value) break;
                              size = *value < 1 ? 1 : *value;
                            }
                            break;
                          case 2:
                            line.next_switch(kDelimiters, {"on", "yes"}, {"off", "no"}, true, settings.three_d);
                            break;
                          case 3: line.next_switch(kDelimiters, {"on"}, {"off"}, true, settings.vigor); break;
                        }
                      });
  // The cells are counted in int, as the real program counts them.
  const double cells = static_cast<double>(settings.grid_size[0]) * settings.grid_size[1] *
                       (settings.three_d ? settings.grid_size[2] : 1);
  if (cells > 1e8)
    throw std::runtime_error(path.string() + ": " + kProgram + ": a grid of " + std::to_string(cells) +
                             " voxels is more than this program can hold");
  return settings;
}

// One object of a pass.
struct Item {
  std::array<float, 3> position{};  // x, then y or (in 2D) z, then z or 0
  float radius = 0;
  float vigor = 1;
  int group = 0;
  bool removed = false;          // lost to a more vigorous object in this pass
  std::array<int, 3> low{}, high{};  // the voxels it lies in, per axis (empty when high < low)
  std::size_t query = 0;
};

// C's conversion of an integral double to int, kept within int.
int to_int(double value) {
  if (!(value == value)) return 0;
  return static_cast<int>(std::fmax(std::fmin(value, std::numeric_limits<int>::max()), std::numeric_limits<int>::min()));
}

class Ecosystem : public Field {
 public:
  explicit Ecosystem(EcosystemSettings settings) : s_(settings) {
    dimensions_ = s_.three_d ? 3 : 2;
    if (!s_.three_d) s_.grid_size[2] = 1;
  }

  void answer(std::span<const Query> queries, std::span<Answer> answers, int step) override {
    std::vector<Item> items = store(queries);
    fit_grid(items, queries);
    fill_cells(items);
    std::size_t stopped = 0;
    for (Item& item : items) {
      const bool free = !collides(item, items);
      answers[item.query].assign(0, free ? 1.0f : 0.0f);
      stopped += !free;
    }
    if (s_.verbose)
      std::cerr << kProgram << ": pass before step " << step + 1 << ": " << items.size() << " objects, " << stopped
                << " stopped\n";
  }

 private:
  std::vector<Item> store(std::span<const Query> queries) {
    std::vector<Item> items;
    std::size_t without_position = 0, without_parameters = 0;
    const std::size_t needed = s_.vigor ? 2 : 1;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const Query& query = queries[q];
      if (query.turtle.position_count < 3) {
        ++without_position;
        continue;
      }
      const std::vector<float>& p = query.module.parameters;
      if (p.size() < needed) {
        ++without_parameters;
        continue;
      }
      Item item;
      const std::array<float, 3>& at = query.turtle.position;
      item.position = s_.three_d ? at : std::array<float, 3>{at[0], at[2], 0.0f};
      item.radius = p[0];
      if (s_.vigor) item.vigor = p.size() > 1 ? p[1] : 1.0f;
      else item.group = p.size() > 1 ? to_int(std::trunc(p[1])) : 0;
      item.query = q;
      items.push_back(item);
    }
    if (without_position > 0)
      warn_once(warned_position_, std::to_string(without_position) +
                                      " communication modules skipped: the .e file does not send the turtle position "
                                      "with three values ('turtle position: %g %g %g')");
    if (without_parameters > 0)
      warn_once(warned_parameters_, std::to_string(without_parameters) +
                                        " communication modules skipped: not enough parameters (the radius" +
                                        (s_.vigor ? ", then the vigor)" : ")"));
    return items;
  }

  // The grid encloses the objects' extents (with the real program's slip for
  // the first object in 2D), widened by 0.001 each way.
  void fit_grid(const std::vector<Item>& items, std::span<const Query> queries) {
    if (items.empty()) return;
    std::array<float, 3> low{}, high{};
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Item& item = items[i];
      for (int c = 0; c < dimensions_; ++c) {
        const float centre = i == 0 ? queries[item.query].turtle.position[c] : item.position[c];
        const float from = centre - item.radius, to = centre + item.radius;
        if (i == 0 || low[c] > from) low[c] = from;
        if (i == 0 || high[c] < to) high[c] = to;
      }
    }
    for (int c = 0; c < dimensions_; ++c) {
      grid_position_[c] = static_cast<float>(low[c] - 0.001);
      grid_range_[c] = static_cast<float>((high[c] - low[c]) + 0.002);
    }
  }

  int cell_index(int x, int y, int z) const { return (z * s_.grid_size[1] + y) * s_.grid_size[0] + x; }

  // Enters each object in its voxels (cell_start_/cell_items_, a list per voxel).
  void fill_cells(std::vector<Item>& items) {
    const std::size_t cells = static_cast<std::size_t>(s_.grid_size[0]) * s_.grid_size[1] * s_.grid_size[2];
    cell_start_.assign(cells + 1, 0);
    for (Item& item : items) {
      item.low = item.high = {0, 0, 0};
      for (int c = 0; c < dimensions_; ++c) {
        const float scale = static_cast<float>(s_.grid_size[c]);
        const float from = (item.position[c] - item.radius - grid_position_[c]) / grid_range_[c] * scale;
        const float to = (item.position[c] + item.radius - grid_position_[c]) / grid_range_[c] * scale;
        // floor in double, as C's floor takes it.
        item.low[c] = std::max(to_int(std::floor(static_cast<double>(from)) - 1), 0);
        item.high[c] = std::min(to_int(1 + std::floor(static_cast<double>(to))), s_.grid_size[c] - 1);
      }
      for_each_cell(item, [&](int cell) { ++cell_start_[cell + 1]; });
    }
    for (std::size_t k = 0; k < cells; ++k) cell_start_[k + 1] += cell_start_[k];
    cell_items_.resize(cell_start_[cells]);
    std::vector<std::uint32_t> filled(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < items.size(); ++i)
      for_each_cell(items[i], [&](int cell) { cell_items_[filled[cell]++] = static_cast<std::uint32_t>(i); });
  }

  template <class Visit>
  void for_each_cell(const Item& item, Visit&& visit) const {
    for (int z = item.low[2]; z <= item.high[2]; ++z)
      for (int y = item.low[1]; y <= item.high[1]; ++y)
        for (int x = item.low[0]; x <= item.high[0]; ++x) visit(cell_index(x, y, z));
  }

  // The real program's TestIntersection.
  bool collides(Item& item, const std::vector<Item>& items) const {
    bool found = false;
    for_each_cell(item, [&](int cell) {
      for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const Item& other = items[cell_items_[k]];
        if (&other == &item || other.group != item.group) continue;
        if (s_.vigor) {
          if (other.removed || !overlap(item, other)) continue;
          if (item.vigor < other.vigor || (item.vigor == other.vigor && item.radius < other.radius)) {
            found = true;
            item.removed = true;
          }
        } else if (item.radius <= other.radius && overlap(item, other)) {
          found = true;
        }
      }
    });
    return found;
  }

  bool overlap(const Item& a, const Item& b) const {
    const float dx = a.position[0] - b.position[0];
    const float dy = a.position[1] - b.position[1];
    const float dz = s_.three_d ? a.position[2] - b.position[2] : 0.0f;
    const float reach = a.radius + b.radius;
    return dx * dx + dy * dy + dz * dz <= reach * reach;
  }

  static void warn_once(bool& warned, const std::string& message) {
    if (warned) return;
    warned = true;
    std::cerr << "warning: " << kProgram << ": " << message << "\n";
  }

  EcosystemSettings s_;
  int dimensions_ = 2;
  std::array<float, 3> grid_position_{}, grid_range_{1, 1, 1};
  std::vector<std::uint32_t> cell_start_;  // per voxel, where its objects begin in cell_items_
  std::vector<std::uint32_t> cell_items_;
  bool warned_position_ = false;
  bool warned_parameters_ = false;
};

}  // namespace

std::unique_ptr<Field> make_ecosystem(const ProgramInvocation& invocation) {
  return std::make_unique<Ecosystem>(read_ecosystem_settings(vlab_spec_file_path(invocation, kProgram)));
}

}  // namespace sylva::env
