// Helpers for the tests of the differential L-systems in examples/: a model
// run in continuous time, and its string as modules.
#pragma once

#include <cctype>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "api/simulation.h"
#include "examples/example_strings.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test::examples {

// examples/NAME/NAME.l, to be run up to `end` with `method` at a relative
// tolerance `tolerance` (absolute: a thousandth of it) and events located to 1e-12.
inline std::unique_ptr<Simulation> timed(const std::string& name, double end,
                                         continuous::Method method = continuous::Method::kDormandPrince,
                                         double tolerance = 1e-9, std::vector<std::string> defines = {}) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.defines = std::move(defines);
  auto simulation =
      std::make_unique<Simulation>(example_path(name + "/" + name + ".l"), options, [](const std::string&) {});
  continuous::ContinuousSettings settings;
  settings.integrator.method = method;
  settings.integrator.relative_tolerance = tolerance;
  settings.integrator.absolute_tolerance = tolerance * 1e-3;
  settings.integrator.step = 1e-3;
  settings.event_tolerance = 1e-12;
  settings.end_time = end;
  simulation->set_continuous_settings(settings);
  return simulation;
}

inline std::vector<Module> modules_of(const Simulation& s) {
  std::string text = io::format_string(s.string(), s.types());
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return parse_modules(text);
}

}  // namespace sylva::test::examples
