// Values that a pass over the interpreted string has for the string's own
// modules: the turtle's answers to query modules (GetPos ..., cpfg's ?P ...)
// and the environment's answers to communication modules (E1, EA20, ?E).
// Interpretation reads the string; these are written afterwards, in one walk,
// by Derivation::write_parameters.
#pragma once

#include <cstdint>
#include <vector>

namespace sylva::derive {

class ParameterWrites {
 public:
  // Module `module_index` of the string (counted from 0, as the interpreted
  // modules' source_index) gets `count` floats from parameter `first_float`.
  void set_floats(std::uint32_t module_index, int first_float, const float* values, int count) {
    writes_.push_back(Write{module_index, first_float, count, static_cast<std::uint32_t>(values_.size())});
    values_.insert(values_.end(), values, values + count);
  }
  bool empty() const { return writes_.empty(); }

  struct Write {
    std::uint32_t module_index;
    int first_float;
    int count;
    std::uint32_t value_offset;  // into values()
  };
  const std::vector<Write>& writes() const { return writes_; }
  const std::vector<float>& values() const { return values_; }

 private:
  std::vector<Write> writes_;
  std::vector<float> values_;
};

}  // namespace sylva::derive
