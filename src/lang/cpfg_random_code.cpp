#include "lang/cpfg_random_code.h"

#include <algorithm>

namespace sylva::lang::cpfg {

RandomCode random_code(const std::vector<LsystemRandomness>& lsystems, std::size_t rule_count) {
  RandomCode out;
  // The stream of ran() and its kin restarts with every run.
  out.start = "::sylva::rt::cpfg::random = ::sylva::rt::cpfg::Random{}; "
              "if (::sylva::rt::control.seed_fixed) ::sylva::rt::cpfg::random.srand(::sylva::rt::control.seed); ";
  out.declarations = "namespace {\n";
  const bool own_streams = std::any_of(lsystems.begin(), lsystems.end(),
                                       [](const LsystemRandomness& l) { return !l.homomorphism_seed.empty(); });
  if (own_streams) {
    // cpfg restarts a homomorphism's own stream (a seed: of 0 or more) each
    // time it interprets the string.
    out.declarations += "[[maybe_unused]] ::std::uint64_t sylva_cpfg_homomorphism_stream[" +
                        std::to_string(lsystems.size()) + "];\nint sylva_cpfg_restart_streams() {\n";
    for (std::size_t k = 0; k < lsystems.size(); ++k) {
      if (lsystems[k].homomorphism_seed.empty()) continue;
      out.declarations += "  { const long s = " + lsystems[k].homomorphism_seed +
                          "; if (s >= 0) sylva_cpfg_homomorphism_stream[" + std::to_string(k) +
                          "] = ::sylva::rt::cpfg::Stream::seeded(s); }\n";
    }
    out.declarations += "  return 0;\n}\n";
    out.restarts_streams = true;
  }
  out.chooses = std::any_of(lsystems.begin(), lsystems.end(), [](const LsystemRandomness& l) { return l.stochastic; });
  if (out.chooses) {
    // The stream that chooses among stochastic productions is the C
    // library's drand48. cpfg seeds it with the first seed: (seed48({seed,
    // 0, 155})) only when its window opens; run in batch (-g), it never does,
    // so drand48 starts from its zero state whatever seed: says.
    const auto seeded = std::find_if(lsystems.begin(), lsystems.end(), [](const LsystemRandomness& l) { return l.stochastic; });
    // A run's own seed takes the place of seed: as the window would use it.
    out.start += "::sylva::rt::control.rand48 = ::sylva::rt::control.seed_fixed ? ((155ULL << 32) | "
                 "(static_cast<::std::uint64_t>(::sylva::rt::control.seed) & 0xFFFFULL)) : "
                 "::sylva::rt::control.cpfg_window_seeding ? ((155ULL << 32) | "
                 "(static_cast<::std::uint64_t>(" + seeded->production_seed + ") & 0xFFFFULL)) : 0; ";
    // The module's draw, the productions that apply with their
    // probabilities (cpfg sums them in float), and the one chosen.
    out.declarations +=
        "double sylva_cpfg_u = 0; int sylva_cpfg_chosen = -1; int sylva_cpfg_count = 0; float sylva_cpfg_total = 0;\n"
        "struct { int rule; float p; } sylva_cpfg_applicable[" + std::to_string(rule_count + 1) + "];\n"
        "void sylva_cpfg_applies(int rule, float p) { sylva_cpfg_total += p; "
        "sylva_cpfg_applicable[sylva_cpfg_count].rule = rule; sylva_cpfg_applicable[sylva_cpfg_count++].p = p; }\n";
    // Only the modules of a stochastic L-system draw.
    std::string draws = lsystems.size() == 1 ? "true" : "false";
    if (lsystems.size() > 1)
      for (const LsystemRandomness& l : lsystems)
        if (l.stochastic) draws += " || ::sylva::rt::control.current_group == " + std::to_string(l.label);
    // Called with a module before the probing pass, with kNoModule after it:
    // the draw times the total, less each probability in turn, picks the first
    // production to take it to 0 or below.
    out.declarations +=
        "void sylva_cpfg_before_module(::sylva::abi::ModuleId id) {\n"
        "  if (id != ::sylva::abi::kNoModule) {\n"
        "    ::sylva::rt::cpfg::probing = true; sylva_cpfg_count = 0; sylva_cpfg_total = 0; sylva_cpfg_chosen = -1;\n"
        "    if (" + draws + ") sylva_cpfg_u = ::sylva::rt::next_rand48();\n"
        "    return;\n"
        "  }\n"
        "  ::sylva::rt::cpfg::probing = false;\n"
        "  float r = static_cast<float>(sylva_cpfg_total * sylva_cpfg_u);\n"
        "  for (int k = 0; k < sylva_cpfg_count; ++k)\n"
        "    if ((r -= sylva_cpfg_applicable[k].p) <= 0) { sylva_cpfg_chosen = sylva_cpfg_applicable[k].rule; break; }\n"
        "}\n";
  }
  out.declarations += "}\n";
  return out;
}

}  // namespace sylva::lang::cpfg
