// The productions' syntax trees (gpu/lsystem_tree.h) interpreted in doubles
// on the CPU: CpuLsystemDeriver, the check of the translation, and the values
// of the model's top-level constants.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gpu/lsystem_tree.h"

namespace sylva::gpu {
namespace {

class Interpreter {
 public:
  explicit Interpreter(const Production& p) : slots_(p.slot_types.size()) {}

  Value eval(const Expr& e) {
    Value r;
    auto arg = [&](int i) { return eval(e.args[static_cast<std::size_t>(i)]); };
    const int w = width_of(e.type);
    switch (e.op) {
      case Expr::kLiteral: return e.literal;
      case Expr::kVar: return slots_[static_cast<std::size_t>(e.slot)];
      case Expr::kField: r.c[0] = arg(0).c[e.field]; return r;
      case Expr::kNeg: {
        Value a = arg(0);
        for (int i = 0; i < w; ++i) r.c[i] = -a.c[i];
        return r;
      }
      case Expr::kNot: r.c[0] = arg(0).c[0] == 0; return r;
      case Expr::kAdd: case Expr::kSub: {
        Value a = arg(0), b = arg(1);
        for (int i = 0; i < w; ++i) r.c[i] = e.op == Expr::kAdd ? a.c[i] + b.c[i] : a.c[i] - b.c[i];
        if (e.type == Type::kInt) r.c[0] = wrap_int(r.c[0]);
        return r;
      }
      case Expr::kMul: {
        r.c[0] = arg(0).c[0] * arg(1).c[0];
        if (e.type == Type::kInt) r.c[0] = wrap_int(r.c[0]);
        return r;
      }
      case Expr::kDiv: {
        const double a = arg(0).c[0], b = arg(1).c[0];
        if (e.type == Type::kInt) {
          if (b == 0) throw std::runtime_error("an integer division by zero");
          r.c[0] = static_cast<double>(static_cast<long long>(a) / static_cast<long long>(b));
        } else {
          r.c[0] = a / b;
        }
        return r;
      }
      case Expr::kMod: {
        const long long b = static_cast<long long>(arg(1).c[0]);
        if (b == 0) throw std::runtime_error("an integer remainder by zero");
        r.c[0] = static_cast<double>(static_cast<long long>(arg(0).c[0]) % b);
        return r;
      }
      case Expr::kScale: case Expr::kDivScale: {
        Value a = arg(0);
        const double k = arg(1).c[0];
        for (int i = 0; i < w; ++i) r.c[i] = e.op == Expr::kScale ? a.c[i] * k : a.c[i] / k;
        return r;
      }
      case Expr::kDot: {
        Value a = arg(0), b = arg(1);
        const int n = width_of(e.args[0].type);
        for (int i = 0; i < n; ++i) r.c[0] += a.c[i] * b.c[i];
        return r;
      }
      case Expr::kCross: {
        Value a = arg(0), b = arg(1);
        r.c[0] = a.c[1] * b.c[2] - a.c[2] * b.c[1];
        r.c[1] = a.c[2] * b.c[0] - a.c[0] * b.c[2];
        r.c[2] = a.c[0] * b.c[1] - a.c[1] * b.c[0];
        return r;
      }
      case Expr::kLess: r.c[0] = arg(0).c[0] < arg(1).c[0]; return r;
      case Expr::kLessEqual: r.c[0] = arg(0).c[0] <= arg(1).c[0]; return r;
      case Expr::kGreater: r.c[0] = arg(0).c[0] > arg(1).c[0]; return r;
      case Expr::kGreaterEqual: r.c[0] = arg(0).c[0] >= arg(1).c[0]; return r;
      case Expr::kEqual: r.c[0] = arg(0).c[0] == arg(1).c[0]; return r;
      case Expr::kNotEqual: r.c[0] = arg(0).c[0] != arg(1).c[0]; return r;
      case Expr::kAnd: r.c[0] = arg(0).c[0] != 0 && arg(1).c[0] != 0; return r;
      case Expr::kOr: r.c[0] = arg(0).c[0] != 0 || arg(1).c[0] != 0; return r;
      case Expr::kTernary: return arg(0).c[0] != 0 ? arg(1) : arg(2);
      case Expr::kConvert: {
        Value a = arg(0);
        const Type from = e.args[0].type;
        if (e.type == Type::kVec3 && from == Type::kVec2) return Value{{a.c[0], a.c[1], 0}};
        if (e.type == Type::kBool) r.c[0] = a.c[0] != 0;
        else if (e.type == Type::kInt) r.c[0] = wrap_int(std::trunc(a.c[0]));
        else r.c[0] = a.c[0];
        return r;
      }
      case Expr::kCall: {
        const double a = arg(0).c[0];
        const std::string& f = e.call;
        const double b = e.args.size() > 1 ? arg(1).c[0] : 0;
        if (f == "abs") r.c[0] = std::abs(a);
        else if (f == "sqrt") r.c[0] = std::sqrt(a);
        else if (f == "min") r.c[0] = b < a ? b : a;
        else if (f == "max") r.c[0] = a < b ? b : a;
        else if (f == "floor") r.c[0] = std::floor(a);
        else if (f == "ceil") r.c[0] = std::ceil(a);
        else if (f == "pow") r.c[0] = std::pow(a, b);
        else if (f == "exp") r.c[0] = std::exp(a);
        else if (f == "log") r.c[0] = std::log(a);
        else if (f == "sin") r.c[0] = std::sin(a);
        else if (f == "cos") r.c[0] = std::cos(a);
        else if (f == "tan") r.c[0] = std::tan(a);
        else if (f == "atan") r.c[0] = std::atan2(a, b);
        return r;
      }
      case Expr::kVec2: case Expr::kVec3:
        for (int i = 0; i < w; ++i) r.c[i] = arg(i).c[0];
        return r;
      case Expr::kLength: case Expr::kNormalized: {
        Value a = arg(0);
        const int n = width_of(e.args[0].type);
        double s = 0;
        for (int i = 0; i < n; ++i) s += a.c[i] * a.c[i];
        const double l = std::sqrt(s);
        if (e.op == Expr::kLength) {
          r.c[0] = l;
          return r;
        }
        for (int i = 0; i < n; ++i) r.c[i] = a.c[i] / l;
        return r;
      }
    }
    return r;
  }

  // Runs the body; the produce statement reached, or -1.
  int run(const Stmt& s) {
    switch (s.kind) {
      case Stmt::kEmpty: return -1;
      case Stmt::kBlock:
        for (const Stmt& t : s.body)
          if (int p = run(t); p >= 0) return p;
        return -1;
      case Stmt::kDecl: slots_[static_cast<std::size_t>(s.slot)] = eval(*s.expr); return -1;
      case Stmt::kAssign: {
        Value v = eval(*s.expr);
        if (s.field >= 0) slots_[static_cast<std::size_t>(s.slot)].c[s.field] = v.c[0];
        else slots_[static_cast<std::size_t>(s.slot)] = v;
        return -1;
      }
      case Stmt::kIf:
        if (eval(*s.expr).c[0] != 0) return run(s.body[0]);
        return s.body.size() > 1 ? run(s.body[1]) : -1;
      case Stmt::kProduce: return s.produce;
    }
    return -1;
  }

  Value& slot(int i) { return slots_[static_cast<std::size_t>(i)]; }

 private:
  static double wrap_int(double v) {
    return static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<long long>(v))));
  }
  std::vector<Value> slots_;
};

}  // namespace

Value evaluate(const Production& p, const Expr& e) {
  Interpreter run(p);
  return run.eval(e);
}

GpuString CpuLsystemDeriver::derive(const LsystemProgram& program, const GpuString& string, int steps) {
  const ProductionCode& code = *program.code;
  GpuString from = string, to;
  std::vector<Interpreter> interpreters;
  for (const Production& p : code.productions) interpreters.emplace_back(p);
  std::vector<long> where;  // the matched modules' places, reused from module to module
  for (int step = 0; step < steps; ++step) {
    const long n = static_cast<long>(from.size());
    to.types.clear();
    to.params.clear();
    auto at = [&](long i, long& j) {
      if (i >= 0 && i < n) {
        j = i;
        return true;
      }
      if (!program.ring || n == 0) return false;
      j = ((i % n) + n) % n;
      return true;
    };
    for (long i = 0; i < n; ++i) {
      const int type = from.types[static_cast<std::size_t>(i)];
      bool applied = false;
      if (static_cast<std::size_t>(type) < code.by_type.size())
        for (int pi : code.by_type[static_cast<std::size_t>(type)]) {
          const Production& p = code.productions[static_cast<std::size_t>(pi)];
          Interpreter& run = interpreters[static_cast<std::size_t>(pi)];
          const long l = static_cast<long>(p.left.size());
          bool match = true;
          where.clear();
          for (long k = 0; k < l && match; ++k) {
            long j = 0;
            match = at(i - l + k, j) && from.types[static_cast<std::size_t>(j)] == p.left[static_cast<std::size_t>(k)];
            where.push_back(j);
          }
          where.push_back(i);
          for (std::size_t k = 0; k < p.right.size() && match; ++k) {
            long j = 0;
            match = at(i + 1 + static_cast<long>(k), j) && from.types[static_cast<std::size_t>(j)] == p.right[k];
            where.push_back(j);
          }
          if (!match) continue;
          for (std::size_t m = 0; m < p.formal_slots.size(); ++m) {
            const GpuModuleType& mt = program.types[static_cast<std::size_t>(from.types[static_cast<std::size_t>(where[m])])];
            const double* q = &from.params[4 * static_cast<std::size_t>(where[m])];
            for (std::size_t k = 0; k < p.formal_slots[m].size(); ++k) {
              Value& v = run.slot(p.formal_slots[m][k]);
              v = Value{};
              const int w = width_of(mt.params[k]);
              for (int c = 0; c < w; ++c) v.c[c] = *q++;
            }
          }
          const int produced = run.run(p.body);
          if (produced < 0) continue;
          for (const Produced& m : p.produces[static_cast<std::size_t>(produced)]) {
            const GpuModuleType& mt = program.types[static_cast<std::size_t>(m.type)];
            to.types.push_back(m.type);
            std::size_t base = to.params.size();
            to.params.resize(base + 4, 0.0);
            for (std::size_t k = 0; k < m.args.size(); ++k) {
              Value v = run.eval(m.args[k]);
              const int w = width_of(mt.params[k]);
              for (int c = 0; c < w; ++c) {
                double x = v.c[c];
                if (mt.single[k]) x = static_cast<float>(x);  // the engine keeps a float parameter in a float
                to.params[base++] = x;
              }
            }
          }
          applied = true;
          break;
        }
      if (!applied) {
        to.types.push_back(type);
        to.params.insert(to.params.end(), from.params.begin() + 4 * i, from.params.begin() + 4 * i + 4);
      }
    }
    std::swap(from, to);
  }
  return from;
}

}  // namespace sylva::gpu
