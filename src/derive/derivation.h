// Runs a compiled model: the control statements in the order the LPFG manual
// gives (Start, axiom, then StartEach / step / decomposition / EndEach for
// each step, End), derivation steps forward or backward, decomposition after
// the axiom and every step, and interpretation rules on demand.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "continuous/continuous_run.h"
#include "derive/chunk_output_pool.h"
#include "derive/gillespie.h"
#include "derive/parameter_writes.h"
#include "derive/rule_index.h"
#include "lstring/branch_index.h"
#include "lstring/built_branches.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"
#include "support/model_faults.h"
#include "sylva/abi.h"

namespace sylva::derive {

// Receives the string as the turtle sees it: each module after interpretation
// rules, with the index of the string module it came from.
class InterpretedModuleVisitor {
 public:
  virtual ~InterpretedModuleVisitor() = default;
  // `in_string` is true when the module is the string's own (not produced by
  // an interpretation rule): answers for it (query modules) can be written
  // back with Derivation::write_parameters.
  virtual void visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string) = 0;
};

// A passive engine: it applies the model's rules and calls its control
// statements when told to, and calls nothing back. The caller (Simulation)
// runs the passes that sit between the pieces of a step (the environment,
// query modules) and acts on what the model asked for in between.
class Derivation {
 public:
  using MessageSink = std::function<void(const std::string&)>;

  // `messages` receives Printf output and warnings; by default they go to stderr.
  explicit Derivation(const abi::ModelDescriptor& model, MessageSink messages = {});
  ~Derivation();
  Derivation(const Derivation&) = delete;
  Derivation& operator=(const Derivation&) = delete;

  // ---- a run, piece by piece, in the order the LPFG manual gives
  // Start (the control state reset first); the string is emptied.
  void start();
  // The axiom and its decomposition; or the string given to
  // set_initial_string (not decomposed again); or nothing, when Start
  // loaded a string with replace_string.
  void make_axiom();
  // StartEach, after the step number and group are set.
  void start_each();
  // The step's productions, then decomposition.
  void apply_productions();
  // EndEach.
  void end_each();
  // End.
  void end();

  // The same pieces joined, for a derivation used on its own: query modules
  // stay unfilled and no environment is asked (Simulation does both).
  void begin() { start(); make_axiom(); }
  void step() { start_each(); apply_productions(); end_each(); }
  void finish() { end(); }
  // begin(), `steps` steps (the model's derivation length if negative) unless
  // the model calls Stop(), finish().
  void run(int steps = -1);

  int derivation_length() const;
  int steps_done() const { return steps_done_; }
  bool stop_requested() const { return control().stop_requested; }
  // The model's Environment() switch: whether the environmental pass runs
  // before the next step (on at every start(); Start may turn it off).
  bool environment_enabled() const { return control().environment; }

  const ModuleString& string() const { return string_; }
  const ModuleTypes& types() const { return types_; }
  // The string with view `view`'s interpretation rules applied (what the
  // turtle draws): vgroup `view`'s (LPFG manual 7.3), then those outside any
  // vgroup, which alone are view 0's.
  ModuleString interpreted(int view = 0);
  // The same, module by module, to a visitor. The string is not changed.
  void interpret(int view, InterpretedModuleVisitor& visitor);
  // Writes answers found by a pass over the interpreted string into the
  // string's modules. Only between derivation passes.
  void write_parameters(const ParameterWrites& writes);

  // Starts the next start() from `string` instead of the axiom (a saved
  // string: it is not decomposed again).
  void set_initial_string(const ModuleString& string);
  // Replaces the current string (LoadString). Only between derivation
  // passes: throws ModelError while rules are being applied. After start(),
  // before make_axiom(), the axiom is not used.
  void replace_string(ModuleString string);

  // Whether query modules (GetPos, GetHead, GetLeft, GetUp, or those named by
  // add_query_modules) must be filled after the axiom and after every step
  // (after decomposition, before EndEach): a production's predecessor holds
  // one.
  bool uses_query_modules() const { return uses_query_modules_; }
  // More module types that the query pass fills, beyond the four predefined
  // ones: the interpreter of a model whose own module types are queries
  // (cpfg's ?P ?H ?L ?U) names them here, before the axiom, so the engine
  // need not know them. Any such module makes the query pass run, as cpfg
  // fills them whether or not a production reads them.
  void add_query_modules(const std::vector<ModuleId>& ids);

  // The step that made each module of the string (0: the axiom), by its
  // index, when asked for with track_births before start(): a module
  // rewritten by a production, decomposed, or fired in a Gillespie step is
  // made anew; one copied unchanged keeps its step; a loaded string is made
  // at the step that loaded it. Empty when not tracked.
  void track_births(bool on) { tracking_births_ = on; }
  const std::vector<std::uint32_t>& births() const { return births_; }

  // ---- continuous time: differential L-systems (continuous_passes.cpp,
  // docs/continuous-time.md). Only between derivation passes.
  // Whether the model has derivative or event rules.
  bool has_continuous_rules() const;
  // The state: the float and double parameters of every module that has a
  // derivative rule, in string order. The order holds until the string changes.
  void gather_state(std::vector<double>& y);
  // Sets the time (CurrentTime()) and writes `y` into those parameters.
  void scatter_state(double t, std::span<const double> y);
  // The rates of change of the state: each module's first derivative rule
  // whose context matches writes them; a parameter without one stays put.
  void evaluate_rates(std::span<double> dy);
  // For each module, each of its event rules whose context matches: whether
  // its condition holds and its margin.
  void read_events(std::vector<continuous::EventReading>& readings);
  // One pass of event rules: each module whose first holding event rule
  // applies is replaced by its successor; then decomposition. Returns the
  // number of productions applied.
  std::size_t fire_events();

  // ---- parallel passes (parallel_derivation.cpp)
  // Passes run on up to `threads` threads wherever the result cannot differ
  // from a serial pass's; 1: every pass is serial. A thread takes at least
  // `min_chunk_bytes` of the old string: smaller chunks cost more in threads
  // and joins than they save (tests split small strings with smaller ones).
  // With 64 KiB, a step of the branching model from 147 KB took as long on
  // two threads as on one (two chunks, the first 70% of the string); with
  // 16 KiB, 1.04 against 1.96 ms.
  static constexpr std::size_t kMinChunkBytes = std::size_t{16} << 10;
  void set_threads(int threads, std::size_t min_chunk_bytes = kMinChunkBytes);
  // ran() in rule bodies draws from a generator keyed by the pass's seed,
  // the module's place in the old string and the draw (derive/keyed_random.h),
  // not from lpfg's sequence: the same string at any thread count, and
  // bodies that call ran() may run in parallel.
  void set_keyed_random(bool on);
  // For each kind of pass, whether it runs in parallel or why it is serial
  // (the rule, its file and line, what its body does); one line each.
  std::string parallel_explanation() const;

 private:
  // Marks a pass that applies rules: the string it reads must not be replaced.
  struct PassGuard {
    int& count;
    explicit PassGuard(int& c) : count(c) { ++count; }
    ~PassGuard() { --count; }
  };
  // A stretch of the old string [source_begin, source_end) replaced by
  // `output_bytes` bytes of the new one, in the order of the old string.
  struct Rewrite {
    std::size_t source_begin, source_end, output_bytes;
  };
  void note_rewrite(std::size_t source_begin, std::size_t source_end, std::size_t output_bytes) {
    if (tracking_births_) rewrites_.push_back({source_begin, source_end, output_bytes});
  }
  // After a pass from `old` to string_: births of copied modules carried
  // over, rewritten ones made at `step` (derive/births.cpp).
  void update_births(const ModuleString& old, std::uint32_t step);
  void reset_births(std::uint32_t step);

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
  // How far apart passes note module starts in what they write, for the
  // next parallel pass to cut the string at (chunk_starts): a quarter of a
  // chunk.
  std::size_t known_start_spacing() const { return std::max<std::size_t>(min_chunk_bytes_ / 4, 1); }
  // Where a fault in the rule's body is reported (one per rule of the model).
  const model_faults::CallSite& rule_site(const abi::Rule& rule) const {
    return rule_sites_[static_cast<std::size_t>(&rule - model_.rules)];
  }
  // Whether a production's predecessor holds one of these module types.
  bool predecessor_holds(const std::vector<ModuleId>& ids) const;
  // The current string as context matching sees it (a ring if the model says so).
  StringView current_view() const;
  // Lets the production pass about to read string_ index its branches,
  // where its rules read context and the string is long enough to pay.
  void index_branches();
  // Bytes after / before each of the last passes of a kind, at most
  // kMaxGrowthReserved each, the latest first.
  struct Growth {
    std::array<double, 4> recent{1.5, 1.5, 1.5, 1.5};
    double last() const { return recent[0]; }
    // Parallel passes reserve the next string by the highest: where cells
    // divide in waves growth swings from step to step (1.19 to 1.38 in the
    // structs benchmark), and parts that find no room reserved are copied
    // in after the pass, on one thread.
    // At most half again the last, though: a burst of growth some steps ago
    // (an axiom setting up a field) would reserve memory the run may lack.
    double for_parallel_pass() const {
      return std::min(*std::max_element(recent.begin(), recent.end()), last() * 1.5);
    }
  };
  // Notes in `growth` how much next_ grew over string_ in the pass just run.
  void note_growth(Growth& growth) const;

  // Gives the pages of the strings, the branch index and the chunks' buffers
  // back on every thread (before the destructor frees them).
  void release_memory_in_parallel();
  // Why passes of `kind` run serially whatever the string, or empty.
  std::string serial_reason(abi::RuleKind kind) const;
  // Where the chunks of a parallel pass over `src` start, for a pass that
  // writes `growth` bytes for each byte it reads; none when the string is
  // too short to split.
  std::vector<std::size_t> chunk_starts(const StringView& src, double growth) const;
  // A forward step, or decomposition, on several threads into next_; false
  // (nothing done) where it must be serial.
  bool derive_forward_in_parallel();
  bool decompose_in_parallel(int max_depth);
  // The chunks of `src` starting at `starts`, each passed through `range`
  // (from, to, out; returns where it stopped), joined into next_.
  // `growth`: the bytes a pass like this one wrote for each byte it read.
  using RangePass = std::function<std::size_t(std::size_t chunk, std::size_t from, std::size_t to, ModuleString& out)>;
  void run_in_chunks(const StringView& src, const std::vector<std::size_t>& starts, double growth,
                     const RangePass& range);
  // Productions applied to the modules of `src` from `from` until the first
  // one at or past `to`, appended to `out`; returns where it stopped (past
  // `to` when a predecessor of several modules or a cut spans it).
  std::size_t forward_range(const StringView& src, std::size_t from, std::size_t to, ModuleString& out);
  // The bytes to set aside for the successor of `source_bytes` bytes.
  std::size_t affordable_reserve(std::size_t source_bytes) const;
  // ran()'s keyed generator installed for the life of a pass, in the keyed mode.
  struct KeyedRandomPass {
    abi::ControlState& control;
    KeyedRandomPass(Derivation& derivation, abi::RuleKind kind);
    ~KeyedRandomPass();
  };
  static double keyed_draw(void* host);

  // Decomposition of string_ in place (through next_).
  void decompose();
  // One pass of productions over string_ into next_.
  void derive_forward();
  void derive_backward();
  // One step of a Gillespie group (gillespie_step.cpp): one reaction fires.
  void derive_gillespie();
  // A level of expand() waiting for the successor it expanded to be written.
  struct ExpansionFrame {
    StringView source;
    std::size_t pos;            // the predecessor expanded
    std::size_t resume;         // past it
    std::size_t output_before;  // the output's size when its successor began
    int depth;
    std::uint64_t random_level;  // keyed_random::Key::level of `source`
  };
  // What expand() works in: one per thread expanding.
  struct alignas(64) Expansion {  // a cache line of its own: one per thread
    std::deque<ModuleString> scratch;  // one per level of the stack
    std::vector<ExpansionFrame> frames;
    // Modules that reached the maximum depth, in the order met, when their
    // warnings are given later (a chunk of a parallel pass); else given at once.
    bool defer_warnings = false;
    std::vector<ModuleId> depth_reached;
  };
  // Decomposition or interpretation: rules applied to each module and again
  // to its successors, up to max_depth levels, without recursion. Expands
  // the modules of `source` from `from` (its start by default) until the
  // first at or past `stop` (its end by default); returns where it stopped.
  std::size_t expand(abi::RuleKind kind, const StringView& source, int depth, int max_depth, ModuleString& out,
                     Expansion& expansion, std::size_t stop = SIZE_MAX, std::size_t from = SIZE_MAX);
  void release_deep_expansion();

  // Tries the rules for the module at `pos`; on success returns true with
  // `*consumed` the offset past the strict predecessor.
  // `built` is the new string so far, for new left context.
  bool apply_forward(abi::RuleKind kind, const StringView& src, std::size_t pos, ModuleString& out,
                     const ModuleString& built, bool call_body, std::size_t* consumed);
  bool try_forward(const abi::Rule& rule, const StringView& src, std::size_t pos, ModuleString& out,
                   const ModuleString& built, bool call_body, std::size_t* consumed);
  bool try_backward(const abi::Rule& rule, const StringView& src, std::size_t end, const StringView& new_string,
                    std::size_t* consumed);

  // The model's maximum depth setting (1 without one).
  int maximum_depth(abi::RuleKind kind) const;
  void warn_depth_reached(abi::RuleKind kind, ModuleId id, int max_depth);
  void message(const std::string& text) const;

  // Where the state lies in string_ (continuous_passes.cpp): the modules
  // with derivative rules and their continuous parameters' bytes; the
  // modules with event rules.
  struct StateSlot {
    std::size_t offset;   // in string_'s bytes
    std::uint32_t param;  // the parameter's index: where a derivative rule writes its rate
    bool is_double;
  };
  struct StateModule {
    std::size_t pos;
    std::uint32_t first_slot, slots;
  };
  void map_state();
  std::vector<StateSlot> state_slots_;
  std::vector<StateModule> state_modules_;
  std::vector<std::size_t> event_modules_;
  std::vector<double> rates_;  // a derivative rule's d(p), by parameter index
  bool probing_events_ = false;
  continuous::EventReading event_reading_{};  // what the probed event rule said

  const abi::ModelDescriptor& model_;
  ModuleTypes types_;
  RuleIndex rules_;
  std::vector<std::vector<std::uint8_t>> skip_tables_;
  std::vector<model_faults::CallSite> rule_sites_;
  MessageSink messages_;

  ModuleString string_;
  ModuleString next_;
  // Where string_'s branches open and close, while a production pass reads
  // its context (branches_ready_).
  BranchIndex branches_;
  bool branches_ready_ = false;
  bool branches_needed_ = false;  // the last production pass built the index: build it at once, in parallel
  bool productions_read_context_ = false;  // some production has a left or right context
  // The brackets of the string a production pass is building, where some
  // production reads it as context: next_ in a serial forward pass
  // (new_branches_of_ while it runs), backward_out_ in a backward pass.
  BuiltBranches new_branches_;
  const ModuleString* new_branches_of_ = nullptr;
  bool productions_read_new_left_ = false;
  bool productions_read_new_right_ = false;
  bool tracking_births_ = false;
  std::vector<std::uint32_t> births_;  // by module index of string_
  std::vector<Rewrite> rewrites_;      // of the pass running
  ModuleString successor_;  // backward derivation builds each successor here
  ModuleString probe_out_;  // the probing pass's output (kModelProbeProductions): stays empty
  PrependBuffer backward_out_;
  Expansion expansion_;  // of the serial passes
  std::set<std::pair<int, ModuleId>> depth_warnings_;
  int steps_done_ = 0;
  bool ring_ = false;
  bool uses_query_modules_ = false;
  bool sub_lsystems_ = false;
  std::vector<int> lsystems_;
  int view_ = 0;             // the view of the interpretation in progress
  bool has_views_ = false;   // some interpretation rule is in a vgroup
  int passes_running_ = 0;   // rules are being applied: the string must stay
  bool axiom_pending_ = false;    // between start() and make_axiom()
  bool loaded_in_start_ = false;  // replace_string between start() and make_axiom()
  std::optional<ModuleString> initial_string_;
  ModuleString interpretation_out_;
  ReactionSet reactions_;
  std::set<int> warned_groups_;                 // UseGroup numbers already warned about
  ReactionSet* gathering_reactions_ = nullptr;  // set while a Gillespie step runs bodies
  ModuleString reaction_scratch_;               // where those bodies write
  int threads_ = 1;
  std::size_t min_chunk_bytes_ = kMinChunkBytes;
  ChunkOutputPool chunk_outputs_;  // where a parallel pass's chunks write
  bool forward_parallel_ = false;        // no production's body keeps productions serial
  bool decomposition_parallel_ = false;  // nor a decomposition rule's decomposition
  bool keyed_random_ = false;
  std::uint64_t keyed_seed_ = 0;  // of the pass running, in the keyed mode
  static constexpr double kMaxGrowthReserved = 8;
  Growth growth_;
  Growth decomposition_growth_;
};

}  // namespace sylva::derive
