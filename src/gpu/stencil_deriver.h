// Point-subdivision L-systems (Chaikin, cubic B-spline, four-point, ...):
// ring L-systems whose one production replaces every point by k points, each
// an affine combination of the point and its neighbours (Lipp, Wonka,
// Wimmer / Prusinkiewicz et al., "Generating subdivision curves with
// L-systems on a GPU", algorithm 1). Such a step is a stencil: output
// point q·k + i is sum_j c[i][j] · p[(q + j - left) mod n].
//
// StencilDeriver is the narrow interface both the CPU (here) and the GPU
// (the GL plugin, render/gl_stencil.cpp) derive through.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace sylva::gpu {

struct Stencil {
  int k = 0;       // points produced per point
  int left = 0;    // neighbours read on the left (offsets -left .. right)
  int right = 0;   // neighbours read on the right
  std::vector<double> c;  // k rows of width() coefficients; column j is offset j - left
  int width() const { return left + 1 + right; }
  double at(int i, int offset) const { return c[static_cast<std::size_t>(i) * width() + offset + left]; }

  // Open curves (the paper's L-systems 3 and 4: other rules next to the
  // ends): the first head_points points make head_rows points of their own,
  // each a combination of points 0 .. end_width - 1 (rows of `head`); the
  // last tail_points make tail_rows (rows of `tail`, over the last end_width
  // points); every point between makes k by the stencil above, which there
  // never reaches past the ends. Closed (a ring) when !open.
  bool open = false;
  int head_points = 0, tail_points = 0, head_rows = 0, tail_rows = 0, end_width = 0;
  std::vector<double> head, tail;  // head_rows (tail_rows) rows of end_width weights
  // Points after one step from n.
  long successors(long n) const {
    return open ? head_rows + static_cast<long>(k) * (n - head_points - tail_points) + tail_rows : k * n;
  }
  // The fewest points the stencil applies to.
  long min_points() const {
    return open ? std::max<long>({head_points + tail_points, end_width, 1}) : width();
  }
};

class StencilDeriver {
 public:
  virtual ~StencilDeriver() = default;
  // `points`: n points of `dim` coordinates (1..4) each, a closed ring (or an
  // open curve, stencil.open). Returns the points after `steps` steps, in order.
  virtual std::vector<double> derive(const std::vector<double>& points, int dim, const Stencil& stencil,
                                     int steps) = 0;
  virtual std::string name() const = 0;
};

// In doubles, on the CPU.
class CpuStencilDeriver : public StencilDeriver {
 public:
  std::vector<double> derive(const std::vector<double>& points, int dim, const Stencil& stencil,
                             int steps) override;
  std::string name() const override { return "cpu"; }
};

// The GPU one: fragment shaders over float textures through OpenGL (OSMesa)
// in libsylva_gl.so, opened on first use. Throws ModelError if the plugin or
// its OpenGL context cannot be had.
StencilDeriver& gl_stencil_deriver();

}  // namespace sylva::gpu

// The GL plugin's factory.
extern "C" __attribute__((visibility("default"))) sylva::gpu::StencilDeriver* sylva_gl_stencil_deriver();
