// The camera's framing, worked out by hand: where a box's corners land, which
// way is up, how perspective converges.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/camera.h"

namespace sylva {
namespace {

using geometry::Box;
using geometry::Camera;
using geometry::Vec3;
using geometry::ViewParameters;

Box square_box(float half, float depth = 0) { return Box{{-half, -half, -depth}, {half, half, depth}}; }

void expect_pixel(const Camera& camera, Vec3 world, float x, float y) {
  Vec3 p = camera.to_pixels(world);
  EXPECT_NEAR(p.x, x, 1e-3) << "x of (" << world.x << "," << world.y << "," << world.z << ")";
  EXPECT_NEAR(p.y, y, 1e-3) << "y of (" << world.x << "," << world.y << "," << world.z << ")";
}

TEST(CameraTest, SquareBoxFillsSquareImageUpright) {
  ViewParameters view;
  view.scale = 1;
  Camera camera(view, square_box(1, 1), 100, 100);
  EXPECT_FLOAT_EQ(camera.pixels_per_unit(), 50);
  expect_pixel(camera, {0, 0, 0}, 50, 50);
  expect_pixel(camera, {-1, -1, 1}, 0, 100);  // bottom left of the model is bottom left of the image
  expect_pixel(camera, {1, 1, 1}, 100, 0);
  expect_pixel(camera, {1, -1, -1}, 100, 100);
  expect_pixel(camera, {0, 1, 0}, 50, 0);  // y up on screen
  // Depth runs from the near side (z = 1, toward the eye) to the far side.
  float near = camera.to_pixels({0, 0, 1}).z, far = camera.to_pixels({0, 0, -1}).z;
  EXPECT_LT(near, far);
  EXPECT_GT(near, 0);
  EXPECT_LT(far, 1);
  EXPECT_LT(camera.near_plane(), camera.view_distance({0, 0, 1}));
  EXPECT_GT(camera.far_plane(), camera.view_distance({0, 0, -1}));
}

TEST(CameraTest, ScalePanAndAspect) {
  ViewParameters view;
  view.scale = 0.5f;
  Camera half(view, square_box(1), 100, 100);
  expect_pixel(half, {-1, -1, 0}, 25, 75);
  expect_pixel(half, {1, 1, 0}, 75, 25);

  view.scale = 1;
  view.pan = {1, 0, 0};  // the view centres on the box's right edge
  Camera panned(view, square_box(1), 100, 100);
  expect_pixel(panned, {1, 0, 0}, 50, 50);
  expect_pixel(panned, {0, 0, 0}, 0, 50);

  // A wide image: the square box fills the height, centred across.
  view.pan = {0, 0, 0};
  Camera wide(view, square_box(1), 200, 100);
  expect_pixel(wide, {-1, -1, 0}, 50, 100);
  expect_pixel(wide, {1, 1, 0}, 150, 0);
  // A wide box in a tall image fills the width.
  Camera tall(view, Box{{-2, -1, 0}, {2, 1, 0}}, 100, 300);
  EXPECT_FLOAT_EQ(tall.pixels_per_unit(), 25);
  expect_pixel(tall, {-2, 1, 0}, 0, 125);
}

TEST(CameraTest, ViewFileBoxOverridesSceneBounds) {
  ViewParameters view;
  view.scale = 1;
  view.box = Box{{0, 0, 0}, {10, 10, 0}};
  Camera camera(view, square_box(1), 100, 100);
  expect_pixel(camera, {0, 0, 0}, 0, 100);
  expect_pixel(camera, {10, 10, 0}, 100, 0);
}

TEST(CameraTest, MatricesFollowOpenGl) {
  ViewParameters view;
  view.scale = 1;
  Camera camera(view, square_box(1, 1), 100, 100);
  const auto& v = camera.view();
  // The eye goes to the origin, the box centre straight ahead (down -z).
  Vec3 e = camera.eye();
  EXPECT_NEAR(v[0] * e.x + v[4] * e.y + v[8] * e.z + v[12], 0, 1e-4);
  EXPECT_NEAR(v[2] * e.x + v[6] * e.y + v[10] * e.z + v[14], 0, 1e-4);
  EXPECT_LT(v[14], 0);  // the origin (the box centre) is in front: z < 0 in eye space
  EXPECT_FLOAT_EQ(v[15], 1);
  // Orthographic: x scale 2 / (right - left), the image is 2 units wide.
  const auto& p = camera.projection();
  EXPECT_NEAR(p[0], 1, 1e-6);
  EXPECT_NEAR(p[5], 1, 1e-6);
  EXPECT_FLOAT_EQ(p[11], 0);
  EXPECT_FLOAT_EQ(p[15], 1);
  // Near and far planes map to depth 0 and 1.
  Vec3 at_near = camera.eye() + camera.direction() * camera.near_plane();
  Vec3 at_far = camera.eye() + camera.direction() * camera.far_plane();
  EXPECT_NEAR(camera.to_pixels(at_near).z, 0, 1e-4);
  EXPECT_NEAR(camera.to_pixels(at_far).z, 1, 1e-4);
}

TEST(CameraTest, OtherDirectionsKeepUpUp) {
  ViewParameters view;
  view.scale = 1;
  view.dir = {1, 0, 0};  // looking along +x with y up: +z is on the right
  Camera side(view, square_box(1, 1), 100, 100);
  expect_pixel(side, {0, 0, 1}, 100, 50);
  expect_pixel(side, {0, 1, 0}, 50, 0);
  EXPECT_NEAR(geometry::length(side.right() - Vec3{0, 0, 1}), 0, 1e-6);

  view.dir = {0, -1, 0};  // up along the view: any orientation, but a finite one
  Camera down(view, square_box(1, 1), 100, 100);
  Vec3 p = down.to_pixels({1, 0, 1});
  EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
  EXPECT_NEAR(std::hypot(p.x - 50, p.y - 50), 50 * std::numbers::sqrt2, 1e-3);
}

// lpfg keeps |back - front| / 2 either side of the point looked at
// (Projection::SetVolume sets its half depth so; the manual describes the
// planes otherwise), so their order does not matter.
TEST(CameraTest, FrontAndBackDistances) {
  ViewParameters view;
  view.front_distance = -3;
  view.back_distance = 4;
  Camera parallel(view, square_box(1, 1), 100, 100);
  float centre = parallel.view_distance({0, 0, 0});
  EXPECT_NEAR(parallel.near_plane(), centre - 3.5f, 1e-4);
  EXPECT_NEAR(parallel.far_plane(), centre + 3.5f, 1e-4);
  view.front_distance = 1000;
  view.back_distance = -1000;
  Camera reversed(view, square_box(1, 1), 100, 100);
  EXPECT_NEAR(reversed.near_plane(), centre - 1000, 1e-2);
  EXPECT_NEAR(reversed.far_plane(), centre + 1000, 1e-2);

  view.perspective = true;
  view.front_distance = -1;
  view.back_distance = 1;
  Camera perspective(view, square_box(1, 1), 100, 100);
  centre = perspective.view_distance({0, 0, 0});
  EXPECT_NEAR(perspective.near_plane(), centre - 1, 1e-4);
  EXPECT_NEAR(perspective.far_plane(), centre + 1, 1e-4);
}

TEST(CameraTest, PerspectiveVanishes) {
  ViewParameters view;
  view.perspective = true;
  view.scale = 1;
  Camera camera(view, square_box(1, 1), 100, 100);
  expect_pixel(camera, {0, 0, 0}, 50, 50);
  // The near face looks bigger than the far face, and it is what fills the image.
  Vec3 near = camera.to_pixels({1, 1, 1}), far = camera.to_pixels({1, 1, -1});
  EXPECT_NEAR(near.x, 100, 1e-3);
  EXPECT_NEAR(near.y, 0, 1e-3);
  EXPECT_GT(far.x, 50);
  EXPECT_LT(far.x, near.x - 5);
  EXPECT_LT(near.z, far.z);
  // Parallel edges along the view converge on the centre.
  float previous = near.x;
  for (float z : {0.f, -10.f, -100.f, -10000.f}) {
    float x = camera.to_pixels({1, 1, z}).x;
    EXPECT_LT(x, previous);
    previous = x;
  }
  EXPECT_NEAR(previous, 50, 0.5);
  EXPECT_GT(camera.pixels_per_unit_at({0, 0, 1}), camera.pixels_per_unit());
  EXPECT_LT(camera.pixels_per_unit_at({0, 0, -1}), camera.pixels_per_unit());
  EXPECT_FLOAT_EQ(camera.projection()[11], -1);

  // Going further (shift) flattens the perspective without changing the frame.
  view.shift = 10;
  Camera distant(view, square_box(1, 1), 100, 100);
  expect_pixel(distant, {1, 1, 1}, 100, 0);
  EXPECT_GT(distant.to_pixels({1, 1, -1}).x, far.x);
}

}  // namespace
}  // namespace sylva
