#include "lang/cpp_generator.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "lang/constant_modules.h"
#include "lang/event_margin.h"
#include "lang/mapped_writer.h"
#include "lang/parallel_safety.h"

namespace sylva::lang {
namespace {

const char* kind_name(abi::RuleKind kind) {
  switch (kind) {
    case abi::RuleKind::Production: return "::sylva::abi::RuleKind::Production";
    case abi::RuleKind::Decomposition: return "::sylva::abi::RuleKind::Decomposition";
    case abi::RuleKind::Interpretation: return "::sylva::abi::RuleKind::Interpretation";
    case abi::RuleKind::Derivative: return "::sylva::abi::RuleKind::Derivative";
    case abi::RuleKind::Event: return "::sylva::abi::RuleKind::Event";
  }
  return "";
}

std::string join_types(const std::vector<std::string>& types) {
  std::string list;
  for (std::size_t k = 0; k < types.size(); ++k) list += (k ? ", " : "") + types[k];
  return list;
}

class CppGenerator {
 public:
  explicit CppGenerator(const Model& model) : model_(model), out_(model.files) {
    for (std::size_t k = 0; k < model.modules.size(); ++k) module_id_[model.modules[k].name] = static_cast<int>(k);
  }

  std::string generate() {
    out_.block("// Generated from " + model_.main_file + " by the Sylva L+C translator.");
    for (const Item& item : model_.items) std::visit([this](const auto& x) { emit(x); }, item);
    emit_tables();
    return out_.take();
  }

 private:
  const ModuleDecl& module(const std::string& name) const { return model_.modules[module_id_.at(name)]; }

  void emit(const Code& code) { out_.tokens(code); }

  void emit(const ModuleDecl& decl) {
    // Checks the parameter types where the module is declared, so a bad type
    // is reported on that line.
    for (const std::string& type : decl.param_types)
      out_.at(decl.at, "static_assert(::std::is_trivially_copyable_v<" + type + ">, " +
                           quoted("module parameters must be trivially copyable (module " + decl.name + ")") + ");");
  }

  void emit(const StructFields& s) {
    std::string text = "inline void sylva_format_value(const " + s.name + "& v, ::sylva::abi::TextSink* out) {";
    for (std::size_t k = 0; k < s.fields.size(); ++k) {
      text += " out->write(" + quoted((k ? "," : "{") + s.fields[k] + "=") + "); ::sylva::rt::format_value(v." +
              s.fields[k] + ", out);";
    }
    text += " out->write(\"}\"); }";
    out_.at(s.at, text);
    out_.at(s.at, struct_parser(s));
    out_.at(s.at, struct_layout(s));
    out_.at(s.at, struct_text_from_table(s));
  }

  // Whether the engine can print the struct from its layout: every field
  // located (not a bit-field or a reference) and printable from its own.
  static std::string struct_text_from_table(const StructFields& s) {
    std::string text = "template <class SylvaS> requires ::std::is_same_v<SylvaS, " + s.name +
                       "> consteval bool sylva_struct_text_from_table(const SylvaS*) { return " +
                       (s.fields.empty() ? "false" : "true");
    for (const std::string& field : s.fields)
      text += " && requires { &SylvaS::" + field + "; } && ::sylva::rt::text_from_table<::std::remove_cv_t<decltype(SylvaS::" +
              field + ")>>()";
    return text + "; }";
  }

  // The fields' types and offsets for the model ABI. A template, so that a
  // field whose place cannot be taken (a bit-field) is listed without a type
  // instead of failing to compile.
  static std::string struct_layout(const StructFields& s) {
    std::string text = "template <class SylvaS> requires ::std::is_same_v<SylvaS, " + s.name +
                       "> inline ::sylva::rt::FieldList sylva_struct_fields(const SylvaS*) {"
                       " static const ::sylva::abi::ParamField sylva_fields[] = {";
    for (const std::string& field : s.fields)
      text += " [] { if constexpr (requires { &SylvaS::" + field + "; })" +
              " return ::sylva::rt::param_field<decltype(SylvaS::" + field + ")>(" + quoted(field) +
              ", __builtin_offsetof(SylvaS, " + field + "));" +
              " else return ::sylva::abi::ParamField{" + quoted(field) + ", 0, nullptr}; }(),";
    text += " }; return {sylva_fields, " + std::to_string(s.fields.size()) + ", " + quoted(s.name) + "}; }";
    return text;
  }

  // One field: read in place, through a copy for a bit-field, an error for a
  // const field.
  static std::string member_parser(const std::string& m) {
    return " if constexpr (requires { ::sylva::rt::parse_value(" + m + ", in); }) { if (!::sylva::rt::parse_value(" +
           m + ", in)) return false; } else if constexpr (requires { " + m + " = " + m +
           "; }) { ::std::remove_cvref_t<decltype(" + m +
           ")> sylva_value{}; if (!::sylva::rt::parse_value(sylva_value, in)) return false; " + m +
           " = sylva_value; } else { return ::sylva::rt::parse_fail(in, \"a field that can be set\"); }";
  }

  // Reads back what the printer above writes, fields by name in any order.
  // A template, so a field that cannot be set (const) reads as an error
  // instead of failing to compile.
  static std::string struct_parser(const StructFields& s) {
    std::string text = "template <class SylvaS> requires ::std::is_same_v<SylvaS, " + s.name +
                       "> inline bool sylva_parse_value(SylvaS& v, ::sylva::abi::TextSource* in) {"
                       " if (!::sylva::rt::parse_char(in, '{', \"'{' to begin a struct\")) return false;"
                       " if (::sylva::rt::parse_char_if(in, '}')) return true;"
                       " do { const char* sylva_name = nullptr; ::std::size_t sylva_n = 0;"
                       " if (!::sylva::rt::parse_field_name(in, sylva_name, sylva_n)) return false;";
    for (const std::string& field : s.fields)
      text += " if (::sylva::rt::same_name(sylva_name, sylva_n, " + quoted(field) + ")) {" + member_parser("v." + field) +
              "} else";
    text += " return ::sylva::rt::unknown_field(in, sylva_name, " + quoted("a field of " + s.name) + ");"
            " } while (::sylva::rt::parse_char_if(in, ','));"
            " return ::sylva::rt::parse_char(in, '}', \"'}' to end the struct\"); }";
    return text;
  }

  void emit(const Setting& setting) {
    std::string name;
    switch (setting.kind) {
      case Setting::kDerivationLength: name = "sylva_derivation_length"; break;
      case Setting::kDecompositionDepth: name = "sylva_decomposition_depth"; break;
      case Setting::kInterpretationDepth: name = "sylva_interpretation_depth"; break;
      case Setting::kRing: name = "sylva_ring"; break;
    }
    settings_[setting.kind] = name;
    out_.at(setting.at, "static int " + name + "() { return static_cast<int>(");
    out_.tokens(setting.expression);
    out_.inline_text("); }");
  }

  void emit(const Axiom& axiom) {
    has_axiom_ = true;
    out_.at(axiom.at, "static void sylva_axiom(::sylva::abi::ModuleBuffer* sylva_out) {");
    emit_calls(axiom.modules, "sylva_out");
    out_.inline_text("}");
  }

  void emit(const ControlStatement& statement) {
    static const char* names[] = {"sylva_start", "sylva_start_each", "sylva_end_each", "sylva_end"};
    control_[statement.kind] = names[statement.kind];
    out_.at(statement.at, std::string("static void ") + names[statement.kind] + "()");
    emit_body(statement.body);
  }

  void emit(const Rule& rule) {
    int index = static_cast<int>(rules_.size());
    rules_.push_back(&rule);
    std::string text = "static void sylva_rule_" + std::to_string(index) +
                       "([[maybe_unused]] ::sylva::abi::RuleCall* sylva_call,"
                       " [[maybe_unused]] const unsigned char* const* sylva_params) {";
    int slot = 0;
    for (const auto& part : rule.parts) {
      for (const PatternModule& m : part) {
        const ModuleDecl& decl = module(m.name);
        std::string types = join_types(decl.param_types);
        for (std::size_t k = 0; k < m.formals.size(); ++k) {
          text += " " + (model_.cpfg ? std::string("double") : decl.param_types[k]) + " " + m.formals[k] + " = ::sylva::rt::param<" + std::to_string(k) +
                  ", " + types + ">(sylva_params[" + std::to_string(slot) + "]); (void)" + m.formals[k] + ";";
        }
        ++slot;
      }
    }
    out_.at(rule.at, text);
    if (rule.kind == abi::RuleKind::Event) emit_event_condition(rule.event_condition);
    if (rule.kind == abi::RuleKind::Derivative)
      rate_types_ = join_types(module(rule.parts[abi::kStrict].front().name).param_types);
    emit_body(rule.body);
    out_.inline_text("}");
  }

  // An event's body first tells the engine whether its condition holds and
  // by how much (lang/event_margin.h); probed, or where it does not hold, it
  // stops there.
  void emit_event_condition(const Code& condition) {
    out_.at(condition.front(), "sylva_call->event_margin = ");
    for (const MarginPiece& piece : event_margin(condition)) {
      if (const auto* literal = std::get_if<std::string>(&piece)) {
        out_.inline_text(*literal);
        continue;
      }
      const TokenRun run = std::get<TokenRun>(piece);
      out_.tokens(Code(condition.begin() + static_cast<std::ptrdiff_t>(run.begin),
                       condition.begin() + static_cast<std::ptrdiff_t>(run.end)));
    }
    out_.inline_text("; sylva_call->event_holds = static_cast<bool>(");
    out_.tokens(condition);
    out_.inline_text("); if (sylva_call->event_probe || !sylva_call->event_holds) return;");
  }

  void emit_body(const Body& body) {
    for (const BodyPart& part : body) {
      if (part.kind == BodyPart::kCode) {
        out_.tokens(part.code);
        continue;
      }
      if (part.kind == BodyPart::kPropensity) {
        emit_propensity(part);
        continue;
      }
      if (part.kind == BodyPart::kInContext) {
        emit_in_context(part);
        continue;
      }
      if (part.kind == BodyPart::kRate) {
        out_.at(part.at, "::sylva::rt::set_rate<" + std::to_string(part.rate_index) + ", " + rate_types_ +
                             ">(sylva_call, static_cast<double>(");
        out_.tokens(part.code);
        out_.inline_text("));");
        continue;
      }
      out_.at(part.at, "{");
      emit_calls(part.modules, "sylva_call->out");
      out_.inline_text(part.kind == BodyPart::kProduce ? "sylva_call->produced = true; return; }" : "}");
    }
  }

  // A reaction: its successor is written, offered to the engine with its
  // propensity, and taken back out, so the body goes on to offer the next.
  void emit_propensity(const BodyPart& part) {
    out_.at(part.at, "{ const double sylva_propensity = static_cast<double>(");
    out_.tokens(part.code);
    out_.inline_text("); const ::std::size_t sylva_mark = sylva_call->out->size; {");
    emit_calls(part.modules, "sylva_call->out");
    out_.inline_text("} if (sylva_call->propose) sylva_call->propose(sylva_call, sylva_propensity);"
                     " sylva_call->out->size = sylva_mark; }");
  }

  // InLeftContext(A(x) B(y)) and its kin: a bool expression (parenthesized,
  // as lpfg allows `if InLeftContext(...)`) asking the engine for the
  // context, then copying the matched parameters into the body's variables.
  // Each variable is written where it stands in the model, so a type that
  // does not match the module's is reported at its line and column.
  void emit_in_context(const BodyPart& test) {
    static const char* parts[] = {"kNewLeft", "kLeft", "kStrict", "kRight", "kNewRight"};
    const std::size_t n = test.modules.size();
    std::string ids;
    for (const ModuleCall& m : test.modules) ids += std::to_string(module_id_.at(m.name)) + ",";
    out_.at(test.at, "(({ static constexpr ::sylva::abi::ModuleId sylva_ic_ids[] = {" + ids +
                         "}; const unsigned char* sylva_ic[" + std::to_string(n) +
                         "]; const bool sylva_ic_ok = ::sylva::rt::in_context(sylva_call, ::sylva::abi::" +
                         parts[test.context] + ", sylva_ic_ids, " + std::to_string(n) +
                         ", sylva_ic); if (sylva_ic_ok) {");
    for (std::size_t k = 0; k < n; ++k) {
      const ModuleCall& m = test.modules[k];
      const std::string types = join_types(module(m.name).param_types);
      for (std::size_t j = 0; j < m.args.size(); ++j) {
        out_.inline_text("::sylva::rt::in_context_parameter<" + std::to_string(j) + ", " + types + ">(sylva_ic[" +
                         std::to_string(k) + "],");
        out_.tokens(m.args[j]);
        out_.inline_text(");");
      }
    }
    out_.inline_text("} sylva_ic_ok; }))");
  }

  // Room for all the modules is reserved once; then each is written in turn:
  // runs of modules whose arguments are literals as bytes encoded here, the
  // others as calls.
  void emit_calls(const std::vector<ModuleCall>& calls, const std::string& target) {
    if (calls.empty()) return;
    std::vector<std::optional<std::string>> encoded;
    std::size_t encoded_size = 0;
    std::map<std::string, std::size_t> called;  // how many modules of each parameter list are calls
    for (const ModuleCall& call : calls) {
      const ModuleDecl& decl = module(call.name);
      encoded.push_back(constant_module_bytes(static_cast<abi::ModuleId>(module_id_.at(call.name)), decl.param_types,
                                              call.args));
      if (encoded.back()) encoded_size += encoded.back()->size();
      else ++called[join_types(decl.param_types)];
    }
    std::string bytes = encoded_size ? std::to_string(encoded_size) : "";
    for (const auto& [types, count] : called)
      bytes += (bytes.empty() ? "" : " + ") + std::to_string(count) + " * ::sylva::rt::module_bytes<" + types + ">";
    out_.inline_text("::sylva::abi::ModuleBuffer* sylva_o = " + target + "; sylva_o->reserve_more(" + bytes +
                     "); unsigned char* sylva_at = sylva_o->data + sylva_o->size;");
    std::string run;
    auto put_run = [&] {
      if (run.empty()) return;
      out_.inline_text("::sylva::rt::put_encoded_modules(sylva_at, " + bytes_literal(run) + ", " +
                       std::to_string(run.size()) + ");");
      run.clear();
    };
    for (std::size_t k = 0; k < calls.size(); ++k) {
      if (encoded[k]) {
        run += *encoded[k];
        continue;
      }
      put_run();
      emit_call(calls[k]);
    }
    put_run();
    out_.inline_text("sylva_o->size = static_cast<::std::size_t>(sylva_at - sylva_o->data);");
  }

  void emit_call(const ModuleCall& call) {
    const ModuleDecl& decl = module(call.name);
    // cpfg evaluates a module's parameters left to right (ran(1) before the
    // next ran(1)); the elements of a braced list are evaluated in order,
    // a function's arguments are not.
    std::size_t in_order = 0;
    if (model_.cpfg)
      while (in_order < call.args.size() && decl.param_types[in_order] == "float") ++in_order;
    if (in_order > 1) {
      out_.at(call.at, "{ const float sylva_v[] = {");
      for (std::size_t k = 0; k < in_order; ++k) {
        if (k) out_.inline_text(",");
        out_.tokens(call.args[k]);
      }
      out_.inline_text("};");
    } else {
      in_order = 0;
    }
    out_.at(call.at, "::sylva::rt::put_module<" + join_types(decl.param_types) + ">(sylva_at, " +
                         std::to_string(module_id_.at(call.name)));
    for (std::size_t k = 0; k < call.args.size(); ++k) {
      out_.inline_text(",");
      if (k < in_order) out_.inline_text("sylva_v[" + std::to_string(k) + "]");
      else out_.tokens(call.args[k]);
    }
    out_.inline_text(in_order > 0 ? "); }" : ");");
  }

  void emit_tables() {
    std::string t;
    t += "namespace {\n";
    t += "const ::sylva::abi::ModuleType sylva_modules[] = {\n";
    const std::size_t predefined = predefined_modules().size();
    for (std::size_t k = 0; k < model_.modules.size(); ++k) {
      const ModuleDecl& m = model_.modules[k];
      const std::string& shown = m.display_name.empty() ? m.name : m.display_name;
      if (model_.cpfg && k >= predefined) {
        // @L("format", p1, ...) holds its text, then floats; other modules only floats.
        const bool label = !m.param_types.empty() && m.param_types[0] == "const char*";
        t += std::string("  ::sylva::rt::cpfg::") + (label ? "label_module_type<" : "float_module_type<") +
             std::to_string(m.param_types.size() - (label ? 1 : 0)) + ">(" + quoted(shown) + "),\n";
        continue;
      }
      t += std::string("  ::sylva::rt::") + (k < predefined ? "predefined_module_type<" : "module_type<") +
           join_types(m.param_types) + ">(" + quoted(shown) + "),\n";
    }
    t += "};\n";
    for (std::size_t k = 0; k < model_.filters.size(); ++k) {
      t += "const ::sylva::abi::ModuleId sylva_filter_ids_" + std::to_string(k) + "[] = {";
      for (const std::string& name : model_.filters[k].names) t += std::to_string(module_id_.at(name)) + ",";
      t += "};\n";
    }
    t += "const ::sylva::abi::ContextFilter sylva_filters[] = {\n";
    for (std::size_t k = 0; k < model_.filters.size(); ++k) {
      t += "  {" + std::string(model_.filters[k].consider ? "true" : "false") + ", sylva_filter_ids_" +
           std::to_string(k) + ", " + std::to_string(model_.filters[k].names.size()) + "},\n";
    }
    t += "  {false, nullptr, 0}\n};\n";
    for (std::size_t r = 0; r < rules_.size(); ++r) {
      t += "const ::sylva::abi::ModuleId sylva_pattern_" + std::to_string(r) + "[] = {";
      for (const auto& part : rules_[r]->parts)
        for (const PatternModule& m : part) t += std::to_string(module_id_.at(m.name)) + ",";
      t += "};\n";
    }
    t += "const ::sylva::abi::Rule sylva_rules[] = {\n";
    for (std::size_t r = 0; r < rules_.size(); ++r) {
      const Rule& rule = *rules_[r];
      t += "  {" + std::string(kind_name(rule.kind)) + ", " + std::to_string(rule.group) + ", " +
           std::to_string(rule.filter) + ", sylva_pattern_" + std::to_string(r) + ", {";
      for (const auto& part : rule.parts) t += std::to_string(part.size()) + ",";
      t += "}, &sylva_rule_" + std::to_string(r) + ", " + quoted(model_.files[rule.at.file]) + ", " +
           std::to_string(rule.at.line) + ", " + std::to_string(rule.view) + "},\n";
    }
    t += "  {}\n};\n";
    // Which bodies a parallel derivation pass may run at once, and why not the others.
    const std::vector<RuleSafety> safety = rule_safety(model_);
    t += "const ::std::uint8_t sylva_rule_parallel[] = {";
    for (const RuleSafety& s : safety)
      t += s.reason.empty() ? (s.draws_random ? "2," : "1,") : "0,";
    t += "0};\nconst char* const sylva_rule_serial_reasons[] = {";
    for (const RuleSafety& s : safety) t += (s.reason.empty() ? std::string("nullptr") : quoted(s.reason)) + ",";
    t += "nullptr};\n";
    auto int_array = [&t](const char* name, const std::vector<int>& values) {
      if (values.empty()) return;
      t += std::string("const int ") + name + "[] = {";
      for (int v : values) t += std::to_string(v) + ",";
      t += "};\n";
    };
    int_array("sylva_lsystem_labels", model_.lsystem_labels);
    if (!model_.verify_string.empty()) {
      t += "const ::sylva::abi::ModuleId sylva_verify_string[] = {";
      for (const std::string& name : model_.verify_string) t += std::to_string(module_id_.at(name)) + ",";
      t += "};\n";
    }
    int_array("sylva_gillespie_groups", model_.gillespie_groups);
    int_array("sylva_groups", model_.groups);
    t += "}  // namespace\n\n";
    auto fn = [](const std::string& name) { return name.empty() ? std::string("nullptr") : "&" + name; };
    // lpfg's functions of the model's settings and groups, which its models
    // may call (lpfgall.h declares them).
    auto setting = [&](Setting::Kind kind, int otherwise) {
      return settings_[kind].empty() ? std::to_string(otherwise) : settings_[kind] + "()";
    };
    int last_group = 0, last_view = 0;
    for (int g : model_.groups) last_group = std::max(last_group, g);
    for (int g : model_.gillespie_groups) last_group = std::max(last_group, g);
    for (const Rule* rule : rules_) {
      last_group = std::max(last_group, rule->group);
      last_view = std::max(last_view, rule->view);
    }
    t += "int DerivationLength() { return " + setting(Setting::kDerivationLength, 0) + "; }\n";
    t += "int DecompositionMaxDepth() { return " + setting(Setting::kDecompositionDepth, 1) + "; }\n";
    t += "int InterpretationMaxDepth() { return " + setting(Setting::kInterpretationDepth, 1) + "; }\n";
    t += "int RingLsystem() { return " + setting(Setting::kRing, 0) + "; }\n";
    t += "int NumOfTables() { return " + std::to_string(last_group + 1) + "; }\n";
    t += "int NumOfViews() { return " + std::to_string(last_view + 1) + "; }\n";
    t += "extern \"C\" __attribute__((visibility(\"default\"))) const ::sylva::abi::ModelDescriptor* sylva_model_v1() {\n";
    // lpfg's ran() starts from its own state, once per loaded model (not per run).
    if (!model_.cpfg)
      t += "  static const bool sylva_random_set = (::sylva::rt::control.rand48 = ::sylva::abi::kLpfgRandomState, true);\n"
           "  (void)sylva_random_set;\n";
    t += "  static ::sylva::abi::ModelDescriptor descriptor = {\n";
    t += "    ::sylva::abi::kAbiVersion, " + quoted(model_.main_file) + ",\n";
    t += "    sylva_modules, " + std::to_string(model_.modules.size()) + ", " +
         std::to_string(predefined_modules().size()) + ",\n";
    t += "    sylva_rules, " + std::to_string(rules_.size()) + ",\n";
    t += "    sylva_filters, " + std::to_string(model_.filters.size()) + ",\n";
    t += "    &::sylva::rt::control,\n";
    t += "    " + std::string(has_axiom_ ? "&sylva_axiom" : "nullptr") + ",\n";
    t += "    " + fn(settings_[Setting::kDerivationLength]) + ", " + fn(settings_[Setting::kDecompositionDepth]) +
         ", " + fn(settings_[Setting::kInterpretationDepth]) + ", " + fn(settings_[Setting::kRing]) + ",\n";
    t += "    " + fn(control_[0]) + ", " + fn(control_[1]) + ", " + fn(control_[2]) + ", " + fn(control_[3]) + ",\n";
    std::string flags = model_.cpfg ? "::sylva::abi::kModelCpfg" : "0";
    if (model_.cpfg_sub_lsystems) flags += " | ::sylva::abi::kModelSubLsystems";
    if (model_.cpfg_stochastic) flags += " | ::sylva::abi::kModelProbeProductions";
    t += "    " + flags + ", " + (model_.cpfg_stochastic ? "&sylva_cpfg_before_module" : "nullptr") + ",\n";
    auto id_or_none = [&](const std::string& name) {
      return name.empty() ? std::string("::sylva::abi::kNoModule") : std::to_string(module_id_.at(name));
    };
    t += "    " + std::to_string(model_.main_lsystem) + ", " +
         (model_.lsystem_labels.empty() ? std::string("nullptr") : "sylva_lsystem_labels") + ", " +
         std::to_string(model_.lsystem_labels.size()) + ", " + id_or_none(model_.call_module) + ", " +
         id_or_none(model_.return_module) + ",\n";
    t += "    " + std::string(model_.verify_string.empty() ? "nullptr" : "sylva_verify_string") + ", " +
         (model_.has_verify_string ? std::to_string(model_.verify_string.size()) : std::string("-1")) + ",\n";
    t += "    " + std::string(model_.gillespie_groups.empty() ? "nullptr" : "sylva_gillespie_groups") + ", " +
         std::to_string(model_.gillespie_groups.size()) + ",\n";
    t += "    " + std::string(model_.groups.empty() ? "nullptr" : "sylva_groups") + ", " +
         std::to_string(model_.groups.size()) + ",\n";
    t += "    sylva_rule_parallel, sylva_rule_serial_reasons,\n";
    t += "  };\n";
    t += "  return &descriptor;\n}\n";
    out_.block(t);
  }

  const Model& model_;
  MappedWriter out_;
  std::unordered_map<std::string, int> module_id_;
  std::vector<const Rule*> rules_;
  std::string rate_types_;  // the parameter types of the derivative rule being written
  std::string settings_[4];
  std::string control_[4];
  bool has_axiom_ = false;
};

}  // namespace

std::string generate_cpp(const Model& model) { return CppGenerator(model).generate(); }

}  // namespace sylva::lang
