// cpfg sub-L-systems (CPFG manual 7.2) and predefined surfaces ~id (6.7.1):
// small models whose strings and scenes are worked out by hand.
//
// ?(label,s) hands the modules after it to L-system `label` until its $; each
// L-system rewrites only its own modules (no fallback to another's rules).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "geometry/scene.h"
#include "io/string_text.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;
using geometry::Scene;
using geometry::Vec3;

struct Model {
  std::string dir;
  std::unique_ptr<Simulation> simulation;
};

// `text` as dir/lsystem.l, with a view file when `view` is not empty.
Model load(const std::string& name, const std::string& text, const std::string& view = "",
           const std::vector<std::string>& copies = {}) {
  Model m;
  m.dir = make_temp_dir("cpfg-sub-" + name);
  std::ofstream(m.dir + "/lsystem.l") << text;
  std::vector<std::string> inputs;
  if (!view.empty()) {
    std::ofstream(m.dir + "/view.v") << view << "\n";
    inputs.push_back(m.dir + "/view.v");
  }
  for (const std::string& file : copies)
    fs::copy_file(data_path(file), fs::path(m.dir) / fs::path(file).filename(), fs::copy_options::overwrite_existing);
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  m.simulation = std::make_unique<Simulation>(m.dir + "/lsystem.l", SimulationOptions{build, {inputs.begin(), inputs.end()}});
  return m;
}

std::string text_of(const ModuleString& string, const Simulation& s) {
  std::string text = io::format_string(string, s.types());
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

std::string string_after(Simulation& s, int steps) {
  s.run(steps);
  return text_of(s.string(), s);
}

// The manual's structure: L-system 1 calls L-system 2 on B. B and F outside
// the call are L-system 1's; inside it, L-system 2's (which has no rule for F).
//   axiom   A(3) B(0) F(1)
//   step 1  ?(2,1)B(2)$ X F(2)          A(3) --> ?(2,1)B(2)$ ; B(0) --> X in 1
//   step 2  ?(2,1)F(2)B(3)$ X F(4)      B(2) --> F(2)B(3) in 2
//   step 3  ?(2,1)F(2)F(3)B(4)$ X F(8)  F(2) inside the call stays
const char* const kManualExample =
    "Lsystem: 1\n"
    "derivation length: 3\n"
    "Axiom: A(3)B(0)F(1)\n"
    "A(t) --> ?(2,1)B(t-1)$\n"
    "B(x) --> X\n"
    "F(x) --> F(2*x)\n"
    "endlsystem\n"
    "\n"
    "Lsystem: 2\n"
    "Axiom: !(3);(48)B(5)\n"
    "B(x) --> F(x)B(x+1)\n"
    "endlsystem\n";

TEST(CpfgSubLsystem, ManualExampleStepByStep) {
  Model m = load("manual", kManualExample);
  EXPECT_EQ(string_after(*m.simulation, 0), "A(3)B(0)F(1)");
  EXPECT_EQ(string_after(*m.simulation, 1), "?(2,1)B(2)$XF(2)");
  EXPECT_EQ(string_after(*m.simulation, 2), "?(2,1)F(2)B(3)$XF(4)");
  EXPECT_EQ(string_after(*m.simulation, 3), "?(2,1)F(2)F(3)B(4)$XF(8)");
  fs::remove_all(m.dir);
}

// Nested calls; C is rewritten by each L-system its own way (c, e, K).
//   axiom   A
//   step 1  ?(2,1)B$C
//   step 2  ?(2,1)?(3,0.5)C$CD$c        B in 2, C in 1
//   step 3  ?(2,1)?(3,0.5)K$ed$c        C in 3, C and D in 2
TEST(CpfgSubLsystem, NestedCallsAndOneSymbolPerLsystem) {
  Model m = load("nested",
                 "Lsystem: 1\nAxiom: A\nA --> ?(2,1)B$C\nC --> c\nendlsystem\n"
                 "Lsystem: 2\nAxiom: B\nB --> ?(3,0.5)C$CD\nC --> e\nD --> d\nendlsystem\n"
                 "Lsystem: 3\nAxiom: C\nC --> K\nendlsystem\n");
  EXPECT_EQ(string_after(*m.simulation, 1), "?(2,1)B$C");
  EXPECT_EQ(string_after(*m.simulation, 2), "?(2,1)?(3,0.5)C$CD$c");
  EXPECT_EQ(string_after(*m.simulation, 3), "?(2,1)?(3,0.5)K$ed$c");
  fs::remove_all(m.dir);
}

// Decomposition and homomorphism follow the calls too.
//   step 1: productions none; decomposition D --> B in 1, D --> E in 2:
//           B?(2,1)E$B ; homomorphism B --> F in 1, E --> G in 2: F?(2,1)G$F
TEST(CpfgSubLsystem, DecompositionAndHomomorphismPerLsystem) {
  Model m = load("homomorphism",
                 "Lsystem: 1\nderivation length: 1\nAxiom: D?(2,1)D$D\n"
                 "decomposition\nD --> B\nhomomorphism\nB --> F\nendlsystem\n"
                 "Lsystem: 2\nAxiom: D\ndecomposition\nD --> E\nhomomorphism\nE --> G\nB --> f\nendlsystem\n");
  EXPECT_EQ(string_after(*m.simulation, 1), "B?(2,1)E$B");
  EXPECT_EQ(text_of(m.simulation->interpreted(0), *m.simulation), "F?(2,1)G$F");
  fs::remove_all(m.dir);
}

// Each L-system's ignore: applies to its own rules only.
TEST(CpfgSubLsystem, IgnorePerLsystem) {
  // In 1, A < B skips +; in 2 it does not (B sees + on its left).
  Model m = load("ignore",
                 "Lsystem: 1\nAxiom: A+B?(2,1)A+B$\nignore: +\nA < B --> X\nendlsystem\n"
                 "Lsystem: 2\nAxiom: B\nA < B --> Y\nendlsystem\n");
  EXPECT_EQ(string_after(*m.simulation, 1), "A+X?(2,1)A+B$");
  fs::remove_all(m.dir);
}

TEST(CpfgSubLsystem, ACallToNoLsystemIsAClearError) {
  // A constant label: when the model is read, at its place.
  try {
    load("unknown-constant", "Lsystem: 1\nAxiom: A\nA --> ?(5,1)B$\nendlsystem\nLsystem: 2\nAxiom: B\nendlsystem\n");
    FAIL() << "the model was accepted";
  } catch (const ModelError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("lsystem.l:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("no 'Lsystem: 5'"), std::string::npos) << what;
  }
  // A computed label: when the derivation meets it.
  Model m = load("unknown-computed", "Lsystem: 1\nAxiom: A(7)\nA(t) --> ?(t,1)B$\nB --> C\nendlsystem\n"
                                     "Lsystem: 2\nAxiom: B\nendlsystem\n");
  m.simulation->run(1);
  try {
    m.simulation->run(2);
    FAIL() << "the call to L-system 7 was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("no 'Lsystem: 7'"), std::string::npos) << e.what();
  }
  fs::remove_all(m.dir);
}

TEST(CpfgSubLsystem, DuplicateLabelsAreAnError) {
  try {
    load("duplicate", "Lsystem: 1\nAxiom: A\nendlsystem\nLsystem: 1\nAxiom: B\nendlsystem\n");
    FAIL() << "the model was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("a second L-system with label 1"), std::string::npos) << e.what();
  }
}

// The turtle scales what a call draws by its s, until the call's $; a $
// outside a call keeps its roll-to-vertical meaning.
TEST(CpfgSubLsystem, TurtleScalesTheCalledStructure) {
  Model m = load("turtle", "Lsystem: 1\nAxiom: F?(2,0.5)FF?(2,0.5)F$F$F\nendlsystem\nLsystem: 2\nAxiom: F\nendlsystem\n",
                 "angle increment: 90");
  m.simulation->run(0);
  const Scene s = m.simulation->scene();
  ASSERT_EQ(s.segments.size(), 6u);
  const float lengths[] = {1, 0.5f, 0.5f, 0.25f, 0.5f, 1};
  float y = 0;
  for (int k = 0; k < 6; ++k) {
    y += lengths[k];
    EXPECT_NEAR(s.segments[static_cast<std::size_t>(k)].end.y, y, 1e-5) << "segment " << k;
  }
  fs::remove_all(m.dir);
}

// ~l draws the view file's surface `l` at the turtle, scaled by its
// parameter. leaf.s: contact (0,0,0), tip (0,2,0), size 2; after F the
// turtle is at (0,1,0) heading +y, so ~l(2) spans y from 1 to 3.
TEST(CpfgSurface, PredefinedSurfaceAtTheTurtle) {
  Model m = load("surface", "Lsystem: 1\nAxiom: F~l(2)\nendlsystem\n", "surface: l leaf.s 1",
                 {"data/inputs/leaf.s"});
  m.simulation->run(0);
  EXPECT_EQ(text_of(m.simulation->string(), *m.simulation), "F~l(2)");
  const Scene s = m.simulation->scene();
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].kind, geometry::TriangleGroup::Kind::Surface);
  EXPECT_EQ(s.groups[0].from.module_index, 1u);
  float low = 1e9f, high = -1e9f;
  bool at_turtle = false, at_tip = false;
  for (std::uint32_t k = 0; k < s.groups[0].index_count; ++k) {
    const Vec3 p = s.positions[s.indices[s.groups[0].first_index + k]];
    low = std::min(low, p.y);
    high = std::max(high, p.y);
    if (std::abs(p.x) < 1e-4f && std::abs(p.y - 1) < 1e-4f && std::abs(p.z) < 1e-4f) at_turtle = true;
    if (std::abs(p.x) < 1e-4f && std::abs(p.y - 3) < 1e-4f && std::abs(p.z) < 1e-4f) at_tip = true;
  }
  EXPECT_NEAR(low, 1, 1e-4);
  EXPECT_NEAR(high, 3, 1e-4);
  EXPECT_TRUE(at_turtle);
  EXPECT_TRUE(at_tip);
  fs::remove_all(m.dir);
}

TEST(CpfgSurface, UnknownIdIsAClearError) {
  Model m = load("surface-missing", "Lsystem: 1\nAxiom: F~k\nendlsystem\n", "surface: l leaf.s 1",
                 {"data/inputs/leaf.s"});
  m.simulation->run(0);
  try {
    m.simulation->scene();
    FAIL() << "~k was drawn";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("no surface has id 'k'"), std::string::npos) << e.what();
  }
  fs::remove_all(m.dir);
}

}  // namespace
}  // namespace sylva::test
