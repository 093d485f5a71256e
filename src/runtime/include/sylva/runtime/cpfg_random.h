// cpfg's random functions (CPFG manual 5.2), as cpfg computes them
// (cpfg/utility.c). They draw from their own erand48 stream, apart from the
// stream that chooses among stochastic productions (seed:): it starts at
// {0x330E, 0, 0}, srand(s) restarts it at {0x330E, s & 0xFFFF, s >> 16}, and a
// homomorphism with a seed: of its own swaps in a stream of its own while
// its productions are applied.
#pragma once

#include <cmath>
#include <cstdint>

#include "sylva/abi.h"

namespace sylva::rt::cpfg {

// One erand48 state, xsubi[2] << 32 | xsubi[1] << 16 | xsubi[0].
struct Stream {
  std::uint64_t x = 0x330E;
  double next() { return ::sylva::abi::next_erand48(x); }
  // {0x330E, s & 0xFFFF, (s >> 16) & 0xFFFF}, as srand() and a homomorphism's seed set it.
  static std::uint64_t seeded(long s) {
    const std::uint64_t u = static_cast<std::uint64_t>(s);
    return ((u >> 16) & 0xFFFF) << 32 | (u & 0xFFFF) << 16 | 0x330E;
  }
};

struct Random {
  Stream stream;
  // nran's second normal value, kept for the next call. cpfg starts with
  // "one kept" and none computed: its first nran before any srand returns
  // the mean itself.
  bool have_kept = true;
  double kept = 0;

  void srand(double seed) {
    stream.x = Stream::seeded(static_cast<long>(seed));
    have_kept = false;
  }
  double ran(double range) { return stream.next() * range; }
  // Marsaglia's polar method, two values at a time.
  double nran(double mean, double sd) {
    if (have_kept) {
      have_kept = false;
      return kept * sd + mean;
    }
    double v1, v2, rsq;
    do {
      v1 = 2.0 * stream.next() - 1.0;
      v2 = 2.0 * stream.next() - 1.0;
      rsq = v1 * v1 + v2 * v2;
    } while (rsq >= 1.0 || rsq == 0.0);
    const double fac = std::sqrt(-2.0 * std::log(rsq) / rsq);
    kept = v1 * fac;
    have_kept = true;
    return v2 * fac * sd + mean;
  }
  // A beta(a, b) variate by Cheng's rejection method.
  double bran(double a, double b) {
    const double s = a + b;
    const double lambda = std::fmin(a, b) <= 1 ? std::fmin(a, b) : std::sqrt((2 * a * b - s) / (s - 2));
    const double u = a + lambda;
    double ym, u1, u2, v;
    do {
      do u1 = stream.next();
      while (u1 == 0);
      do u2 = stream.next();
      while (u2 == 0);
      v = (1 / lambda) * std::log(u1 / (1 - u1));
      ym = a * std::exp(v);
    } while (s * std::log(s / (b + ym)) + u * v - std::log(4.0) < std::log(u1 * u1 * u2));
    return ym / (b + ym);
  }
  // How many of n draws fall at or below p.
  double biran(double n, double p) {
    const int trials = static_cast<int>(n);
    int hits = 0;
    for (int i = 1; i <= trials; ++i) hits += stream.next() <= p;
    return hits;
  }
};

// Swaps a homomorphism's own stream in while one of its productions runs.
class StreamSwap {
 public:
  StreamSwap(Stream& in_use, std::uint64_t& own) : in_use_(in_use), own_(own) { swap(); }
  ~StreamSwap() { swap(); }
  StreamSwap(const StreamSwap&) = delete;
  StreamSwap& operator=(const StreamSwap&) = delete;

 private:
  void swap() {
    const std::uint64_t x = in_use_.x;
    in_use_.x = own_;
    own_ = x;
  }
  Stream& in_use_;
  std::uint64_t& own_;
};

}  // namespace sylva::rt::cpfg
