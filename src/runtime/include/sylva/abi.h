// The binary interface between the engine and a compiled model.
//
// A compiled model is a shared library exporting one C function,
// `sylva_model_v1`, that returns a ModelDescriptor: its module types (with
// their parameters' types and offsets), its rules with their patterns and
// body functions, and its control statements. The engine owns the strings;
// the model only reads parameter blocks and appends modules to a ModuleBuffer. Everything here is plain data so the
// header stays cheap to compile into every model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace sylva::abi {

inline constexpr std::uint32_t kAbiVersion = 16;

using ModuleId = std::uint16_t;

// A module with parameters is stored as [id][parameters][id], one without as
// [id]. Either way a module begins and ends with its id, so the string can be
// walked backward as well as forward with nothing but the encoded size of
// each id. Parameters are packed in declaration order without padding and
// read with memcpy.
//
// An id below kWideId (nearly every model's every id: the predefined modules
// and about the first 150 of the model's own) is one byte, so a parameterless
// module takes one byte, as a symbol does in cpfg. A wider id is kWideId and
// the id's two bytes at the start, the two bytes and kWideId at the end; a
// parameterless module with a wide id is [kWideId][id][kWideId]. The byte at
// either end of a module thus tells whether its id is wide.
inline constexpr unsigned char kWideId = 0xFF;

// Bytes the id takes at each end of a module with parameters (the parameters
// begin that far in).
inline constexpr std::size_t encoded_id_size(ModuleId id) { return id < kWideId ? 1 : 3; }

inline constexpr std::size_t encoded_module_size(ModuleId id, std::size_t param_size) {
  if (id < kWideId) return param_size ? param_size + 2 : 1;
  return param_size ? param_size + 6 : 4;
}

// The most bytes a module with `param_size` bytes of parameters can take.
inline constexpr std::size_t largest_module_size(std::size_t param_size) {
  return encoded_module_size(kWideId, param_size);
}

// The id of the module starting at `at`, and of the one ending at `end`.
inline ModuleId leading_id(const unsigned char* at) {
  if (__builtin_expect(at[0] != kWideId, 1)) return at[0];
  ModuleId id;
  std::memcpy(&id, at + 1, sizeof id);
  return id;
}
inline ModuleId trailing_id(const unsigned char* end) {
  if (__builtin_expect(end[-1] != kWideId, 1)) return end[-1];
  ModuleId id;
  std::memcpy(&id, end - 3, sizeof id);
  return id;
}

// Writes a module's first id, its last id (after its parameters), or the
// whole of a module without parameters, at `at`, and advances `at`.
inline void put_leading_id(unsigned char*& at, ModuleId id) {
  if (id < kWideId) {
    *at++ = static_cast<unsigned char>(id);
    return;
  }
  at[0] = kWideId;
  std::memcpy(at + 1, &id, sizeof id);
  at += 3;
}
inline void put_trailing_id(unsigned char*& at, ModuleId id) {
  if (id < kWideId) {
    *at++ = static_cast<unsigned char>(id);
    return;
  }
  std::memcpy(at, &id, sizeof id);
  at[2] = kWideId;
  at += 3;
}
inline void put_parameterless(unsigned char*& at, ModuleId id) {
  put_leading_id(at, id);
  if (id >= kWideId) *at++ = kWideId;
}
// A whole module: `param_size` bytes of parameters framed by its id, or its
// id alone without them.
inline void put_encoded_module(unsigned char*& at, ModuleId id, const void* params, std::size_t param_size) {
  if (!param_size) return put_parameterless(at, id);
  put_leading_id(at, id);
  std::memcpy(at, params, param_size);
  at += param_size;
  put_trailing_id(at, id);
}

// A growable byte buffer of encoded modules. The engine allocates it and
// supplies `grow`, so a model never calls an allocator of its own.
struct ModuleBuffer {
  unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t capacity = 0;
  void (*grow)(ModuleBuffer* self, std::size_t min_capacity) = nullptr;

  void reserve_more(std::size_t bytes) {
    if (size + bytes > capacity) grow(this, size + bytes);
  }
};

// Text sink used by the per-module parameter formatters.
struct TextSink {
  void* self;
  void (*append)(void* self, const char* text, std::size_t length);
  void write(const char* text, std::size_t length) { append(self, text, length); }
  void write(const char* text) { append(self, text, std::strlen(text)); }
};

// Text being read back into parameters (a saved string). The text ends with
// a NUL at or after `end`, so number parsers may stop on their own.
struct TextSource {
  const char* at;   // advanced past what was read; on failure, where it went wrong
  const char* end;
  const char* expected = nullptr;  // on failure: what was expected there
};

// What a parameter is: a module's parameter, a struct's field, a vector's
// coordinate or an array's element.
enum class ParamKind : std::uint8_t {
  kFloat,
  kDouble,
  kLongDouble,
  kBool,
  kSigned,    // a signed integer (char, short, int, long ...)
  kUnsigned,  // an unsigned integer
  kEnum,      // `element` is its underlying integer type
  kVector,    // V2f ... V3d: `count` coordinates of type `element`
  kArray,     // `count` elements of type `element`, `element->size` bytes apart
  kStruct,    // `fields` are those the model's source lists (none: its layout is unknown)
  kText,      // a pointer to a NUL-terminated string (a label's text)
  kOther,     // anything else (other pointers, unions ...): only bytes
};

struct ParamField;

struct ParamType {
  ParamKind kind;
  std::uint32_t size;
  const ParamType* element = nullptr;
  std::uint32_t count = 0;
  const ParamField* fields = nullptr;
  std::uint32_t field_count = 0;
  const char* name = nullptr;  // a struct's name, where its fields are listed
};

// A module's parameter (unnamed, at its offset in the parameter block) or a
// struct's field (at its offset in the struct). `type` is null for a field
// whose place is not known (a bit-field, a reference).
struct ParamField {
  const char* name;
  std::uint32_t offset;
  const ParamType* type;
};

struct ModuleType {
  const char* name;
  std::uint32_t param_size;
  // The saved-string text of the parameters, "p1,p2,..." without
  // parentheses (null for a predefined module: the engine has its own).
  void (*format_params)(const unsigned char* params, TextSink* out);
  std::uint32_t param_count;
  // Reads back what format_params wrote: `param_count` values separated by
  // commas into `params`, stopping before the closing parenthesis; false
  // (with `in->expected` set) on bad text. Null: the engine reads them from
  // `params`' table where it writes them from it, and they cannot be read
  // back otherwise.
  bool (*parse_params)(TextSource* in, unsigned char* params);
  // The parameters' types and offsets, `param_count` of them (null for a
  // predefined module: the engine has its own).
  const ParamField* params;
};

// Derivative and Event rules belong to differential L-systems
// (docs/continuous-time.md): a Derivative rule gives the rates of change of
// its module's parameters, an Event rule the production applied at the
// instant its condition becomes true.
enum class RuleKind : std::uint8_t { Production = 0, Decomposition = 1, Interpretation = 2, Derivative = 3, Event = 4 };
inline constexpr int kRuleKinds = 5;

// Pattern parts in the order the engine hands their parameters to a body.
enum PatternPart : int { kNewLeft = 0, kLeft, kStrict, kRight, kNewRight, kPatternParts };

// What a body sees of the derivation while it runs.
struct RuleCall {
  ModuleBuffer* out;   // the successor is appended here
  bool produced;       // set by `produce`
  // In a step using a Gillespie group (LPFG manual 7.2) a body offers
  // reactions instead of producing. `propensity p produce S;` appends S to
  // `out`, calls propose, and removes S again; the engine takes as the
  // reaction's successor what `out` held since the body began (nproduce'd
  // modules, then S). Null outside such a step.
  void* reactions = nullptr;
  void (*propose)(RuleCall* call, double propensity) = nullptr;
  // InLeftContext(...) and its kin (LPFG manual 3.3) ask here whether the n
  // modules of `pattern` (a PatternPart: kLeft, kRight, kNewLeft or
  // kNewRight) follow in the context; on success params[k] points at the
  // parameters of the module matched by pattern[k]. Null: every test is false.
  void* context = nullptr;
  bool (*in_context)(void* context, int part, const ModuleId* pattern, int n, const unsigned char** params) = nullptr;
  // A Derivative rule writes d(p) of its module's parameter p at rates[p]
  // (by parameter index); the engine zeroes them first.
  double* rates = nullptr;
  // An Event rule sets whether its condition holds and its margin: a number
  // that is >= 0 where the condition holds and crosses zero where it starts
  // to (x - xmax for `x >= xmax`), so the engine can locate the instant.
  // With event_probe set the body stops there and produces nothing.
  bool event_probe = false;
  bool event_holds = false;
  double event_margin = 0;
};

struct Rule {
  RuleKind kind;
  int group;
  int filter;  // index into ModelDescriptor::filters, or -1: every module counts
  const ModuleId* pattern;  // all parts concatenated in PatternPart order
  std::uint16_t part_length[kPatternParts];
  // params[i] points at the parameter block of the i-th pattern module.
  void (*body)(RuleCall* call, const unsigned char* const* params);
  const char* file;
  int line;
  // The vgroup (LPFG manual 7.3) of an interpretation rule; 0 outside any
  // vgroup. Drawing view v uses vgroup v, then vgroup 0.
  int view;
};

// An ignore: or consider: statement in force for some rules.
struct ContextFilter {
  bool consider;  // true: only `ids` count; false: `ids` are skipped
  const ModuleId* ids;
  std::uint32_t count;
};

// State shared by the model's predefined functions (Forward(), StepNo(), ran()
// ...) and the engine. It lives in the model; the engine reads and writes it.
struct ControlState {
  bool forward = true;
  bool stop_requested = false;
  int step = 0;
  int current_group = 0;
  int next_group = 0;
  // ran()'s generator (erand48's 48-bit state): drand48's state before any
  // srand48 call; an lpfg model starts from kLpfgRandomState instead.
  std::uint64_t rand48 = 0x1234ABCD330EULL;
  // Messages (Printf, warnings) go through the engine.
  void* host = nullptr;
  void (*message)(void* host, const char* text) = nullptr;
  // Functions, curves and surfaces from the input files (LPFG manual 6.2),
  // answered by the engine: `query` is an InputQuery, `in` and `out` its
  // arguments and results. Null when the model runs without input files.
  void* inputs = nullptr;
  bool (*input_query)(void* inputs, int query, int id, const double* in, double* out) = nullptr;
  // What a model asks the engine to do (a ModelRequest) with a view number
  // or a file name; null: nothing is done.
  void* requests = nullptr;
  void (*request)(void* requests, int request, int value, const char* file) = nullptr;
  // Gillespie groups: the state of their own random generator (erand48's,
  // as rand48; SeedGillespie sets it, ran() does not touch it) and the time
  // of the Gillespie steps so far (GillespieTime: the sum of the times to
  // each reaction, as lpfg keeps it).
  std::uint64_t gillespie_random = 0;
  double gillespie_time = 0;
  // Environment() / NoEnvironment() (LPFG manual 6.1.3): whether the
  // environmental pass follows the current step.
  bool environment = true;
  // Where the UseGroup call that set next_group is (the model's file and
  // line), so a group the model lacks can be reported there.
  const char* group_call_file = nullptr;
  int group_call_line = 0;
  // The time of a continuous run (Time() in a model): where the equations
  // are evaluated, or the instant an event fires.
  double time = 0;
  // A cpfg model's stochastic productions are chosen from its seed: as
  // cpfg's window seeds drand48 (seed48({seed, 0, 155})); false: as cpfg's
  // batch runs (-g), which never seed it (state 0).
  bool cpfg_window_seeding = false;
  // Set by the engine in the keyed random mode: ran() draws from here, a
  // generator keyed by the step's seed, the step, the module's place in the
  // old string and the draw, rather than from rand48; so a stochastic model
  // derives the same string whichever bodies run first. Null: rand48.
  double (*keyed_random)(void* host) = nullptr;
  // A run's seed (`sylva run --seed`, an experiment's replicate): the
  // generators start from it (as sran(seed) and SeedGillespie(seed) would
  // set them; a cpfg model's as seed: and srand(seed) would), and the
  // model's own sran, SeedGillespie, srand and seed: are passed over, so
  // that replicates differ even where a model seeds itself.
  bool seed_fixed = false;
  long seed = 0;
};

// The state lpfg gives both of its generators when it loads a model (erand48
// words {0x330E, 0, 0}); ran() and Gillespie steps draw from it until seeded.
inline constexpr std::uint64_t kLpfgRandomState = 0x330E;

// One step of erand48's 48-bit generator on `state`, and the number in [0,1)
// it gives: the engine's Gillespie steps and the models' ran() and cpfg's
// streams all draw with it.
inline double next_erand48(std::uint64_t& state) {
  state = (0x5DEECE66DULL * state + 0xB) & ((1ULL << 48) - 1);
  return static_cast<double>(state) * (1.0 / 281474976710656.0);  // 2^-48
}

// What ControlState::request is asked (LPFG manual 6.1, 6.4, 6.6).
enum ModelRequest : int {
  kRequestOutputString = 0,  // file: write the current string now
  kRequestLoadString,        // file: replace the current string now
  kRequestOutputFrame,       // file: write an image at the end of the step
  kRequestDisplayFrame,      // an animation frame of the current step
  kRequestUseView,           // value: a view to draw
};

// What ControlState::input_query is asked.
enum InputQuery : int {
  // lpfg's functions (func; tfunc and funcTangent through the function's
  // limits, which pfunc sets), all in float as lpfg computes them.
  kQueryFunction = 0,       // in: x                  out: y
  kQueryFunctionTangent,    // in: x                  out: dx, dy
  kQueryCurvePoint,         // in: s                  out: x, y, z
  kQueryCurveNormal,        // in: s                  out: x, y, z
  kQuerySurfacePatch,       // in: -                  out: 48 numbers (16 control points)
  kQueryCurveLength,        // in: -                  out: length
  // Changing a curve (LPFG manual 6.2.3); the turtle draws the changed curve.
  kQueryCurveScale,         // in: x, y, z            out: -
  kQueryCurveSetPoint,      // in: p, x, y, z         out: -
  kQueryCurveRecalculate,   // in: -                  out: -
  kQueryCurveReset,         // in: -                  out: -
  kQueryParameter,          // in: -                  out: value (val, LPFG manual 6.2.1)
  kQueryTimelineFunction,   // in: x                  out: y (tfunc: x mapped from the limits to [0,1])
  kQueryFunctionLimits,     // in: min, max           out: - (pfunc sets them, for good)
  kQueryCpfgFunction,       // in: x                  out: y (cpfg's func, in double)
  kQuerySurfacePoint,       // in: point              out: x, y, z (point 16p + k: patch p's k-th)
  // cpfg's vvXmin() ... vvScale() as a batch run has them: no window, so the
  // x and y extents are 0; the view file's front and back distance and scale.
  kQueryCpfgViewVolume,     // in: -                  out: xmin, xmax, ymin, ymax, zmin, zmax, scale
};

struct ModelDescriptor {
  std::uint32_t abi_version;
  const char* source_file;
  const ModuleType* modules;
  std::uint32_t module_count;
  std::uint32_t predefined_count;
  const Rule* rules;
  std::uint32_t rule_count;
  const ContextFilter* filters;
  std::uint32_t filter_count;
  ControlState* control;
  void (*axiom)(ModuleBuffer* out);
  int (*derivation_length)();
  int (*decomposition_depth)();   // null: the default depth, 1
  // null: the default depth, 1. Called once at the start of every
  // interpretation pass (cpfg models restart a homomorphism's own random
  // stream there).
  int (*interpretation_depth)();
  int (*ring)();                  // null: not a ring L-system
  void (*start)();
  void (*start_each)();
  void (*end_each)();
  void (*end)();
  std::uint32_t flags;  // kModelCpfg ...
  // Called by a forward derivation step for every module of the old string
  // before its productions are tried (cpfg's stochastic draw); may be null.
  // With kModelProbeProductions, a module's productions are tried twice: a
  // probing pass, in which the rules that apply say so to the model and
  // produce nothing, then before_module(kNoModule) and the real pass.
  // For sub-L-system models, ControlState::current_group holds the label of
  // the module's L-system during the call.
  void (*before_module)(ModuleId id);
  // cpfg's sub-L-systems (CPFG manual 7.2), when flags has
  // kModelSubLsystems. Rule::group is then the label of the L-system a rule
  // belongs to; `?(label,s)` (call_module) hands the modules
  // after it to L-system `label` until its `$` (return_module), and a module
  // is rewritten only by its own L-system's rules (no fallback to another).
  int main_lsystem;              // the label of the first L-system
  const int* lsystem_labels;     // every L-system's label
  std::uint32_t lsystem_count;
  ModuleId call_module;          // ?(label,s); kNoModule if the model has none
  ModuleId return_module;        // $ without parameters; kNoModule if none
  // VerifyString: (LPFG manual 10.4), the module names the derived string
  // must have; verify_length is -1 without one.
  const ModuleId* verify_string;
  std::int32_t verify_length;
  // The numbers of the Gillespie groups (ggroup N:, LPFG manual 7.2); a step
  // whose group is one of them fires one reaction.
  const int* gillespie_groups;
  std::uint32_t gillespie_group_count;
  // The numbers of the groups the model defines (group N:, ggroup N:; 0
  // always exists), which UseGroup may select.
  const int* groups;
  std::uint32_t group_count;
  // Per rule (rule_count of each), from the translator's analysis of its
  // body: whether it may run at the same time as other bodies of its pass
  // (a RuleParallel), and if not, why ("assigns `n`, which is not its own").
  const std::uint8_t* rule_parallel;
  const char* const* rule_serial_reasons;  // null where the rule is parallel
};

// ModelDescriptor::rule_parallel
enum RuleParallel : std::uint8_t {
  kRuleSerial = 0,
  kRuleParallel = 1,
  kRuleParallelIfKeyed = 2,  // it calls ran(): parallel where ran() is keyed (ControlState::keyed_random)
};

inline constexpr ModuleId kNoModule = 0xFFFF;

// ModelDescriptor::flags
inline constexpr std::uint32_t kModelCpfg = 1;  // a cpfg model: cpfg's string format and derivation
inline constexpr std::uint32_t kModelSubLsystems = 2;  // cpfg sub-L-systems: see main_lsystem
// cpfg's stochastic choice among the productions that apply: see before_module.
inline constexpr std::uint32_t kModelProbeProductions = 4;

using ModelEntryPoint = const ModelDescriptor* (*)();
inline constexpr const char* kEntryPointName = "sylva_model_v1";

}  // namespace sylva::abi
