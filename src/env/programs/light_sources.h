// Directional light sources of chiba and takenaka: explicit ones from the
// parameter file, or chiba's sampled light sphere.
#pragma once

#include <vector>

#include "env/programs/light_geometry.h"

namespace sylva::env::light {

struct LightSource {
  Vec3 direction;  // unit vector from the lit object towards the source
  double intensity = 0;
};

// Directions are made unit length and intensities scaled to sum to 1
// (EnviroManual 3.2.2 and 3.2.3); the sum must be positive.
void normalize_sources(std::vector<LightSource>& sources);

// The number of rays the sky sphere is sampled with for a requested count:
// the least 8·k^4 (k a positive integer) not below `requested` (8, 128, 648,
// 2048, ...; EnviroManual 3.2.2).
int sky_sample_count(int requested);

// Unit directions covering the whole sphere evenly: each face of an
// octahedron whose vertices are the axes is cut into k^4 triangles (its edges
// into k^2 parts) and the centroid of each, pushed onto the sphere, is one
// direction. Half of them point up (+y), half down.
std::vector<Vec3> sphere_directions(int samples);

// The light sphere of chiba: the directions above, upper hemisphere (y > 0)
// sources all of one intensity or, with `cie_overcast`, following the CIE
// standard overcast sky (1 + 2 sin(elevation)) / 3; each lower hemisphere
// source has `lower_to_upper` times the mean upper intensity. Normalized.
std::vector<LightSource> sky_sources(int samples, double lower_to_upper, bool cie_overcast);

}  // namespace sylva::env::light
