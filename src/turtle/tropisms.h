// The tropisms' elasticities as the turtle carries them: the view file's
// tropisms (ids 1..n) and the simple tropism, changed by modules, saved and
// restored with the turtle's state at [ and ], and bending the heading after
// each drawn step (LPFG manual 8.1.4).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "turtle/frame.h"
#include "turtle/turtle_settings.h"

namespace sylva::turtle {

class Tropisms {
 public:
  explicit Tropisms(const TurtleSettings& settings);

  // Whether any elasticity is not zero: only then does a step bend.
  bool bending() const { return bending_; }
  // Bends (or twists) `frame` toward every tropism of non-zero elasticity.
  void bend(Frame& frame) const;

  // Tropism `id`'s elasticity set to `value` or (relative) changed by it;
  // returns the new elasticity, none when there is no such tropism.
  std::optional<float> set(int id, float value, bool relative);
  void set_simple(float value);

  void push() { saved_.insert(saved_.end(), elasticity_.begin(), elasticity_.end()); }
  // Back to the elasticities of the last push (there must be one).
  void pop() {
    const std::size_t n = elasticity_.size();
    std::copy(saved_.end() - static_cast<std::ptrdiff_t>(n), saved_.end(), elasticity_.begin());
    saved_.resize(saved_.size() - n);
    update_bending();
  }

 private:
  void update_bending() {
    bending_ = std::any_of(elasticity_.begin(), elasticity_.end(), [](float e) { return e != 0; });
  }

  const TurtleSettings& settings_;
  // The view file's tropisms' (ids 1..n at 0..n-1) and the simple tropism's (at n).
  std::vector<float> elasticity_;
  std::vector<float> saved_;
  bool bending_ = false;
};

}  // namespace sylva::turtle
