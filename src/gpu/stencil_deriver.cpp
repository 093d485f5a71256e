#include "gpu/stencil_deriver.h"

#include <stdexcept>

#include "support/plugin_library.h"

namespace sylva::gpu {

std::vector<double> CpuStencilDeriver::derive(const std::vector<double>& points, int dim, const Stencil& s,
                                              int steps) {
  std::vector<double> from = points, to;
  const int w = s.width();
  for (int step = 0; step < steps; ++step) {
    const long n = static_cast<long>(from.size()) / dim;
    if (s.open) {
      if (n < s.min_points()) throw std::invalid_argument("an open curve of fewer points than its end rules read");
      to.assign(static_cast<std::size_t>(s.successors(n)) * dim, 0.0);
      auto combine = [&](double* out, const double* weights, long first) {
        for (int j = 0; j < s.end_width; ++j)
          for (int d = 0; d < dim; ++d) out[d] += weights[j] * from[(first + j) * dim + d];
      };
      for (int r = 0; r < s.head_rows; ++r) combine(&to[r * dim], &s.head[r * s.end_width], 0);
      const long inner = n - s.head_points - s.tail_points;
      for (long m = 0; m < inner; ++m)
        for (int i = 0; i < s.k; ++i) {
          double* out = &to[(s.head_rows + m * s.k + i) * dim];
          for (int j = 0; j < w; ++j) {
            const double cij = s.c[static_cast<std::size_t>(i) * w + j];
            if (cij == 0) continue;
            const double* p = &from[(s.head_points + m + j - s.left) * dim];
            for (int d = 0; d < dim; ++d) out[d] += cij * p[d];
          }
        }
      const long tail_at = s.head_rows + inner * s.k;
      for (int r = 0; r < s.tail_rows; ++r)
        combine(&to[(tail_at + r) * dim], &s.tail[r * s.end_width], n - s.end_width);
      from.swap(to);
      continue;
    }
    to.assign(static_cast<std::size_t>(n) * s.k * dim, 0.0);
    for (long q = 0; q < n; ++q)
      for (int i = 0; i < s.k; ++i) {
        double* out = &to[(static_cast<std::size_t>(q) * s.k + i) * dim];
        for (int j = 0; j < w; ++j) {
          const double cij = s.c[static_cast<std::size_t>(i) * w + j];
          if (cij == 0) continue;
          long idx = (q + j - s.left) % n;
          if (idx < 0) idx += n;
          const double* p = &from[static_cast<std::size_t>(idx) * dim];
          for (int d = 0; d < dim; ++d) out[d] += cij * p[d];
        }
      }
    from.swap(to);
  }
  return from;
}

StencilDeriver& gl_stencil_deriver() {
  return plugin_object<StencilDeriver>("libsylva_gl.so", "sylva_gl_stencil_deriver",
                                       "derives point-subdivision L-systems on the GPU");
}

}  // namespace sylva::gpu
