#include "turtle/tropisms.h"

#include <cmath>

namespace sylva::turtle {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

}  // namespace

Tropisms::Tropisms(const TurtleSettings& settings) : settings_(settings) {
  for (const Tropism& t : settings.tropisms) elasticity_.push_back(t.elasticity);
  elasticity_.push_back(settings.simple_tropism.elasticity);
  update_bending();
}

void Tropisms::bend(Frame& f) const {
  const std::size_t n = settings_.tropisms.size();
  for (std::size_t k = 0; k <= n; ++k) {
    const float e = elasticity_[k];
    if (e == 0) continue;
    const Tropism& t = k < n ? settings_.tropisms[k] : settings_.simple_tropism;
    const float strength = length(t.direction);
    if (strength < kEpsilon) continue;
    const Vec3 toward = t.direction / strength;
    const float intensity = t.intensity;
    if (t.torque) {
      // Twist around H, turning U toward T's part across H.
      const Vec3 across = toward - f.heading * dot(toward, f.heading);
      const Vec3 axis = cross(f.up, across);
      const float s = length(axis);
      if (s < 1e-7f) continue;
      const double angle = static_cast<double>(e) * intensity * strength * s;
      f.rotate(axis / s, static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
    } else {
      Vec3 axis = cross(f.heading, toward);
      const float s = length(axis);
      const double phi = std::atan2(static_cast<double>(s), static_cast<double>(dot(f.heading, toward)));
      const double angle = static_cast<double>(e) * intensity * strength * std::sin(phi - t.angle * kDegrees);
      if (s < 1e-7f) {
        if (t.angle == 0) continue;  // already along T
        axis = f.left;               // along T but meant to keep an angle to it: leave T in any direction
      } else {
        axis = axis / s;
      }
      f.rotate(axis, static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
    }
  }
  f.orthonormalize();
}

std::optional<float> Tropisms::set(int id, float value, bool relative) {
  if (id < 1 || static_cast<std::size_t>(id) > settings_.tropisms.size()) return std::nullopt;
  float& e = elasticity_[static_cast<std::size_t>(id) - 1];
  e = relative ? e + value : value;
  update_bending();
  return e;
}

void Tropisms::set_simple(float value) {
  elasticity_.back() = value;
  update_bending();
}

}  // namespace sylva::turtle
