// Gillespie groups (LPFG manual 7.2). A derivation step whose group is a
// Gillespie group rewrites one module of the whole string: the group's
// productions offer reactions (`propensity p produce S;`), one is chosen with
// probability proportional to its propensity, and the time to it is drawn
// from the exponential distribution of rate P, the sum of the propensities —
// Gillespie's direct method. Every other module stays as it is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sylva/abi.h"

namespace sylva::derive {

// Whether `group` is one of the model's Gillespie groups.
bool is_gillespie_group(const abi::ModelDescriptor& model, int group);

// The generator of Gillespie steps, lpfg's: erand48 on its own 48-bit state
// (SeedGillespie(seed) makes it seed's low 32 bits), apart from ran()'s.
// Returns a number in [0,1).
double gillespie_uniform(std::uint64_t& state);

// The time to the next reaction, τ = -ln(1 - χ) / P for χ uniform in [0,1),
// computed as lpfg does (the manual prints ln(1 - χ) / P, which is never
// positive; time runs forward).
double gillespie_time(double chi, double total_propensity);

// The reactions offered in one Gillespie step, in string order and, within a
// module, in the order the body offers them.
class ReactionSet {
 public:
  struct Reaction {
    double propensity;
    std::size_t begin, end;                      // the strict predecessor, in the string
    std::size_t successor_begin, successor_end;  // in successors()
  };

  void clear();
  // Makes the body about to run with `call` offer its reactions here, for the
  // strict predecessor [begin, end) it matched.
  void listen(abi::RuleCall& call, std::size_t begin, std::size_t end);
  // How many reactions bodies have offered since clear() (zero propensities
  // too): a production that offers any gives its module's reactions.
  std::size_t offers() const { return offers_; }
  // A propensity that cannot be one (negative, infinite, not a number) is
  // taken as 0, as lpfg takes it: what the first was, the first time one is
  // offered (empty otherwise and from then on).
  std::string take_warning();

  bool empty() const { return reactions_.empty(); }
  double total_propensity() const { return total_; }
  // The reaction chosen by u in [0,1), as lpfg chooses: r = u * P, less each
  // reaction's propensity in turn until r is 0 or less. Null if rounding
  // leaves r above 0 after the last (lpfg then fires none).
  const Reaction* choose(double u) const;
  const unsigned char* successors() const { return successors_.data(); }

 private:
  static void propose(abi::RuleCall* call, double propensity);

  std::vector<Reaction> reactions_;
  std::vector<unsigned char> successors_;
  double total_ = 0;
  // The body now listening.
  std::size_t begin_ = 0, end_ = 0, body_start_ = 0;
  std::size_t offers_ = 0;
  std::string warning_;
  bool warned_ = false;
};

}  // namespace sylva::derive
