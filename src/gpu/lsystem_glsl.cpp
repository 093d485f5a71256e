// Productions to GLSL (gpu/lsystem_glsl.h), the model's side: the Model IR
// read from the preprocessed model, its modules' parameters packed in
// texels, and its rules checked against the class and parsed
// (lsystem_body_parser.h) into the syntax tree (lsystem_tree.h), which is
// written out as GLSL (lsystem_glsl_writer.cpp) and interpreted on the CPU
// (lsystem_interpreter.cpp). Also the strings' text.
#include "gpu/lsystem_glsl.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/simulation.h"
#include "build/model_builder.h"
#include "gpu/lsystem_body_parser.h"
#include "gpu/lsystem_tree.h"
#include "gpu/number_text.h"
#include "lang/model_ir.h"
#include "lang/translator.h"
#include "support/diagnostic.h"
#include "support/plugin_library.h"

namespace sylva::gpu {
namespace {

// ---- the model ---------------------------------------------------------------

std::string where(const lang::Model& model, const Token& t) {
  const std::string file = t.file >= 0 && static_cast<std::size_t>(t.file) < model.files.size()
                               ? model.files[static_cast<std::size_t>(t.file)]
                               : model.main_file;
  return file + ":" + std::to_string(t.line) + ":" + std::to_string(t.column);
}

struct NotInClass {
  std::string reason;
};

lang::Model model_ir(const std::string& path, const build::BuildOptions& options) {
  lang::Model model;
  try {
    model = build::parse_model(path, options).model;
  } catch (const ModelError& error) {
    throw NotInClass{error.what()};
  }
  if (model.cpfg) throw NotInClass{"a cpfg model (only L+C productions are translated to GLSL)"};
  return model;
}

GpuKind param_kind(const abi::ParamType* t, bool& single, bool& ok) {
  ok = true;
  single = false;
  if (!t) {
    ok = false;
    return GpuKind::kFloat;
  }
  switch (t->kind) {
    case abi::ParamKind::kFloat: single = true; return GpuKind::kFloat;
    case abi::ParamKind::kDouble: return GpuKind::kFloat;
    case abi::ParamKind::kBool: return GpuKind::kBool;
    case abi::ParamKind::kSigned:
      if (t->size > 4) break;
      return GpuKind::kInt;
    case abi::ParamKind::kEnum:
      if (t->element && t->element->kind == abi::ParamKind::kSigned && t->element->size <= 4) return GpuKind::kInt;
      break;
    case abi::ParamKind::kVector:
      if (t->element && (t->element->kind == abi::ParamKind::kFloat || t->element->kind == abi::ParamKind::kDouble) &&
          (t->count == 2 || t->count == 3)) {
        single = t->element->kind == abi::ParamKind::kFloat;
        return t->count == 2 ? GpuKind::kVec2 : GpuKind::kVec3;
      }
      break;
    default: break;
  }
  ok = false;
  return GpuKind::kFloat;
}

class Translator {
 public:
  Translator(const lang::Model& model, const ModuleTypes& types) : model_(model), engine_(types) {}

  // The type's index, adding it; throws NotInClass if its parameters are not packable.
  int type_of(const std::string& name, const std::string& where_text) {
    if (auto f = index_.find(name); f != index_.end()) return f->second;
    const auto id = engine_.find(name);
    if (!id) throw NotInClass{where_text + ": module " + name + " is unknown to the compiled model"};
    if (name == "SB" || name == "EB")
      throw NotInClass{where_text + ": branches (" + name + "): context on the GPU is along a string without branches"};
    GpuModuleType t;
    t.name = name;
    t.engine_id = *id;
    const auto params = engine_.params(*id);
    if (engine_[*id].param_size > 0 && params.empty())
      throw NotInClass{where_text + ": module " + name + "'s parameters are of unknown types"};
    for (const abi::ParamField& f : params) {
      bool single = false, ok = false;
      const GpuKind k = param_kind(f.type, single, ok);
      if (!ok)
        throw NotInClass{where_text + ": module " + name +
                         " has a parameter that is not float, double, int, bool or a V2/V3 vector"};
      t.params.push_back(k);
      t.single.push_back(single);
      t.floats += width_of(k);
    }
    if (t.floats > 4)
      throw NotInClass{where_text + ": module " + name + "'s parameters are " + std::to_string(t.floats) +
                       " numbers, more than a texel's 4"};
    types_.push_back(std::move(t));
    index_[name] = static_cast<int>(types_.size()) - 1;
    return static_cast<int>(types_.size()) - 1;
  }

  void read_constants() {
    // `const TYPE NAME = EXPR;` at the top level (outside braces).
    int depth = 0;
    for (const lang::Item& item : model_.items) {
      const auto* code = std::get_if<lang::Code>(&item);
      if (!code) continue;
      const auto& c = *code;
      for (std::size_t i = 0; i < c.size(); ++i) {
        const Token& t = c[i];
        if (t.kind == TokenKind::Verbatim) continue;
        if (t.is_punct("{")) ++depth;
        if (t.is_punct("}")) --depth;
        if (depth != 0 || !(t.is_ident("const") || t.is_ident("constexpr"))) continue;
        std::size_t k = i + 1;
        std::string type_text;
        while (k < c.size() && c[k].is_ident() && (is_type_name(c[k].text) || c[k].is_ident("static"))) type_text = c[k++].text;
        std::optional<Type> ty = type_named(type_text);
        if (!ty || k + 2 >= c.size() || !c[k].is_ident() || !c[k + 1].is_punct("=")) continue;
        const std::string name = c[k].text;
        std::size_t end = k + 2;
        while (end < c.size() && !c[end].is_punct(";") && !c[end].is_punct("{") && !c[end].is_punct("}")) ++end;
        if (end >= c.size() || !c[end].is_punct(";")) continue;
        std::vector<Tok> toks;
        for (std::size_t j = k + 2; j < end; ++j) toks.push_back(Tok{&c[j]});
        if (toks.empty()) continue;
        try {
          Production scratch;
          std::vector<std::vector<lang::ModuleCall>> none;
          std::function<Produced(const lang::ModuleCall&, BodyParser&)> no_produce;
          BodyParser parser(toks, scratch, constants_, none, no_produce);
          Expr e = parser.assign_convert(parser.whole_expression(), *ty, c[k]);
          Value v = evaluate(scratch, e);
          constants_[name] = BodyParser::literal(*ty, 0);
          constants_[name].literal = v;
        } catch (const Unsupported&) {
          // Not a constant the productions can use: an error only where one does.
        } catch (const std::exception&) {
        }
      }
    }
  }

  ProductionCode productions() {
    for (const lang::Item& item : model_.items) {
      if (const auto* control = std::get_if<lang::ControlStatement>(&item))
        throw NotInClass{where(model_, control->at) +
                         ": a control statement (Start, StartEach, EndEach, End): its effects are not translated"};
    }
    if (!model_.gillespie_groups.empty()) throw NotInClass{"Gillespie groups (ggroup)"};
    if (model_.cpfg_sub_lsystems) throw NotInClass{"cpfg sub-L-systems"};
    ProductionCode code;
    for (const lang::Item& item : model_.items) {
      const auto* rule = std::get_if<lang::Rule>(&item);
      if (!rule) continue;
      if (rule->kind == abi::RuleKind::Interpretation) continue;
      if (rule->kind != abi::RuleKind::Production)
        throw NotInClass{where(model_, rule->at) + ": " +
                         (rule->kind == abi::RuleKind::Decomposition ? "a decomposition rule"
                          : rule->kind == abi::RuleKind::Event       ? "an event rule"
                                                                     : "a derivative rule") +
                         ": only productions are translated"};
      if (rule->group != 0)
        throw NotInClass{where(model_, rule->at) + ": a production of group " + std::to_string(rule->group)};
      if (rule->filter >= 0) {
        const auto& f = model_.filters[static_cast<std::size_t>(rule->filter)];
        throw NotInClass{where(model_, f.at) + ": " + (f.consider ? "consider:" : "ignore:") +
                         " (context on the GPU is over every module)"};
      }
      code.productions.push_back(production(*rule));
    }
    code.by_type.resize(types_.size());
    for (std::size_t p = 0; p < code.productions.size(); ++p)
      code.by_type[static_cast<std::size_t>(code.productions[p].strict)].push_back(static_cast<int>(p));
    return code;
  }

  Production production(const lang::Rule& rule) {
    Production p;
    const auto& parts = rule.parts;
    if (!parts[abi::kNewLeft].empty() || !parts[abi::kNewRight].empty()) {
      const auto& m = !parts[abi::kNewLeft].empty() ? parts[abi::kNewLeft][0] : parts[abi::kNewRight][0];
      throw NotInClass{where(model_, m.at) + ": new context (<< or >>): the GPU reads only the old string"};
    }
    if (parts[abi::kStrict].size() != 1)
      throw NotInClass{where(model_, rule.at) + ": a strict predecessor of " +
                       std::to_string(parts[abi::kStrict].size()) + " modules (one is translated)"};
    std::vector<const lang::PatternModule*> pattern;
    for (const auto& m : parts[abi::kLeft]) pattern.push_back(&m);
    pattern.push_back(&parts[abi::kStrict][0]);
    for (const auto& m : parts[abi::kRight]) pattern.push_back(&m);
    for (const lang::PatternModule* m : pattern) {
      const int t = type_of(m->name, where(model_, m->at));
      if (m->name == "%" || m->name == "*") throw NotInClass{where(model_, m->at) + ": a wildcard module"};
      if (m->formals.size() != types_[static_cast<std::size_t>(t)].params.size())
        throw NotInClass{where(model_, m->at) + ": module " + m->name + " with " + std::to_string(m->formals.size()) +
                         " formal parameters"};
    }
    for (const auto& m : parts[abi::kLeft]) p.left.push_back(index_[m.name]);
    p.strict = index_[parts[abi::kStrict][0].name];
    for (const auto& m : parts[abi::kRight]) p.right.push_back(index_[m.name]);

    // The body's tokens with the produce statements cut out.
    std::vector<Tok> toks;
    std::vector<std::vector<lang::ModuleCall>> produce_calls;
    for (const lang::BodyPart& part : rule.body) {
      switch (part.kind) {
        case lang::BodyPart::kCode:
          for (const Token& t : part.code) toks.push_back(Tok{&t});
          break;
        case lang::BodyPart::kProduce:
          toks.push_back(Tok{&part.at, static_cast<int>(produce_calls.size())});
          produce_calls.push_back(part.modules);
          break;
        case lang::BodyPart::kNProduce:
          throw NotInClass{where(model_, part.at) + ": 'nproduce'"};
        case lang::BodyPart::kInContext:
          throw NotInClass{where(model_, part.at) + ": a context test in the body (InLeftContext ...)"};
        default:
          throw NotInClass{where(model_, part.at) + ": a statement of another kind of rule"};
      }
    }
    std::function<Produced(const lang::ModuleCall&, BodyParser&)> produced = [this](const lang::ModuleCall& call,
                                                                                    BodyParser& parser) {
      Produced m;
      m.type = type_of(call.name, where(model_, call.at));
      const GpuModuleType& type = types_[static_cast<std::size_t>(m.type)];
      if (call.args.size() != type.params.size())
        parser.fail_at(call.at, "module " + call.name + " produced with " + std::to_string(call.args.size()) +
                                    " parameters");
      for (std::size_t k = 0; k < call.args.size(); ++k) {
        std::vector<Tok> arg;
        for (const Token& t : call.args[k]) arg.push_back(Tok{&t});
        parser.reset(std::move(arg));
        Expr e = parser.whole_expression();
        m.args.push_back(parser.assign_convert(std::move(e), type.params[k], call.args[k].front()));
      }
      return m;
    };
    if (toks.empty()) throw NotInClass{where(model_, rule.at) + ": an empty body"};
    BodyParser parser(std::move(toks), p, constants_, produce_calls, produced);
    for (std::size_t m = 0; m < pattern.size(); ++m) {
      const GpuModuleType& type = types_[static_cast<std::size_t>(index_[pattern[m]->name])];
      std::vector<int> slots;
      for (std::size_t k = 0; k < pattern[m]->formals.size(); ++k) {
        const int slot = parser.new_slot(pattern[m]->formals[k], type.params[k]);
        parser.declare_formal(pattern[m]->formals[k], slot);
        slots.push_back(slot);
      }
      p.formal_slots.push_back(std::move(slots));
    }
    try {
      p.body = parser.parse_body();
    } catch (const Unsupported& u) {
      throw NotInClass{where(model_, *u.at) + ": " + u.what};
    }
    return p;
  }

  std::vector<GpuModuleType> take_types() { return std::move(types_); }
  const std::vector<GpuModuleType>& types() const { return types_; }

 private:
  const lang::Model& model_;
  const ModuleTypes& engine_;
  std::vector<GpuModuleType> types_;
  std::map<std::string, int> index_;
  std::map<std::string, Expr> constants_;
};

}  // namespace

LsystemTranslation translate_lsystem(Simulation& simulation, const build::BuildOptions& build) {
  LsystemTranslation result;
  try {
    const lang::Model model = model_ir(simulation.model_path(), build);
    Translator translator(model, simulation.types());
    translator.read_constants();
    auto code = std::make_shared<ProductionCode>(translator.productions());
    simulation.begin();
    // The string after the axiom: every module's type.
    const ModuleString& string = simulation.string();
    const ModuleTypes& engine = simulation.types();
    std::vector<std::pair<int, std::vector<double>>> modules;
    for (std::size_t at = 0; at < string.size_bytes(); at += engine.encoded_size(module_id_at(string.data(), at))) {
      const ModuleId id = module_id_at(string.data(), at);
      const int t = translator.type_of(engine.name(id), "the axiom's string");
      modules.emplace_back(t, engine.numbers(id, module_params(string.data(), at)));
    }
    code->by_type.resize(translator.types().size());
    result.program.types = translator.take_types();
    result.program.productions = static_cast<int>(code->productions.size());
    result.program.glsl = program_glsl(*code, result.program.types);
    result.program.code = std::move(code);
    const auto& descriptor = simulation.descriptor();
    result.program.ring = descriptor.ring && descriptor.ring() != 0;
    for (auto& [t, numbers] : modules) {
      if (static_cast<int>(numbers.size()) != result.program.types[static_cast<std::size_t>(t)].floats)
        throw NotInClass{"module " + result.program.types[static_cast<std::size_t>(t)].name +
                         "'s parameters in the axiom are not the numbers of its declaration"};
      result.axiom.types.push_back(t);
      numbers.resize(4, 0.0);
      result.axiom.params.insert(result.axiom.params.end(), numbers.begin(), numbers.end());
    }
    result.in_class = true;
  } catch (const NotInClass& n) {
    result.reason = n.reason;
  }
  return result;
}

std::string format_gpu_string(const LsystemProgram& program, const GpuString& string, bool as_float) {
  std::string out;
  out.reserve(string.size() * 24);
  for (std::size_t i = 0; i < string.size(); ++i) {
    const GpuModuleType& type = program.types[static_cast<std::size_t>(string.types[i])];
    if (i) out += ' ';
    out += type.name;
    if (type.params.empty()) continue;
    out += '(';
    const double* q = &string.params[4 * i];
    for (std::size_t k = 0; k < type.params.size(); ++k) {
      if (k) out += ',';
      const bool single = as_float || type.single[k];
      switch (type.params[k]) {
        case GpuKind::kBool: out += *q != 0 ? "1" : "0"; ++q; break;
        case GpuKind::kInt: append_number(out, std::trunc(*q), false); ++q; break;
        case GpuKind::kFloat: append_number(out, *q, single); ++q; break;
        case GpuKind::kVec2: case GpuKind::kVec3: {
          const int n = type.params[k] == GpuKind::kVec2 ? 2 : 3;
          out += '(';
          for (int c = 0; c < n; ++c) {
            if (c) out += ',';
            append_number(out, *q++, single);
          }
          out += ')';
          break;
        }
      }
    }
    out += ')';
  }
  return out;
}


GlLsystemDeriver& gl_lsystem_deriver() {
  return plugin_object<GlLsystemDeriver>("libsylva_gl.so", "sylva_gl_lsystem_deriver",
                                         "derives L-systems on the GPU");
}

}  // namespace sylva::gpu
