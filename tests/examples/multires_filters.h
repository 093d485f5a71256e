// The multiresolution notes' filters (part 3, appendices A and B) as dense
// matrices, built independently of the example models: the curve tests
// check the models' analysis and synthesis against them.
#pragma once

#include "examples/plane_points.h"

namespace sylva::test::examples {

// The notes' filters for a level with m coarse points.
struct Filters {
  Matrix a, b, p, q;  // c = A f, d = B f, f = P c + Q d
};

// Closed: n = 2m fine points, c_i at f_{2i}, d_i at f_{2i+1} (equations 8-10,
// indices modulo the size).
inline Filters closed_filters(int m) {
  const int n = 2 * m;
  auto f = [n](int i) { return static_cast<std::size_t>(((i % n) + n) % n); };
  auto c = [m](int i) { return static_cast<std::size_t>(((i % m) + m) % m); };
  Filters r{zeros(m, n), zeros(m, n), zeros(n, m), zeros(n, m)};
  for (int i = 0; i < m; ++i) {
    r.a[i][f(2 * i - 1)] += -0.5, r.a[i][f(2 * i)] += 2, r.a[i][f(2 * i + 1)] += -0.5;
    const double bw[5] = {0.25, -1, 1.5, -1, 0.25};
    for (int k = 0; k < 5; ++k) r.b[i][f(2 * i - 1 + k)] += bw[k];
    const std::size_t even = f(2 * i), odd = f(2 * i + 1);
    r.p[even][c(i - 1)] += 0.125, r.p[even][c(i)] += 0.75, r.p[even][c(i + 1)] += 0.125;
    r.q[even][c(i - 1)] += 0.25, r.q[even][c(i)] += 0.25;
    r.p[odd][c(i)] += 0.5, r.p[odd][c(i + 1)] += 0.5;
    r.q[odd][c(i)] += 1;
  }
  return r;
}

// Open: n = 2m - 3 fine points; c_0 = f_0, c_1 from f_1, c_i from f_{2i-1},
// c_{m-2} from f_{n-2}, c_{m-1} = f_{n-1}; detail d_j (j = 1 .. m-3, row
// j - 1) at f_{2j}. Appendix B's end rows, mirrored at the right end.
inline Filters open_filters(int m) {
  const int n = 2 * m - 3, details = m - 3;
  Filters r{zeros(m, n), zeros(details, n), zeros(n, m), zeros(n, details)};
  auto mirror_f = [n](int i) { return n - 1 - i; };
  auto mirror_c = [m](int i) { return m - 1 - i; };
  auto mirror_d = [m](int j) { return m - 2 - j; };  // d_j <-> d_{m-2-j}
  // the end rows of Appendix B, given for the left end, set at both ends
  for (int side = 0; side < 2; ++side) {
    auto F = [&](int i) { return static_cast<std::size_t>(side ? mirror_f(i) : i); };
    auto C = [&](int i) { return static_cast<std::size_t>(side ? mirror_c(i) : i); };
    auto D = [&](int j) { return static_cast<std::size_t>((side ? mirror_d(j) : j) - 1); };
    r.a[C(0)][F(0)] = 1;
    r.a[C(1)][F(0)] = -1, r.a[C(1)][F(1)] = 2;
    const double bw[5] = {0.75, -1.5, 1.125, -0.5, 0.125};
    for (int k = 0; k < 5; ++k) r.b[D(1)][F(k)] = bw[k];
    r.p[F(0)][C(0)] = 1;
    r.p[F(1)][C(0)] = 0.5, r.p[F(1)][C(1)] = 0.5;
    r.p[F(2)][C(1)] = 0.75, r.p[F(2)][C(2)] = 0.25, r.q[F(2)][D(1)] = 1;
    r.p[F(3)][C(1)] = 0.1875, r.p[F(3)][C(2)] = 0.6875, r.p[F(3)][C(3)] = 0.125;
    r.q[F(3)][D(1)] = 0.25, r.q[F(3)][D(2)] = 0.25;
  }
  for (int i = 2; i <= m - 3; ++i) {  // coarse points inside
    const std::size_t row = static_cast<std::size_t>(i), fi = static_cast<std::size_t>(2 * i - 1);
    r.a[row][fi - 1] = -0.5, r.a[row][fi] = 2, r.a[row][fi + 1] = -0.5;
    if (i >= 3 && i <= m - 4) {  // fine points f_{2i-1} inside
      r.p[fi][row - 1] = 0.125, r.p[fi][row] = 0.75, r.p[fi][row + 1] = 0.125;
      r.q[fi][row - 2] = 0.25, r.q[fi][row - 1] = 0.25;
    }
  }
  for (int j = 2; j <= m - 4; ++j) {  // details inside
    const std::size_t row = static_cast<std::size_t>(j - 1), fj = static_cast<std::size_t>(2 * j);
    const double bw[5] = {0.25, -1, 1.5, -1, 0.25};
    for (int k = 0; k < 5; ++k) r.b[row][fj - 2 + static_cast<std::size_t>(k)] = bw[k];
    r.p[fj][static_cast<std::size_t>(j)] = 0.5, r.p[fj][static_cast<std::size_t>(j + 1)] = 0.5;
    r.q[fj][row] = 1;
  }
  return r;
}

}  // namespace sylva::test::examples
