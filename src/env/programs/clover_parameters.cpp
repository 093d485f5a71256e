#include "env/programs/clover_parameters.h"

#include "env/programs/vlab_spec_file.h"
#include "support/diagnostic.h"

namespace sylva::env {
namespace {

constexpr const char* kNumbers = "x,; \t:\n";  // "100x100" is two numbers
constexpr const char* kWords = ",; \t:\n";

// Two numbers, each stored as it is read: a line with one keeps the second's
// old value, as the real clover does.
template <class Number>
void read_pair(SpecLineTokens& line, std::array<Number, 2>& pair) {
  for (Number& value : pair) {
    const std::optional<double> number = line.next_number(kNumbers);
    if (!number) return;
    value = static_cast<Number>(*number);  // an int truncates, as C's assignment does
  }
}

}  // namespace

CloverParameters read_clover_parameters(const std::filesystem::path& path, const std::filesystem::path& directory) {
  CloverParameters p;
  int size_line = 0;
  read_vlab_spec_file(path, "clover",
                      {"grid size", "grid position", "verbose", "transmittance", "input image", "grid range",
                       "remove old leaves", "z is up"},
                      [&](std::size_t keyword, SpecLineTokens& line) {
                        switch (keyword) {
                          case 0:
                            read_pair(line, p.size);
                            size_line = line.line();
                            break;
                          case 1: read_pair(line, p.position); break;
                          case 2: line.next_switch(kWords, {"on"}, {"off"}, true, p.verbose); break;
                          case 3:
                            if (std::optional<double> t = line.next_number(kWords)) {
                              p.transmittance = static_cast<float>(*t);
                              if (p.transmittance == 0) {
                                p.transmittance = 0.0001f;
                                line.warn("a transmittance of 0 is read as 0.0001, as clover reads it");
                              }
                            }
                            break;
                          case 4:
                            if (std::optional<std::string> image = line.next(kWords)) p.image = *image;
                            break;
                          case 5: read_pair(line, p.range); break;
                          case 6: line.next_switch(kWords, {"on", "yes"}, {"off", "no"}, true, p.remove_old_leaves); break;
                          case 7: line.next_switch(kWords, {"no", "off"}, {"yes", "on"}, false, p.z_is_up); break;
                        }
                      });
  if (p.size[0] < 1 || p.size[1] < 1 || static_cast<double>(p.size[0]) * p.size[1] > 1e9)
    throw ModelError(SourceLocation{path.string(), size_line, 0},
                     "clover: the grid size must be at least 1 x 1 cells and at most 10^9 cells, found " +
                         std::to_string(p.size[0]) + " x " + std::to_string(p.size[1]));
  if (!p.image.empty() && p.image.is_relative()) p.image = directory / p.image;
  return p;
}

}  // namespace sylva::env
