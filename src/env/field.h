// The interface between a model and its environment (open L-systems).
//
// Before each derivation step (as lpfg and cpfg do: n passes for n steps,
// the first over the axiom) the engine interprets the string and, for every
// communication module (lpfg E1/E2/EA20, cpfg ?E), records a Query: the
// module's parameters, the turtle state there, and optionally the module that
// follows it. All queries of one pass go to the Field at once, in string
// order; the field fills in an Answer per query. Values the field does not set
// keep the module's current parameters.
//
// This is the same data as the Virtual Laboratory's communication library
// (CTURTLE, Cmodule_type) so that a program written for it maps one to one.
// Built-in programs (honda81, chiba, ...) and the external-process bridge are
// Fields; users add their own by implementing one: passed to Simulation
// (EnvironmentOptions::field) or loaded as a plugin (see make_field in
// environment.h for how a .e file picks one, and docs/environment.md).
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sylva::env {

// The most parameters a communication module carries (EA20, cpfg CMAXPARAMS).
inline constexpr int kMaxParameters = 20;

// The turtle as reported to the environment where a communication module was
// met (the communication library's CTURTLE). A count is the number of
// values of that field the .e file asks for (its format's conversions, e.g.
// "turtle position: %g %g" gives 2); 0 means the field was not requested and
// a program must not rely on it. Vectors are always filled in full.
struct TurtleReport {
  std::array<float, 3> position{};
  std::array<float, 3> heading{};
  std::array<float, 3> left{};
  std::array<float, 3> up{};
  float line_width = 0;
  float scale_factor = 1;
  int position_count = 0;
  int heading_count = 0;
  int left_count = 0;
  int up_count = 0;
  int line_width_count = 0;
  int scale_factor_count = 0;
};

// A module as the environment sees it: its name as written in the model and
// its parameters as floats (cpfg's ?E is sent as "?E"; lpfg's E1 as "E1").
struct ModuleRecord {
  std::string symbol;
  std::vector<float> parameters;
};

struct Query {
  // Position of the communication module in the string, increasing in string
  // order. A module an interpretation rule produced carries the place of the
  // module the rule replaced (it is not in the string: its answer is not
  // used, as in cpfg), so several may share one.
  std::uint64_t id = 0;
  ModuleRecord module;
  // The next module in the string; symbol empty when the .e file does not ask
  // for it ("following module: no"), the string ends, or the module was
  // produced by an interpretation rule.
  ModuleRecord following;
  TurtleReport turtle;
};

// The reply to one query: value[i] replaces parameter i where set[i] is true.
struct Answer {
  std::array<float, kMaxParameters> value{};
  std::bitset<kMaxParameters> set;

  void assign(int parameter, float v) {
    value[parameter] = v;
    set.set(parameter);
  }
};

class Field {
 public:
  virtual ~Field() = default;

  // Answers every query of one environmental pass. `answers` has one entry per
  // query, all unset on entry. `step` is the number of derivation steps done
  // (0 for the pass over the axiom, before step 1).
  // Throws ModelError (or std::runtime_error) with a message naming the
  // program on failure.
  virtual void answer(std::span<const Query> queries, std::span<Answer> answers, int step) = 0;

  // Called once when the simulation ends (external programs are told to exit).
  virtual void finish() {}
};

}  // namespace sylva::env
