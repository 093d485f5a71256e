// The two decoders, module by module: an L+C predefined module or a cpfg
// symbol with its parameters, and the turtle command it means, worked out
// by hand from the LPFG and CPFG manuals.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "sylva/predefined_ids.h"
#include "turtle/cpfg_decoder.h"
#include "turtle/lpfg_decoder.h"

namespace sylva::test {
namespace {

namespace mid = rt::mid;
namespace cmd = turtle::command;
using turtle::TurtleCommand;

// A parameter block of the given 4-byte values, as a module's.
template <class... Values>
std::vector<unsigned char> params(Values... values) {
  std::vector<unsigned char> bytes;
  [[maybe_unused]] auto put = [&](auto v) {
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    bytes.insert(bytes.end(), b, b + sizeof v);
  };
  (put(values), ...);
  bytes.resize(bytes.size() + 8);  // room for reads past the last parameter
  return bytes;
}

TurtleCommand lpfg(const turtle::TurtleSettings& settings, ModuleId id, const std::vector<unsigned char>& p = params()) {
  turtle::LpfgDecoder decoder(settings);
  turtle::CommandRecorder recorder;
  EXPECT_TRUE(decoder.decode(id, p.data(), recorder));
  return recorder.command;
}

TEST(LpfgDecoder, StepsAndTurns) {
  const turtle::TurtleSettings settings;
  const auto forward = std::get<cmd::Forward>(lpfg(settings, mid::F, params(2.5f)));
  EXPECT_EQ(forward.distance, 2.5f);
  EXPECT_TRUE(forward.draw && forward.records_vertex);
  const auto g = std::get<cmd::Forward>(lpfg(settings, mid::g, params(1.0f)));
  EXPECT_FALSE(g.draw || g.records_vertex);

  const auto right = std::get<cmd::Turn>(lpfg(settings, mid::Right, params(30.0f)));
  EXPECT_EQ(right.axis, cmd::Axis::Up);
  EXPECT_EQ(right.degrees, -30.0f);
  // Corrected rotation (the default): Up turns H toward U, a negative turn around L.
  const auto up = std::get<cmd::Turn>(lpfg(settings, mid::Up, params(30.0f)));
  EXPECT_EQ(up.axis, cmd::Axis::Left);
  EXPECT_EQ(up.degrees, -30.0f);
  turtle::TurtleSettings old = settings;
  old.corrected_rotation = false;
  EXPECT_EQ(std::get<cmd::Turn>(lpfg(old, mid::Up, params(30.0f))).degrees, 30.0f);
  EXPECT_EQ(std::get<cmd::Turn>(lpfg(old, mid::RollR, params(30.0f))).degrees, -30.0f);
}

TEST(LpfgDecoder, MovesInTheirCoordinates) {
  const turtle::TurtleSettings settings;
  const auto move = std::get<cmd::MoveTo>(lpfg(settings, mid::MoveRel2f, params(1.0f, 2.0f)));
  EXPECT_EQ(move.coordinates, cmd::Coordinates::LocalOffset);
  EXPECT_EQ(move.point.x, 1.0f);
  EXPECT_EQ(move.point.y, 2.0f);
  EXPECT_EQ(move.point.z, 0.0f);
  const auto line = std::get<cmd::Line>(lpfg(settings, mid::Line3f, params(1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f)));
  EXPECT_EQ(line.from.z, 3.0f);
  EXPECT_EQ(line.to.x, 4.0f);
}

TEST(LpfgDecoder, OutOfRangeValuesAreNotes) {
  const turtle::TurtleSettings settings;
  EXPECT_STREQ(std::get<cmd::Note>(lpfg(settings, mid::SetColor, params(256))).text, " ignored: outside 1..255");
  EXPECT_EQ(std::get<cmd::SetColor>(lpfg(settings, mid::SetColor, params(255))).index, 255);
  EXPECT_STREQ(std::get<cmd::Note>(lpfg(settings, mid::SetWidth, params(0.0f))).text, " ignored: not positive");
  EXPECT_EQ(std::get<cmd::ContourSides>(lpfg(settings, mid::ContourSides, params(2))).sides, 3);
}

TEST(LpfgDecoder, ShapesAndElasticities) {
  turtle::TurtleSettings settings;
  settings.tropisms.resize(1);
  settings.tropisms[0].step = 0.25f;
  // Circle0: half the width; CircleB: a ring of the width.
  EXPECT_FALSE(std::get<cmd::Circle>(lpfg(settings, mid::Circle0)).radius.has_value());
  const auto ring = std::get<cmd::Circle>(lpfg(settings, mid::CircleFrontB, params(3.0f)));
  EXPECT_EQ(*ring.radius, 3.0f);
  EXPECT_TRUE(ring.outlined && ring.facing_viewer);
  const auto surface = std::get<cmd::Surface>(lpfg(settings, mid::Surface, params(2, 0.5f)));
  EXPECT_EQ(surface.id, 2);
  EXPECT_EQ(surface.scale.y, 0.5f);
  EXPECT_FALSE(surface.view_texture_first);
  const auto dec = std::get<cmd::SetElasticity>(lpfg(settings, mid::DecElasticity, params(1)));
  EXPECT_EQ(dec.value, -0.25f);
  EXPECT_TRUE(dec.relative);
  EXPECT_EQ(std::get<cmd::SetElasticity>(lpfg(settings, mid::IncElasticity, params(2))).value, 0.0f);  // no tropism 2
  EXPECT_EQ(std::get<cmd::Query>(lpfg(settings, mid::GetHead, params(0.0f, 0.0f, 0.0f))).quantity,
            cmd::Quantity::Heading);
  EXPECT_FALSE(std::get<cmd::EndPolygon>(lpfg(settings, mid::EP)).textured);
}

TEST(LpfgDecoder, UserModulesAreNotCommands) {
  const turtle::TurtleSettings settings;
  turtle::LpfgDecoder decoder(settings);
  turtle::CommandRecorder recorder;
  const auto p = params();
  EXPECT_FALSE(decoder.decode(static_cast<ModuleId>(mid::PredefinedCount), p.data(), recorder));
  // A predefined module the turtle does not act on still has its line in the trace.
  recorder.command = cmd::Push{};
  EXPECT_TRUE(decoder.decode(mid::MouseIns, p.data(), recorder));
  EXPECT_STREQ(std::get<cmd::Note>(recorder.command).text, "");
}

// ---- cpfg -----------------------------------------------------------------------------

// A cpfg model's module types: the predefined ones, then `symbols` (name,
// number of float parameters).
ModuleTypes cpfg_types(const std::vector<std::pair<std::string, int>>& symbols) {
  std::vector<ModuleTypes::Type> types(mid::PredefinedCount);
  for (std::size_t id = 0; id < types.size(); ++id) types[id].name = "predefined" + std::to_string(id);
  for (const auto& [name, count] : symbols) {
    ModuleTypes::Type t;
    t.name = name;
    t.param_size = static_cast<std::uint32_t>(4 * count + (name == "@L" ? sizeof(const char*) : 0));
    types.push_back(t);
  }
  ModuleTypes result(std::move(types));
  result.set_cpfg(true);
  return result;
}

ModuleId id_of(const ModuleTypes& types, const std::string& name, int count) {
  for (std::size_t id = mid::PredefinedCount; id < types.size(); ++id)
    if (types.name(static_cast<ModuleId>(id)) == name && types[static_cast<ModuleId>(id)].param_size == 4u * count)
      return static_cast<ModuleId>(id);
  ADD_FAILURE() << name << " with " << count << " parameters";
  return 0;
}

struct CpfgDecoding {
  explicit CpfgDecoding(const std::vector<std::pair<std::string, int>>& symbols,
                        turtle::TurtleSettings view = turtle::TurtleSettings{})
      : settings(std::move(view)), types(cpfg_types(symbols)), decoder(settings, types) {}
  // Decodes module `name` with `count` parameters; false when it makes no command.
  bool decode(const std::string& name, int count, const std::vector<unsigned char>& p = params()) {
    return decoder.decode(id_of(types, name, count), p.data(), 0, recorder);
  }

  turtle::TurtleSettings settings;
  ModuleTypes types;
  turtle::CpfgDecoder decoder;
  turtle::CommandRecorder recorder;
  const TurtleCommand& command = recorder.command;
};

TEST(CpfgDecoder, DefaultsComeFromTheViewFile) {
  turtle::TurtleSettings view;
  view.angle_increment = 30;
  view.width_increment = 0.5f;
  view.color_increment = 2;
  CpfgDecoding d({{"+", 0}, {"&", 1}, {"F", 0}, {"!", 0}, {",", 0}, {";", 1}}, view);
  ASSERT_TRUE(d.decode("+", 0));
  EXPECT_EQ(std::get<cmd::Turn>(d.command).degrees, 30.0f);
  ASSERT_TRUE(d.decode("&", 1, params(10.0f)));
  EXPECT_EQ(std::get<cmd::Turn>(d.command).axis, cmd::Axis::Left);
  EXPECT_EQ(std::get<cmd::Turn>(d.command).degrees, 10.0f);
  ASSERT_TRUE(d.decode("F", 0));
  EXPECT_EQ(std::get<cmd::Forward>(d.command).distance, 1.0f);  // the turtle's scale applies when executed
  ASSERT_TRUE(d.decode("!", 0));
  EXPECT_EQ(std::get<cmd::StepWidth>(d.command).by, -0.5f);
  ASSERT_TRUE(d.decode(",", 0));
  EXPECT_EQ(std::get<cmd::StepColor>(d.command).by, -2);
  EXPECT_EQ(std::get<cmd::StepColor>(d.command).wrap, cmd::ColorWrap::CpfgDown);
  // ;(600): wrapped once past 255, entry 88 of colormap 2.
  ASSERT_TRUE(d.decode(";", 1, params(600.0f)));
  EXPECT_EQ(std::get<cmd::SetColor>(d.command).index, 344);
}

TEST(CpfgDecoder, BracesArePolygonsOrCylinders) {
  CpfgDecoding d({{"{", 0}, {"{", 1}, {"}", 0}, {"}", 1}, {".", 1}, {"@o", 1}});
  ASSERT_TRUE(d.decode("{", 0));
  EXPECT_TRUE(std::holds_alternative<cmd::StartPolygon>(d.command));
  ASSERT_TRUE(d.decode("{", 1, params(3.0f)));
  EXPECT_EQ(std::get<cmd::StartCylinder>(d.command).type, 3);
  ASSERT_TRUE(d.decode("{", 1, params(9.0f)));
  EXPECT_EQ(std::get<cmd::StartCylinder>(d.command).type, 1);
  EXPECT_TRUE(std::get<cmd::StartCylinder>(d.command).unknown_type);
  ASSERT_TRUE(d.decode("}", 0));
  EXPECT_TRUE(std::get<cmd::EndPolygon>(d.command).textured);  // @Tx textures cpfg's polygons
  ASSERT_TRUE(d.decode("}", 1, params(2.0f)));
  EXPECT_EQ(std::get<cmd::EndCylinder>(d.command).type, 2);
  EXPECT_EQ(std::get<cmd::EndCylinder>(d.command).strips, 4);
  ASSERT_TRUE(d.decode(".", 1, params(2000.0f)));
  EXPECT_EQ(std::get<cmd::CylinderDot>(d.command).strips, 1000);
  // @o(d): d is the diameter.
  ASSERT_TRUE(d.decode("@o", 1, params(3.0f)));
  EXPECT_EQ(*std::get<cmd::Circle>(d.command).radius, 1.5f);
  EXPECT_TRUE(std::get<cmd::Circle>(d.command).facing_viewer);
}

TEST(CpfgDecoder, CommandsReadACharacterAModule) {
  // @Gc(3) read as @, G, c(3): one command, the last module's parameters.
  CpfgDecoding d({{"@", 0}, {"G", 0}, {"c", 1}, {"F", 0}});
  EXPECT_FALSE(d.decode("@", 0));
  EXPECT_FALSE(d.decode("G", 0));
  ASSERT_TRUE(d.decode("c", 1, params(3.0f)));
  EXPECT_EQ(std::get<cmd::CylinderPoint>(d.command).strips, 3);
  // @ then a module that makes no command with it: the module on its own.
  EXPECT_FALSE(d.decode("@", 0));
  ASSERT_TRUE(d.decode("F", 0));
  EXPECT_TRUE(std::holds_alternative<cmd::Forward>(d.command));
}

TEST(CpfgDecoder, MissingParametersAreNotes) {
  CpfgDecoding d({{"@R", 1}, {"@D", 0}, {"?P", 2}, {"@Dd", 0}, {"$", 0}});
  ASSERT_TRUE(d.decode("@R", 1, params(1.0f)));
  EXPECT_STREQ(std::get<cmd::Note>(d.command).text, " ignored: needs a heading");
  EXPECT_TRUE(std::get<cmd::Note>(d.command).shows_frame);
  ASSERT_TRUE(d.decode("@D", 0));
  EXPECT_STREQ(std::get<cmd::Note>(d.command).text, " ignored: needs a scale");
  ASSERT_TRUE(d.decode("?P", 2, params(0.0f, 0.0f)));
  EXPECT_EQ(std::get<cmd::Query>(d.command).count, 2);
  ASSERT_TRUE(d.decode("@Dd", 0));
  EXPECT_EQ(std::get<cmd::DivideScale>(d.command).by, 1.0f);
  ASSERT_TRUE(d.decode("$", 0));
  EXPECT_TRUE(std::holds_alternative<cmd::ReturnFromSubLsystem>(d.command));
}

TEST(CpfgDecoder, LabelsAreFormatted) {
  CpfgDecoding d({{"@L", 1}});
  const char* format = "n=%g";
  const auto p = params(format, 2.5f);
  ASSERT_TRUE(d.decoder.decode(*d.types.find("@L"), p.data(), 0, d.recorder));
  EXPECT_EQ(std::get<cmd::Label>(d.command).text, "n=2.5");
  EXPECT_TRUE(std::get<cmd::Label>(d.command).shown);
}

}  // namespace
}  // namespace sylva::test
