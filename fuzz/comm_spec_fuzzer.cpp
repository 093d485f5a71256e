// The environment's communication specification (.e), and its turtle formats
// applied as the environment pass applies them to each communication module.
#include "env/comm_spec.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sylva::fuzz::reading([&] {
    const sylva::env::CommSpec spec = sylva::env::parse_comm_spec(sylva::fuzz::text_of(data, size), "fuzz.e");
    const float vector[3] = {1.5f, -2e30f, 0.0f}, scalar[1] = {3.25f};
    for (const sylva::env::TurtleFormat* f : {&spec.position, &spec.heading, &spec.left, &spec.up})
      sylva::env::format_turtle_values(*f, vector);
    sylva::env::format_turtle_values(spec.line_width, scalar);
    sylva::env::format_turtle_values(spec.scale_factor, scalar);
  });
  return 0;
}
