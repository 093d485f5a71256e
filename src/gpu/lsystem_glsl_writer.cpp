// The productions' syntax trees (gpu/lsystem_tree.h) written as GLSL: a
// function per production, and the sylva_match and sylva_apply that
// render/gl_lsystem.cpp's fragment programs call.
#include <charconv>
#include <string>
#include <utility>
#include <vector>

#include "gpu/lsystem_tree.h"

namespace sylva::gpu {
namespace {

std::string glsl_number(double v, Type t) {
  char buffer[64];
  if (t == Type::kBool) return v != 0 ? "true" : "false";
  if (t == Type::kInt) {
    auto r = std::to_chars(buffer, buffer + sizeof buffer, static_cast<long long>(v));
    std::string s(buffer, r.ptr);
    return v < 0 ? "(" + s + ")" : s;
  }
  auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  std::string s(buffer, r.ptr);
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return v < 0 ? "(" + s + ")" : s;
}

class GlslWriter {
 public:
  explicit GlslWriter(const Production& p) : p_(p) {}

  // Unique per slot; no "__" (reserved in GLSL).
  std::string name(int slot) const {
    std::string n = "s" + std::to_string(slot) + "_";
    for (char c : p_.slot_names[static_cast<std::size_t>(slot)])
      if (c != '_') n += c;
    return n;
  }

  std::string expr(const Expr& e) const {
    auto a = [&](int i) { return expr(e.args[static_cast<std::size_t>(i)]); };
    switch (e.op) {
      case Expr::kLiteral:
        if (e.type == Type::kVec2) return "vec2(" + glsl_number(e.literal.c[0], Type::kFloat) + ", " + glsl_number(e.literal.c[1], Type::kFloat) + ")";
        if (e.type == Type::kVec3)
          return "vec3(" + glsl_number(e.literal.c[0], Type::kFloat) + ", " + glsl_number(e.literal.c[1], Type::kFloat) +
                 ", " + glsl_number(e.literal.c[2], Type::kFloat) + ")";
        return glsl_number(e.literal.c[0], e.type);
      case Expr::kVar: return name(e.slot);
      case Expr::kField: return "(" + a(0) + ")." + "xyz"[e.field];
      case Expr::kNeg: return "(-" + a(0) + ")";
      case Expr::kNot: return "(!" + a(0) + ")";
      case Expr::kAdd: return "(" + a(0) + " + " + a(1) + ")";
      case Expr::kSub: return "(" + a(0) + " - " + a(1) + ")";
      case Expr::kMul: case Expr::kScale: return "(" + a(0) + " * " + a(1) + ")";
      case Expr::kDiv:
        if (e.type == Type::kInt) return "sylva_div(" + a(0) + ", " + a(1) + ")";
        return "(" + a(0) + " / " + a(1) + ")";
      case Expr::kDivScale: return "(" + a(0) + " / " + a(1) + ")";
      case Expr::kMod: return "sylva_mod(" + a(0) + ", " + a(1) + ")";
      case Expr::kDot: return "dot(" + a(0) + ", " + a(1) + ")";
      case Expr::kCross: return "cross(" + a(0) + ", " + a(1) + ")";
      case Expr::kLess: return "(" + a(0) + " < " + a(1) + ")";
      case Expr::kLessEqual: return "(" + a(0) + " <= " + a(1) + ")";
      case Expr::kGreater: return "(" + a(0) + " > " + a(1) + ")";
      case Expr::kGreaterEqual: return "(" + a(0) + " >= " + a(1) + ")";
      case Expr::kEqual: return "(" + a(0) + " == " + a(1) + ")";
      case Expr::kNotEqual: return "(" + a(0) + " != " + a(1) + ")";
      case Expr::kAnd: return "(" + a(0) + " && " + a(1) + ")";
      case Expr::kOr: return "(" + a(0) + " || " + a(1) + ")";
      case Expr::kTernary: return "(" + a(0) + " ? " + a(1) + " : " + a(2) + ")";
      case Expr::kConvert: {
        const Type from = e.args[0].type;
        if (e.type == Type::kVec3) return "vec3(" + a(0) + ", 0.0)";
        if (e.type == Type::kBool) return "(" + a(0) + (from == Type::kFloat ? " != 0.0)" : " != 0)");
        return std::string(glsl_type(e.type)) + "(" + a(0) + ")";
      }
      case Expr::kCall: {
        std::string s = e.call + "(" + a(0);
        if (e.args.size() > 1) s += ", " + a(1);
        return s + ")";
      }
      case Expr::kVec2: return "vec2(" + a(0) + ", " + a(1) + ")";
      case Expr::kVec3: return "vec3(" + a(0) + ", " + a(1) + ", " + a(2) + ")";
      case Expr::kLength: return "length(" + a(0) + ")";
      case Expr::kNormalized: return "sylva_normalized(" + a(0) + ")";
    }
    return "0";
  }

  void stmt(const Stmt& s, std::string& out, int indent) const {
    const std::string pad(static_cast<std::size_t>(indent), ' ');
    switch (s.kind) {
      case Stmt::kEmpty: return;
      case Stmt::kBlock:
        if (s.slot == -2) {
          for (const Stmt& t : s.body) stmt(t, out, indent);
          return;
        }
        out += pad + "{\n";
        for (const Stmt& t : s.body) stmt(t, out, indent + 2);
        out += pad + "}\n";
        return;
      case Stmt::kDecl:
        out += pad + glsl_type(p_.slot_types[static_cast<std::size_t>(s.slot)]) + " " + name(s.slot) + " = " + expr(*s.expr) + ";\n";
        return;
      case Stmt::kAssign:
        out += pad + name(s.slot) + (s.field >= 0 ? std::string(".") + "xyz"[s.field] : "") + " = " + expr(*s.expr) + ";\n";
        return;
      case Stmt::kIf:
        out += pad + "if (" + expr(*s.expr) + ") {\n";
        stmt(s.body[0], out, indent + 2);
        out += pad + "}";
        if (s.body.size() > 1) {
          out += " else {\n";
          stmt(s.body[1], out, indent + 2);
          out += pad + "}";
        }
        out += "\n";
        return;
      case Stmt::kProduce: {
        const auto& modules = p_.produces[static_cast<std::size_t>(s.produce)];
        out += pad + "{\n";
        for (std::size_t m = 0; m < modules.size(); ++m) {
          out += pad + "  if (want == " + std::to_string(m) + ") {\n";
          out += pad + "    sylva_type = " + std::to_string(modules[m].type) + ";\n";
          out += pad + "    sylva_params = " + pack(modules[m]) + ";\n";
          out += pad + "  }\n";
        }
        out += pad + "  return " + std::to_string(modules.size()) + ";\n";
        out += pad + "}\n";
        return;
      }
    }
  }

  std::string pack(const Produced& m) const {
    std::vector<std::string> parts;
    int floats = 0;
    for (const Expr& a : m.args) {
      const std::string v = expr(a);
      switch (a.type) {
        case Type::kBool: parts.push_back("(" + v + " ? 1.0 : 0.0)"); floats += 1; break;
        case Type::kInt: parts.push_back("float(" + v + ")"); floats += 1; break;
        case Type::kFloat: parts.push_back(v); floats += 1; break;
        case Type::kVec2: parts.push_back(v); floats += 2; break;
        case Type::kVec3: parts.push_back(v); floats += 3; break;
      }
    }
    for (; floats < 4; ++floats) parts.push_back("0.0");
    std::string s = "vec4(";
    for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
    return s + ")";
  }

 private:
  const Production& p_;
};

// Reading parameter `k` of a module's vec4 `q` of type `type`.
std::string unpack(const GpuModuleType& type, std::size_t k, const std::string& q) {
  int first = 0;
  for (std::size_t j = 0; j < k; ++j) first += width_of(type.params[j]);
  const char* c = "xyzw";
  switch (type.params[k]) {
    case Type::kBool: return "(" + q + "." + c[first] + " != 0.0)";
    case Type::kInt: return "int(" + q + "." + c[first] + ")";
    case Type::kFloat: return q + "." + c[first];
    case Type::kVec2: return q + "." + c[first] + c[first + 1];
    case Type::kVec3: return q + "." + c[first] + c[first + 1] + c[first + 2];
  }
  return "0.0";
}

std::string production_glsl(const Production& p, int index, const std::vector<GpuModuleType>& types) {
  GlslWriter w(p);
  std::string out = "int sylva_production_" + std::to_string(index) +
                    "(int i, int want, out int sylva_type, out vec4 sylva_params) {\n"
                    "  int t; vec4 q;\n";
  const int l = static_cast<int>(p.left.size());
  std::vector<std::pair<int, int>> modules;  // offset, type
  for (int k = 0; k < l; ++k) modules.emplace_back(k - l, p.left[static_cast<std::size_t>(k)]);
  modules.emplace_back(0, p.strict);
  for (std::size_t k = 0; k < p.right.size(); ++k) modules.emplace_back(static_cast<int>(k) + 1, p.right[k]);
  // Context first (all of it matches before the formals are read).
  for (std::size_t m = 0; m < modules.size(); ++m) {
    const auto [offset, type] = modules[m];
    if (offset == 0) continue;
    out += "  if (!sylva_module(i + (" + std::to_string(offset) + "), t, q) || t != " + std::to_string(type) +
           ") return -1;\n";
  }
  for (std::size_t m = 0; m < modules.size(); ++m) {
    const auto [offset, type] = modules[m];
    const auto& slots = p.formal_slots[m];
    if (slots.empty()) continue;
    out += "  sylva_module(i + (" + std::to_string(offset) + "), t, q);\n";
    for (std::size_t k = 0; k < slots.size(); ++k)
      out += "  " + std::string(glsl_type(p.slot_types[static_cast<std::size_t>(slots[k])])) + " " + w.name(slots[k]) +
             " = " + unpack(types[static_cast<std::size_t>(type)], k, "q") + ";\n";
  }
  w.stmt(p.body, out, 2);
  out += "  return -1;\n}\n";
  return out;
}

}  // namespace

std::string program_glsl(const ProductionCode& code, const std::vector<GpuModuleType>& types) {
  std::string out =
      // C++'s integer / and % (truncating); GLSL leaves them undefined for negative operands.
      "int sylva_div(int a, int b) { int q = abs(a) / abs(b); return (a < 0) != (b < 0) ? -q : q; }\n"
      "int sylva_mod(int a, int b) { int r = abs(a) % abs(b); return a < 0 ? -r : r; }\n"
      "vec2 sylva_normalized(vec2 v) { return v / length(v); }\n"
      "vec3 sylva_normalized(vec3 v) { return v / length(v); }\n";
  for (std::size_t p = 0; p < code.productions.size(); ++p)
    out += production_glsl(code.productions[p], static_cast<int>(p), types);
  out += "int sylva_match(int i, out int len) {\n  int t; vec4 q; int ot; vec4 op; int r;\n"
         "  sylva_module(i, t, q);\n";
  for (std::size_t p = 0; p < code.productions.size(); ++p) {
    const std::string n = std::to_string(p);
    out += "  if (t == " + std::to_string(code.productions[p].strict) + ") { r = sylva_production_" + n +
           "(i, -1, ot, op); if (r >= 0) { len = r; return " + n + "; } }\n";
  }
  out += "  len = 1;\n  return -1;\n}\n";
  out += "void sylva_apply(int p, int i, int want, out int type, out vec4 params) {\n";
  for (std::size_t p = 0; p < code.productions.size(); ++p)
    out += "  if (p == " + std::to_string(p) + ") { sylva_production_" + std::to_string(p) +
           "(i, want, type, params); return; }\n";
  out += "  sylva_module(i, type, params);\n}\n";
  return out;
}

}  // namespace sylva::gpu
