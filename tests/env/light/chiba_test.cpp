// chiba (EnviroManual 3.2.2): light reaching spheres through other spheres.
// Expected values are worked out by hand in the comments, or by testing every
// pair of spheres directly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "env/light/light_test_support.h"
#include "env/programs/light_sources.h"
#include "env/programs/programs.h"

namespace sylva::test::light {
namespace {

using env::make_chiba;

// One light straight above (+y), transmittance 0.5.
const std::string kFromAbove = "grid size: 8 8 8\nsource direction: 0 1 0 1\ntransmittance: 0.5\n";

std::unique_ptr<env::Field> chiba(const std::string& name, const std::string& text) {
  return make_chiba(invocation_with_file(name, "chiba", "chiba.par", text));
}

TEST(ChibaTest, SphereDirectlyAboveHalvesTheLight) {
  auto field = chiba("chiba-above", kFromAbove);
  // The ray from A goes through B's centre: 2 of B's diameter 2 -> 0.5^1.
  std::vector<env::Query> q{query_at(0, 0, 0, {1, 0, 0, 0}), query_at(0, 5, 0, {1, 0, 0, 0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[1].value[0], 1.0f);  // nothing above B; A below does not shade it
  // The brightest direction of a single source is the source's.
  for (int i : {0, 1}) {
    EXPECT_FLOAT_EQ(a[i].value[1], 0.0f);
    EXPECT_FLOAT_EQ(a[i].value[2], 1.0f);
    EXPECT_FLOAT_EQ(a[i].value[3], 0.0f);
    EXPECT_EQ(a[i].set.count(), 4u);
  }
}

TEST(ChibaTest, OneParameterModulesGetOnlyTheLight) {
  auto field = chiba("chiba-one", kFromAbove);
  std::vector<env::Query> q{query_at(0, 0, 0, {1}), query_at(0, 5, 0, {1})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 0.5f);
  EXPECT_EQ(a[0].set.count(), 1u);
}

TEST(ChibaTest, ChordThroughAnOffsetSphere) {
  auto field = chiba("chiba-chord", kFromAbove);
  // B 0.6 to the side: the chord is 2 sqrt(1 - 0.36) = 1.6, 0.8 of B's diameter.
  std::vector<env::Query> q{query_at(0, 0, 0, {1}), query_at(0.6f, 5, 0, {1}), query_at(3, 0, 0, {1})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], std::pow(0.5f, 0.8f));
  EXPECT_FLOAT_EQ(a[2].value[0], 1.0f);  // 2.4 to the side of B: missed
}

TEST(ChibaTest, SeveralSpheresMultiply) {
  auto field = chiba("chiba-several", kFromAbove);
  // Through the centres of B (radius 1) and C (radius 2): 0.5 * 0.5; D, radius
  // 1 at 0.6 to the side of the ray from A, adds 0.5^0.8.
  std::vector<env::Query> q{query_at(0, 0, 0, {1}), query_at(0, 4, 0, {1}), query_at(0, 10, 0, {2}),
                            query_at(0, 20, 0.6f, {1})};
  auto a = answer_all(*field, q);
  EXPECT_NEAR(a[0].value[0], 0.25 * std::pow(0.5, 0.8), 1e-6);
  // From B: C fully, D's chord 2 sqrt(1 - 0.36).
  EXPECT_NEAR(a[1].value[0], 0.5 * std::pow(0.5, 0.8), 1e-6);
}

TEST(ChibaTest, ZeroRadiusTakesTheDefault) {
  auto field = chiba("chiba-default", kFromAbove + "radius: 2\n");
  // B has the default radius 2 and lies 1.5 to the side: chord
  // 2 sqrt(4 - 2.25) = 2.6458 over diameter 4.
  std::vector<env::Query> q{query_at(0, 0, 0, {1}), query_at(1.5f, 6, 0, {0})};
  EXPECT_NEAR(answer_all(*field, q)[0].value[0], std::pow(0.5, 2 * std::sqrt(1.75) / 4), 1e-6);
}

TEST(ChibaTest, BeamRadiusWidensTheRay) {
  auto field = chiba("chiba-beam", kFromAbove + "beam radius: 0.5\n");
  // A (radius 1) tests B (radius 1, 1.2 to the side) as a sphere of radius
  // 1 + 0.5 * 1 = 1.5: chord 2 sqrt(2.25 - 1.44) = 1.8 over B's diameter 2.
  std::vector<env::Query> q{query_at(0, 0, 0, {1}), query_at(1.2f, 5, 0, {1})};
  EXPECT_NEAR(answer_all(*field, q)[0].value[0], std::pow(0.5, 0.9), 1e-6);
}

TEST(ChibaTest, EstimatedIntersectionAreaIsTheCoveredPartOfTheDisk) {
  auto field = chiba("chiba-area", kFromAbove + "estimate intersection area: on\n");
  // Unit disks 1 apart overlap in 2 acos(1/2) - (1/2) sqrt(3) = 1.2284, which
  // is 0.39100 of A's disk; the light is multiplied by 0.5^0.391.
  double lens = 2 * std::acos(0.5) - 0.5 * std::sqrt(3.0);
  std::vector<env::Query> q{query_at(0, 0, 0, {1}), query_at(1, 5, 0, {1}), query_at(0, -5, 0, {3})};
  auto a = answer_all(*field, q);
  EXPECT_NEAR(a[0].value[0], std::pow(0.5, lens / std::numbers::pi), 1e-6);
  // The big sphere C below A does not shade A (it is behind A's ray). C's own
  // disk (radius 3) has A's and B's unit disks wholly inside it: each covers
  // 1/9 of it.
  EXPECT_NEAR(a[2].value[0], std::pow(0.5, 2.0 / 9), 1e-6);
}

TEST(ChibaTest, SourcesAreNormalizedAndTheBrightestDirectionIsTheirWeightedSum) {
  auto field = chiba("chiba-sources",
                     "grid size: 4 4 4\ntransmittance: 0.5\nsource direction: 0 2 0 3\nsource direction: 5 0 0 1\n");
  // Intensities 3 and 1 become 0.75 and 0.25. B above A halves the first.
  std::vector<env::Query> q{query_at(0, 0, 0, {1, 0, 0, 0}), query_at(0, 5, 0, {1, 0, 0, 0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 0.625f);
  double x = 0.25, y = 0.375, n = std::hypot(x, y);
  EXPECT_NEAR(a[0].value[1], x / n, 1e-6);
  EXPECT_NEAR(a[0].value[2], y / n, 1e-6);
  EXPECT_FLOAT_EQ(a[1].value[0], 1.0f);
  EXPECT_NEAR(a[1].value[1], 0.25 / std::hypot(0.25, 0.75), 1e-6);
}

TEST(ChibaTest, SkySampleCountIsEightKToTheFourth) {
  EXPECT_EQ(env::light::sky_sample_count(1), 8);
  EXPECT_EQ(env::light::sky_sample_count(8), 8);
  EXPECT_EQ(env::light::sky_sample_count(9), 128);
  EXPECT_EQ(env::light::sky_sample_count(128), 128);
  EXPECT_EQ(env::light::sky_sample_count(129), 648);
}

TEST(ChibaTest, SkyDirectionsCoverTheSphereEvenly) {
  for (int samples : {8, 128, 648}) {
    auto directions = env::light::sphere_directions(samples);
    ASSERT_EQ(directions.size(), static_cast<std::size_t>(samples));
    int up = 0;
    double sx = 0, sy = 0, sz = 0;
    for (auto d : directions) {
      EXPECT_NEAR(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), 1.0, 1e-12);
      up += d.y > 0;
      sx += d.x, sy += d.y, sz += d.z;
    }
    EXPECT_EQ(up, samples / 2);
    // The octahedron's symmetry: opposite directions cancel.
    EXPECT_NEAR(sx, 0, 1e-9);
    EXPECT_NEAR(sy, 0, 1e-9);
    EXPECT_NEAR(sz, 0, 1e-9);
  }
  // The 8 face centres of the octahedron.
  auto eight = env::light::sphere_directions(8);
  for (auto d : eight) {
    EXPECT_NEAR(std::abs(d.x), 1 / std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(std::abs(d.y), 1 / std::sqrt(3.0), 1e-12);
  }
}

TEST(ChibaTest, SkyIntensities) {
  // 64 upper sources of 1 and 64 lower ones of 0.7, scaled to sum to 1.
  auto sky = env::light::sky_sources(128, 0.7, false);
  for (const auto& s : sky) EXPECT_NEAR(s.intensity, (s.direction.y > 0 ? 1.0 : 0.7) / (64 * 1.7), 1e-12);
  // CIE overcast sky: upper intensities follow (1 + 2 sin(elevation)) / 3.
  auto cie = env::light::sky_sources(128, 0.7, true);
  double upper_sum = 0;
  for (const auto& s : cie)
    if (s.direction.y > 0) upper_sum += (1 + 2 * s.direction.y) / 3;
  double lower = 0.7 * upper_sum / 64;
  double total = upper_sum + 64 * lower;
  for (const auto& s : cie) {
    double expected = s.direction.y > 0 ? (1 + 2 * s.direction.y) / 3 : lower;
    EXPECT_NEAR(s.intensity, expected / total, 1e-12);
  }
}

TEST(ChibaTest, SphereAloneUnderTheSkyGetsAllLightFromAbove) {
  auto field = chiba("chiba-alone", "transmittance: 0.5\n");
  std::vector<env::Query> q{query_at(1, 2, 3, {0, 0, 0, 0})};
  auto a = answer_all(*field, q);
  EXPECT_NEAR(a[0].value[0], 1.0, 1e-6);
  // Upper sources are brighter and the sphere of directions is symmetric.
  EXPECT_NEAR(a[0].value[1], 0.0, 1e-6);
  EXPECT_NEAR(a[0].value[2], 1.0, 1e-6);
  EXPECT_NEAR(a[0].value[3], 0.0, 1e-6);
}

TEST(ChibaTest, SphereInsideABigSphereSeesItInEveryDirection) {
  auto field = chiba("chiba-inside", "transmittance: 0.5\nnumber of samples: 100\n");
  // A (radius 10) and B (radius 1) share a centre. Every ray from there runs
  // 10 inside A, half its diameter, and 1 inside B, half its diameter: each
  // ray, and so the whole sky, is multiplied by 0.5^0.5 for each.
  std::vector<env::Query> q{query_at(0, 0, 0, {10}), query_at(0, 0, 0, {1})};
  auto a = answer_all(*field, q);
  EXPECT_NEAR(a[1].value[0], std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(a[0].value[0], std::sqrt(0.5), 1e-6);
}

// Every pair of spheres tested directly, by the formula of the manual.
double light_by_every_pair(const std::vector<env::Query>& q, std::size_t i, double t, double beam,
                           const std::vector<std::array<double, 4>>& sources) {
  double total = 0;
  auto at = [&](std::size_t k) {
    return std::array<double, 3>{q[k].turtle.position[0], q[k].turtle.position[1], q[k].turtle.position[2]};
  };
  for (const auto& s : sources) {
    double n = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    std::array<double, 3> d{s[0] / n, s[1] / n, s[2] / n};
    double intensity = s[3];
    for (std::size_t j = 0; j < q.size(); ++j) {
      if (j == i) continue;
      std::array<double, 3> a = at(i), b = at(j);
      double w[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      double along = w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
      double h2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - along * along;
      double r = q[j].module.parameters[0];
      double big = r + beam * q[i].module.parameters[0];
      if (h2 >= big * big) continue;
      double half = std::sqrt(big * big - h2);
      double from = std::max(0.0, along - half), to = along + half;
      if (to > from) intensity *= std::pow(t, (to - from) / (2 * r));
    }
    total += intensity;
  }
  return total;
}

TEST(ChibaTest, GridGivesTheSameAnswerAsTestingEveryPair) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-20, 20), radius(0.3f, 3);
  std::vector<env::Query> q;
  for (int i = 0; i < 400; ++i) q.push_back(query_at(coordinate(random), coordinate(random), coordinate(random),
                                                    {radius(random)}));
  std::vector<std::array<double, 4>> sources{{0, 1, 0, 0.5}, {0.3, 1, -0.2, 0.3}, {-1, 0.4, 0.7, 0.2}};
  auto field = chiba("chiba-pairs", "grid size: 16 9 5\ntransmittance: 0.3\nbeam radius: 0.25\n"
                                    "source direction: 0 1 0 0.5\nsource direction: 0.3 1 -0.2 0.3\n"
                                    "source direction: -1 0.4 0.7 0.2\n");
  auto a = answer_all(*field, q);
  for (std::size_t i = 0; i < q.size(); ++i)
    EXPECT_NEAR(a[i].value[0], light_by_every_pair(q, i, 0.3, 0.25, sources), 2e-5) << i;
}

// Spheres crowded into three crowns, so that every ray passes many others
// and the grid cells hold long lists.
std::vector<env::Query> crowded_crowns(int count) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1, 1), radius(0.4f, 1.6f);
  std::vector<env::Query> q;
  for (int i = 0; i < count; ++i) {
    float x, y, z;
    do {
      x = unit(random), y = unit(random), z = unit(random);
    } while (x * x + y * y + z * z > 1);
    float crown = static_cast<float>(i % 3);
    q.push_back(query_at(9 * crown + 7 * x, 7 * y + 2 * crown, 7 * z, {radius(random)}));
  }
  return q;
}

const std::string kFiveSources = "source direction: 0 1 0 0.3\nsource direction: 0.3 1 -0.2 0.2\n"
                                 "source direction: -1 0.4 0.7 0.2\nsource direction: 1 0.1 0 0.2\n"
                                 "source direction: 0.2 -1 0.5 0.1\n";
const std::vector<std::array<double, 4>> kFiveSourceList{
    {0, 1, 0, 0.3}, {0.3, 1, -0.2, 0.2}, {-1, 0.4, 0.7, 0.2}, {1, 0.1, 0, 0.2}, {0.2, -1, 0.5, 0.1}};

TEST(ChibaTest, CrowdedGridGivesTheSameAnswerAsTestingEveryPair) {
  std::vector<env::Query> q = crowded_crowns(3000);
  auto field = chiba("chiba-crowded", "grid size: 8 8 8\ntransmittance: 0.7\nbeam radius: 0.5\n" + kFiveSources);
  auto a = answer_all(*field, q);
  for (std::size_t i = 0; i < q.size(); ++i)
    EXPECT_NEAR(a[i].value[0], light_by_every_pair(q, i, 0.7, 0.5, kFiveSourceList), 2e-5) << i;
}

// The same with estimated intersection areas: each sphere ahead dims the ray
// by the part of the shooting sphere's disk that its own disk covers.
double area_light_by_every_pair(const std::vector<env::Query>& q, std::size_t i, double t,
                                const std::vector<std::array<double, 4>>& sources) {
  auto lens = [](double a, double b, double d) {
    if (d >= a + b) return 0.0;
    if (d <= std::abs(a - b)) return std::numbers::pi * std::min(a, b) * std::min(a, b);
    double alpha = std::acos((d * d + a * a - b * b) / (2 * d * a));
    double beta = std::acos((d * d + b * b - a * a) / (2 * d * b));
    return a * a * (alpha - std::sin(2 * alpha) / 2) + b * b * (beta - std::sin(2 * beta) / 2);
  };
  double total = 0;
  for (const auto& s : sources) {
    double n = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    double exponent = 0;
    for (std::size_t j = 0; j < q.size(); ++j) {
      if (j == i) continue;
      double w[3];
      for (int k = 0; k < 3; ++k) w[k] = double(q[j].turtle.position[k]) - double(q[i].turtle.position[k]);
      double along = (w[0] * s[0] + w[1] * s[1] + w[2] * s[2]) / n;
      if (along <= 0) continue;
      double h2 = std::max(0.0, w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - along * along);
      double a = q[i].module.parameters[0], b = q[j].module.parameters[0];
      exponent += lens(a, b, std::sqrt(h2)) / (std::numbers::pi * a * a);
    }
    total += s[3] * std::pow(t, exponent);
  }
  return total;
}

TEST(ChibaTest, CrowdedGridWithAreasGivesTheSameAnswerAsTestingEveryPair) {
  std::vector<env::Query> q = crowded_crowns(3000);
  auto field = chiba("chiba-crowded-area",
                     "grid size: 8 8 8\ntransmittance: 0.7\nestimate intersection area: on\n" + kFiveSources);
  auto a = answer_all(*field, q);
  for (std::size_t i = 0; i < q.size(); ++i)
    EXPECT_NEAR(a[i].value[0], area_light_by_every_pair(q, i, 0.7, kFiveSourceList), 2e-5) << i;
}

TEST(ChibaTest, QueryErrors) {
  auto field = chiba("chiba-query-errors", kFromAbove);
  std::vector<env::Query> q{query_at(0, 0, 0, {-1})};
  EXPECT_NE(error_of([&] { answer_all(*field, q); }).find("expected 0 (the default radius) or more"),
            std::string::npos);
  q[0].module.parameters = {1};
  q[0].turtle.position_count = 0;
  EXPECT_NE(error_of([&] { answer_all(*field, q); }).find("turtle position: %g %g %g"), std::string::npos);
}

std::string chiba_error(const std::string& text) {
  auto invocation = invocation_with_file("chiba-errors", "chiba", "chiba.par", text);
  std::string message = error_of([&] { make_chiba(invocation); });
  std::string prefix = (invocation.directory / "chiba.par").string();
  EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
  return message.substr(std::min(message.size(), prefix.size()));
}

TEST(ChibaTest, ParameterFileErrors) {
  EXPECT_EQ(chiba_error("grid size: 64 64\n"),
            ":1:17: error: chiba: expected 3 numbers after 'grid size:' (voxels along x, y and z), found 2");
  EXPECT_EQ(chiba_error("grid size: 64 64 0\n"),
            ":1:18: error: chiba: expected a positive whole number (voxels along x, y and z), found 0");
  EXPECT_EQ(chiba_error("transmittance: 0.6\nlower to upper ratio: 2\n"),
            ":2:23: error: chiba: expected the ratio of lower to upper hemisphere intensity between 0 and 1, found 2");
  EXPECT_EQ(chiba_error("source direction: 0 0 0 1\n"),
            ":1:19: error: chiba: expected a direction other than 0 0 0");
  EXPECT_EQ(chiba_error("source direction: 0 1 0\n"),
            ":1:24: error: chiba: expected 4 numbers after 'source direction:' (direction x y z and intensity), "
            "found 3");
  EXPECT_EQ(chiba_error("source direction: 0 1 0 0\n"), ":1:19: error: chiba: the sources' intensities add up to 0");
  EXPECT_EQ(chiba_error("use CIE formula: sometimes\n"),
            ":1:18: error: chiba: expected yes or no (also on/off) after 'use cie formula:'");
  EXPECT_EQ(chiba_error("radius: -1\n"), ":1:9: error: chiba: expected the default sphere radius of 0 or more, found -1");
  std::string unknown = chiba_error("grid size: 4 4 4\nsamples: 128\n");
  EXPECT_EQ(unknown.rfind(":2:1: error: chiba: unknown command 'samples:'; expected one of 'grid size:', ", 0), 0u)
      << unknown;
}

}  // namespace
}  // namespace sylva::test::light
