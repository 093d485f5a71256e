// cpfg's camera, worked out by hand from the CPFG manual (8.1.2) and what
// cpfg's SetView and CalculateWindow do: the eye at vrp + (viewpoint - vrp) /
// scale, up world y made square to the view and turned by the twist (tenths
// of a degree), the box's projection filling the image in parallel, and
// gluPerspective(viewing angle) in perspective.
#include <gtest/gtest.h>

#include "geometry/camera.h"

namespace sylva {
namespace {

using geometry::Box;
using geometry::Camera;
using geometry::CpfgView;
using geometry::Vec3;
using geometry::ViewParameters;

ViewParameters cpfg_view(const CpfgView& v, bool perspective = false) {
  ViewParameters p;
  p.cpfg = v;
  p.perspective = perspective;
  return p;
}

void expect_pixel(const Camera& camera, Vec3 world, float x, float y) {
  Vec3 p = camera.to_pixels(world);
  EXPECT_NEAR(p.x, x, 1e-2) << "x of (" << world.x << "," << world.y << "," << world.z << ")";
  EXPECT_NEAR(p.y, y, 1e-2) << "y of (" << world.x << "," << world.y << "," << world.z << ")";
}

void expect_vec(Vec3 actual, Vec3 expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-6f);
  EXPECT_NEAR(actual.y, expected.y, 1e-6f);
  EXPECT_NEAR(actual.z, expected.z, 1e-6f);
}

TEST(CpfgCameraTest, UpIsWorldYSquareToTheViewAndTurnedByTheTwist) {
  CpfgView v;  // from (0,0,1) to the origin
  expect_vec(geometry::cpfg_view_up(v), {0, 1, 0});
  // Looking down y: y cannot be up; cpfg takes (-1,0,0) x n = -z.
  v.viewpoint = {0, 5, 0};
  expect_vec(geometry::cpfg_view_up(v), {0, 0, -1});
  // From the side (+x): y stays up.
  v.viewpoint = {1, 0, 0};
  expect_vec(geometry::cpfg_view_up(v), {0, 1, 0});
  // twist 900 = 90 degrees: across = (-1,0,0) turned by +90 about n = z is
  // (0,-1,0); up = across x n = (-1,0,0).
  v.viewpoint = {0, 0, 1};
  v.twist = 900;
  expect_vec(geometry::cpfg_view_up(v), {-1, 0, 0});
}

TEST(CpfgCameraTest, ParallelBoxFillsTheImageCentredOnItself) {
  CpfgView v;
  v.box = Box{{-2, 0, 0}, {2, 4, 0}};
  // The box is 4 x 4 around (0,2): it fills the square image exactly.
  Camera camera(cpfg_view(v), Box{}, 100, 100);
  expect_pixel(camera, {-2, 0, 0}, 0, 100);
  expect_pixel(camera, {2, 4, 0}, 100, 0);
  expect_pixel(camera, {0, 2, 0}, 50, 50);
  EXPECT_FLOAT_EQ(camera.pixels_per_unit(), 25);
  // scale factor 0.5 halves it: the window spans 8 units.
  v.scale = 0.5f;
  expect_pixel(Camera(cpfg_view(v), Box{}, 100, 100), {2, 4, 0}, 75, 25);
}

TEST(CpfgCameraTest, TheWiderSideOfTheImageGetsTheMargin) {
  CpfgView v;
  v.box = Box{{-1, -1, 0}, {1, 1, 0}};
  // 200 x 100: cpfg's aspect ratio 0.5, span = max(1, 1 / 0.5) = 2; the window
  // is x -2..2, y -1..1.
  Camera camera(cpfg_view(v), Box{}, 200, 100);
  expect_pixel(camera, {1, 1, 0}, 150, 0);
  expect_pixel(camera, {-1, -1, 0}, 50, 100);
}

TEST(CpfgCameraTest, TwistTurnsThePictureClockwise) {
  CpfgView v;
  v.twist = 900;
  v.box = Box{{0, -1, 0}, {4, 1, 0}};
  // Up is world -x, right world +y: the box is seen as x' -1..1, y' -4..0,
  // centred on (0,-2) with a span of 2.
  Camera camera(cpfg_view(v), Box{}, 100, 100);
  expect_pixel(camera, {4, 0, 0}, 50, 100);  // +x points down
  expect_pixel(camera, {0, 1, 0}, 75, 0);    // +y points right
}

TEST(CpfgCameraTest, ViewpointOffTheAxisLooksAtTheReferencePoint) {
  CpfgView v;
  v.viewpoint = {1, 0, 0};
  v.box = Box{{0, -1, -1}, {0, 1, 1}};
  // Looking along -x with y up, right is -z: (0,0,1) is on the left.
  Camera camera(cpfg_view(v), Box{}, 100, 100);
  expect_pixel(camera, {0, 0, 1}, 0, 50);
  expect_pixel(camera, {0, 1, -1}, 100, 0);
}

TEST(CpfgCameraTest, WithoutABoxTheModelIsFramedFromAtMostOneAndAtLeastZero) {
  // cpfg measures the model from a minimum of 1 and a maximum of 0: a model
  // at x, y in 2..4 is framed as 1..4.
  CpfgView v;
  Camera camera(cpfg_view(v), Box{{2, 2, 0}, {4, 4, 0}}, 100, 100);
  expect_pixel(camera, {1, 1, 0}, 0, 100);
  expect_pixel(camera, {4, 4, 0}, 100, 0);
}

TEST(CpfgCameraTest, PerspectiveUsesTheViewingAngleAndTheEyeNotTheBox) {
  CpfgView v;
  v.viewpoint = {0, 0, 10};
  v.viewing_angle = 90;
  v.front_distance = 1;
  v.back_distance = 100;
  v.box = Box{{-100, -100, -100}, {100, 100, 100}};  // ignored in perspective
  // At 10 units from the eye, tan(45) * 10 = 10 units reach the image's edge.
  Camera camera(cpfg_view(v, true), Box{{-10, -10, 0}, {10, 10, 0}}, 100, 100);
  expect_pixel(camera, {10, 0, 0}, 100, 50);
  expect_pixel(camera, {5, 5, 0}, 75, 25);
  EXPECT_FLOAT_EQ(camera.pixels_per_unit(), 5);
  // scale factor 2 brings the eye to 5 units away.
  v.scale = 2;
  expect_pixel(Camera(cpfg_view(v, true), Box{{-10, -10, 0}, {10, 10, 0}}, 100, 100), {5, 0, 0}, 100, 50);
}

TEST(CpfgCameraTest, ClippingPlanesAreAtTheFrontAndBackDistancesFromTheEye) {
  CpfgView v;  // the eye at z = 1, looking down -z
  v.front_distance = 0.5f;
  v.back_distance = 1.5f;
  v.box = Box{{-1, -1, -2}, {1, 1, 2}};
  Camera camera(cpfg_view(v), Box{{-1, -1, -2}, {1, 1, 2}}, 100, 100);
  // The model reaches from 3 (z = -2) to -1 (z = 2) units from the eye.
  EXPECT_FLOAT_EQ(camera.near_plane(), 0.5f);
  EXPECT_FLOAT_EQ(camera.far_plane(), 1.5f);
  // cpfg's default planes (+-100000) clip nothing: the camera keeps closer
  // ones around the model, which clip nothing either.
  v.front_distance = -100000;
  v.back_distance = 100000;
  Camera open(cpfg_view(v), Box{{-1, -1, -2}, {1, 1, 2}}, 100, 100);
  EXPECT_LE(open.near_plane(), -1);
  EXPECT_GE(open.far_plane(), 3);
  EXPECT_LT(open.far_plane() - open.near_plane(), 10);
}

}  // namespace
}  // namespace sylva
