// L-systems whose productions give successors of different lengths, derived
// in fragment shaders: algorithm 2 of "Generating subdivision curves with
// L-systems on a GPU" (Lipp, Wonka, Wimmer / Měch and Prusinkiewicz, 2003),
// for the paper's L-systems 3, 4 and 5 (open curves with end points E,
// adaptive subdivision with conditions on parameters) and any L+C model of
// the same kind.
//
// Where algorithm 1 (gpu/stencil_probe.h) probes the compiled production for
// a linear stencil, and so cannot see conditions on values, this translates
// the model's productions themselves (the Model IR of lang/model_ir.h) into
// GLSL and, from the same syntax tree, into an interpreter on the CPU. The
// class (translate_lsystem says why a model is not in it, at the first
// construct outside it, as file:line:column):
//   - an L+C model (not cpfg); production rules only, in group 0, no
//     decomposition, derivative or event rules (interpretation rules are
//     kept by the CPU path only: --gpu writes the string); no control
//     statements (Start, StartEach ...), no ignore:/consider:, no Gillespie
//     groups; `ring L-system:` or an open string;
//   - every module the axiom's string holds, the productions match or
//     produce has parameters of float/double, int/bool (or an enum) and
//     V2f/V2d/V3f/V3d, at most 4 numbers in all (a module is 4 floats on the
//     GPU and its type id); no branches (SB/EB);
//   - each production has a strict predecessor of one module and left and
//     right context of fixed length (no new context << >>), and a body of:
//     local declarations of those types, assignments (= += -= *= /=, also to
//     .x .y .z), if/else, blocks, and `produce`; expressions of literals,
//     formal parameters, locals, top-level constants (`#define` and -D are
//     already substituted by the preprocessor; `const double NAME = value;`
//     at top level is read), arithmetic, comparisons, && || !, ?:, the
//     vectors' operators (+ - scalar * /, v * w the dot product, v % w the
//     cross product), .x .y .z, Length(), Normalized(), Normalize(v),
//     V2d(x, y) / V3d(x, y, z), and the functions fabs abs sqrt min max fmin
//     fmax floor ceil pow exp log sin cos tan atan2;
//   - productions are tried in file order and the first whose context
//     matches and whose body produces applies (a body that ends without
//     producing does not apply, as in the engine); a module no production
//     rewrites is copied.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sylva {
class Simulation;
namespace build {
struct BuildOptions;
}
}  // namespace sylva

namespace sylva::gpu {

// A parameter as the GPU holds it: 1, 1, 1, 2 or 3 of the module's 4 floats.
enum class GpuKind : std::uint8_t { kBool, kInt, kFloat, kVec2, kVec3 };

struct GpuModuleType {
  std::string name;
  std::uint32_t engine_id = 0;
  std::vector<GpuKind> params;
  std::vector<bool> single;  // per parameter: float (or V2f, V3f) rather than double
  int floats = 0;            // numbers in all, at most 4, in parameter order
};

// A string: module i is types[i] (an index into LsystemProgram::types) with
// params[4i .. 4i+3] (its numbers in order, the rest 0).
struct GpuString {
  std::vector<std::int32_t> types;
  std::vector<double> params;
  std::size_t size() const { return types.size(); }
};

struct ProductionCode;  // the syntax trees, for the CPU (lsystem_tree.h)

struct LsystemProgram {
  std::vector<GpuModuleType> types;
  bool ring = false;
  int productions = 0;
  // The productions as GLSL (after the prelude a pass supplies, which defines
  //   bool sylva_module(int i, out int type, out vec4 params)
  // false for a position past the ends of an open string, modules wrapped
  // round a ring): functions
  //   int sylva_match(int i, out int length)   the production rewriting
  //       module i (-1: none, the module is copied) and its successor's length;
  //   void sylva_apply(int p, int i, int want, out int type, out vec4 params)
  //       module `want` of production p's successor of module i.
  std::string glsl;
  std::shared_ptr<const ProductionCode> code;
};

struct LsystemTranslation {
  bool in_class = false;
  std::string reason;  // why not: "file:line:column: what" where there is a place
  LsystemProgram program;
  GpuString axiom;  // the string after the axiom (and Start)
};

// Translates the model `simulation` runs (built with `build`: its -D
// definitions and compiler), and reads the string after its axiom. Leaves
// the simulation begun (at step 0).
LsystemTranslation translate_lsystem(Simulation& simulation, const build::BuildOptions& build);

// The string's text as the engine writes it: modules separated by spaces,
// Name(p1,p2,...), vectors (x,y). `as_float`: floating-point numbers written
// as the shortest text of the float nearest them (the GPU's precision).
std::string format_gpu_string(const LsystemProgram& program, const GpuString& string, bool as_float);

class LsystemDeriver {
 public:
  virtual ~LsystemDeriver() = default;
  // The string after `steps` steps of `program` from `string`.
  virtual GpuString derive(const LsystemProgram& program, const GpuString& string, int steps) = 0;
  virtual std::string name() const = 0;
};

// The productions' syntax trees interpreted in doubles, on the CPU: the check
// of the translation (equal to the engine to rounding for double parameters).
class CpuLsystemDeriver : public LsystemDeriver {
 public:
  GpuString derive(const LsystemProgram& program, const GpuString& string, int steps) override;
  std::string name() const override { return "cpu"; }
};

// The GPU one (render/gl_lsystem.cpp, in libsylva_gl.so): per step, fragment
// program 1 finds each module's production and successor length, a scan-add
// (Hillis-Steele, `radix` values summed per pass: ⌈log_radix n⌉ passes) gives
// each successor's place, only the total is read back, and fragment program 3
// makes each output module, finding its predecessor by binary search in the
// sums. Strings lie in textures of at most `row_width` texels a row (0: as
// wide as OpenGL allows).
class GlLsystemDeriver : public LsystemDeriver {
 public:
  virtual void set_layout(int row_width, int radix) = 0;
  // The scan-add pass alone: exclusive prefix sums of `lengths` (y[0] = 0,
  // y[i] = lengths[0] + ... + lengths[i-1]), computed as derive computes them.
  virtual std::vector<std::int64_t> scan_add(const std::vector<std::int32_t>& lengths) = 0;
};

// Opens libsylva_gl.so on first use; throws ModelError if it or its OpenGL
// context cannot be had.
GlLsystemDeriver& gl_lsystem_deriver();

}  // namespace sylva::gpu

// The GL plugin's factory.
extern "C" __attribute__((visibility("default"))) sylva::gpu::GlLsystemDeriver* sylva_gl_lsystem_deriver();
