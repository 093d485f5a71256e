// Runs a compiled model: the control statements in the order the LPFG manual
// gives (Start, axiom, then StartEach / step / decomposition / EndEach for
// each step, End), derivation steps forward or backward, decomposition after
// the axiom and every step, and interpretation rules on demand.
#pragma once

#include <deque>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "derive/gillespie.h"
#include "derive/rule_index.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"
#include "sylva/abi.h"

namespace sylva::derive {

// Receives the string as the turtle sees it: each module after interpretation
// rules, with the position of the string module it came from.
class InterpretedModuleVisitor {
 public:
  virtual ~InterpretedModuleVisitor() = default;
  // `in_string` is true when the module is the string's own (not produced by
  // an interpretation rule): writes to `params` then change the string, which
  // is how query modules (GetPos ...) receive their values.
  virtual void visit(ModuleId id, unsigned char* params, std::uint32_t source_index, bool in_string) = 0;
};

class Derivation {
 public:
  using MessageSink = std::function<void(const std::string&)>;

  // `messages` receives Printf output and warnings; by default they go to stderr.
  explicit Derivation(const abi::ModelDescriptor& model, MessageSink messages = {});
  ~Derivation();
  Derivation(const Derivation&) = delete;
  Derivation& operator=(const Derivation&) = delete;

  // Start, the axiom and its decomposition.
  void begin();
  // One derivation step: StartEach, the step, decomposition, EndEach.
  void step();
  // End.
  void finish();
  // begin(), `steps` steps (the model's derivation length if negative) unless
  // the model calls Stop(), finish().
  void run(int steps = -1);

  int derivation_length() const;
  int steps_done() const { return steps_done_; }
  bool stop_requested() const { return control().stop_requested; }

  const ModuleString& string() const { return string_; }
  const ModuleTypes& types() const { return types_; }
  // The string with interpretation rules applied (what the turtle draws).
  ModuleString interpreted();
  // The view (LPFG manual 7.3) whose interpretation rules interpret() and
  // interpreted() apply: vgroup `view`'s, then those outside any vgroup.
  void set_view(int view) { view_ = view; }
  int view() const { return view_; }

  // Starts the next begin() from `string` instead of the axiom (a saved
  // string: it is not decomposed again).
  void set_initial_string(const ModuleString& string);
  // Replaces the current string (LoadString). Only between derivation
  // passes: throws ModelError while rules are being applied. Called from
  // Start, the axiom is not used.
  void replace_string(ModuleString string);

  // Points in a run where the engine acts on the model's requests:
  // Starting before Start, Started after the axiom, Stepped after each step
  // (after EndEach), Finished after End. `stopped` says whether Stop() was
  // called since the previous point.
  enum class Phase { Starting, Started, Stepped, Finished };
  void set_phase_hook(std::function<void(Phase, bool stopped)> hook) { phase_hook_ = std::move(hook); }
  // The same, module by module, to a visitor.
  void interpret(InterpretedModuleVisitor& visitor);

  // Whether a production's predecessor holds a query module (GetPos, GetHead,
  // GetLeft, GetUp): then the string is interpreted after the axiom and after
  // every step, so those modules carry the turtle's state.
  bool uses_query_modules() const { return uses_query_modules_; }
  // More module types that the query pass fills, beyond the four predefined
  // ones: the interpreter of a model whose own module types are queries
  // (cpfg's ?P ?H ?L ?U) names them here, before the axiom, so the engine
  // need not know them. Any such module makes the query pass run, as cpfg
  // fills them whether or not a production reads them.
  void add_query_modules(const std::vector<ModuleId>& ids);
  // Called after the axiom and after every step (after decomposition, before
  // EndEach) when the model uses query modules.
  void set_query_pass(std::function<void(Derivation&)> pass) { query_pass_ = std::move(pass); }
  // The environmental pass of open L-systems (communication modules E1, E2,
  // EA20, cpfg's ?E): called at the start of every step, before StartEach,
  // while the model's Environment() switch is on (it is at every begin();
  // Start may turn it off). lpfg and cpfg both run it there (their Derive
  // starts with it), so the first pass sees the axiom and no pass follows the
  // last step.
  void set_environment_pass(std::function<void(Derivation&)> pass) { environment_pass_ = std::move(pass); }

 private:

  abi::ControlState& control() const { return *model_.control; }
  // The group whose rules apply: lpfg's current group, or with cpfg's
  // sub-L-systems the label of the L-system the scan is in.
  int current_group() const { return sub_lsystems_ ? lsystems_.back() : control().current_group; }
  // cpfg sub-L-systems: the stack of L-system labels while a pass scans the
  // string; ?(label,s) pushes, $ pops.
  void reset_lsystems();
  void track_lsystem(ModuleId id, const unsigned char* params);
  void track_lsystems(const StringView& src, std::size_t from, std::size_t to);
  SkipTable skip_table(const abi::Rule& rule) const;
  // Whether a production's predecessor holds one of these module types.
  bool predecessor_holds(const std::vector<ModuleId>& ids) const;
  // The current string as context matching sees it (a ring if the model says so).
  StringView current_view() const;

  // Decomposition of string_ in place (through next_).
  void decompose();
  // One pass of productions over string_ into next_.
  void derive_forward();
  void derive_backward();
  // One step of a Gillespie group (gillespie_step.cpp): one reaction fires.
  void derive_gillespie();
  // Decomposition or interpretation: rules applied recursively to each module
  // and its successors, up to max_depth levels.
  void expand(abi::RuleKind kind, const StringView& source, int depth, int max_depth, ModuleString& out);

  // Tries the rules for the module at `pos`; on success returns true with
  // `*consumed` the offset past the strict predecessor.
  // `built` is the new string so far, for new left context.
  bool apply_forward(abi::RuleKind kind, const StringView& src, std::size_t pos, ModuleString& out,
                     const ModuleString& built, bool call_body, std::size_t* consumed);
  bool try_forward(const abi::Rule& rule, const StringView& src, std::size_t pos, ModuleString& out,
                   const ModuleString& built, bool call_body, std::size_t* consumed);
  bool try_backward(const abi::Rule& rule, const StringView& src, std::size_t end, const StringView& new_string,
                    std::size_t* consumed);

  void warn_depth_reached(abi::RuleKind kind, ModuleId id, int max_depth);
  void message(const std::string& text) const;

  const abi::ModelDescriptor& model_;
  ModuleTypes types_;
  RuleIndex rules_;
  std::vector<std::vector<std::uint8_t>> skip_tables_;
  MessageSink messages_;

  ModuleString string_;
  ModuleString next_;
  ModuleString successor_;  // backward derivation builds each successor here
  ModuleString probe_out_;  // the probing pass's output (kModelProbeProductions): stays empty
  PrependBuffer backward_out_;
  std::deque<ModuleString> expansion_scratch_;  // one per decomposition depth
  std::set<std::pair<int, ModuleId>> depth_warnings_;
  int steps_done_ = 0;
  bool begun_ = false;
  bool ring_ = false;
  bool uses_query_modules_ = false;
  bool sub_lsystems_ = false;
  std::vector<int> lsystems_;
  std::function<void(Derivation&)> query_pass_;
  std::function<void(Derivation&)> environment_pass_;
  std::function<void(Phase, bool)> phase_hook_;
  void phase(Phase p, bool stopped_before);
  int view_ = 0;
  bool has_views_ = false;   // some interpretation rule is in a vgroup
  int passes_running_ = 0;   // rules are being applied: the string must stay
  bool in_start_ = false;
  bool loaded_in_start_ = false;
  std::optional<ModuleString> initial_string_;
  ModuleString interpretation_out_;
  ReactionSet reactions_;
  std::set<int> warned_groups_;                 // UseGroup numbers already warned about
  ReactionSet* gathering_reactions_ = nullptr;  // set while a Gillespie step runs bodies
  ModuleString reaction_scratch_;               // where those bodies write
  static constexpr double kMaxGrowthReserved = 8;
  double growth_ = 1.5;  // bytes after / before the last step, at most kMaxGrowthReserved
};

}  // namespace sylva::derive
