// The syntax tree of the productions translated to GLSL (gpu/lsystem_glsl.h),
// private to src/gpu: the Model IR's rules are parsed into it
// (lsystem_body_parser.h), and it is both written out as GLSL
// (lsystem_glsl_writer.cpp) and interpreted on the CPU (lsystem_interpreter.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gpu/lsystem_glsl.h"

namespace sylva::gpu {

using Type = GpuKind;  // bool, int, float (double), vec2, vec3

inline int width_of(Type t) { return t == Type::kVec3 ? 3 : t == Type::kVec2 ? 2 : 1; }
inline bool is_vector(Type t) { return t == Type::kVec2 || t == Type::kVec3; }
inline bool is_scalar(Type t) { return !is_vector(t); }
inline const char* glsl_type(Type t) {
  switch (t) {
    case Type::kBool: return "bool";
    case Type::kInt: return "int";
    case Type::kFloat: return "float";
    case Type::kVec2: return "vec2";
    case Type::kVec3: return "vec3";
  }
  return "float";
}

struct Value {
  double c[3] = {0, 0, 0};  // bool and int in c[0]
};

struct Expr {
  enum Op {
    kLiteral, kVar, kField, kNeg, kNot, kAdd, kSub, kMul, kDiv, kMod, kScale, kDivScale, kDot, kCross,
    kLess, kLessEqual, kGreater, kGreaterEqual, kEqual, kNotEqual, kAnd, kOr, kTernary, kConvert,
    kCall, kVec2, kVec3, kLength, kNormalized
  } op = kLiteral;
  Type type = Type::kFloat;
  Value literal;
  int slot = -1;       // kVar
  int field = 0;       // kField: 0 x, 1 y, 2 z
  std::string call;    // kCall: the GLSL name
  std::vector<Expr> args;
};

struct Stmt {
  enum Kind { kBlock, kDecl, kAssign, kIf, kProduce, kEmpty } kind = kEmpty;
  std::vector<Stmt> body;  // kBlock; kIf: then (body[0]) and else (body[1], optional)
  int slot = -1;           // kDecl, kAssign
  int field = -1;          // kAssign: -1 the whole variable
  char op = '=';           // kAssign: = + - * /
  std::optional<Expr> expr;  // kDecl's initialiser, kAssign's value, kIf's condition
  int produce = -1;        // kProduce: index into Production::produces
};

struct Produced {
  int type = 0;             // index into LsystemProgram::types
  std::vector<Expr> args;   // converted to the parameters' kinds
};

struct Production {
  int strict = 0;                 // the predecessor's type
  std::vector<int> left, right;   // context types in string order
  // The formals: for each pattern module (left..., strict, right...) the slots of its parameters.
  std::vector<std::vector<int>> formal_slots;
  std::vector<Type> slot_types;
  std::vector<std::string> slot_names;
  Stmt body;
  std::vector<std::vector<Produced>> produces;  // one list of modules per produce statement
};

struct ProductionCode {
  std::vector<Production> productions;
  std::vector<std::vector<int>> by_type;  // productions (in order) by strict predecessor type
};

// The productions as GLSL: a prelude of helpers, a function per production,
// sylva_match and sylva_apply (LsystemProgram::glsl says what they do).
std::string program_glsl(const ProductionCode& code, const std::vector<GpuModuleType>& types);

// `e` evaluated in doubles with the slots of `p` (the production it was
// parsed for) all zero: a top-level constant's value. Throws
// std::runtime_error on an integer division by zero.
Value evaluate(const Production& p, const Expr& e);

}  // namespace sylva::gpu
