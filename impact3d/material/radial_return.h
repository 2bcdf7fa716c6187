#pragma once
// The radial return of von Mises plasticity with a nonlinear isotropic flow stress: the
// plastic strain increment de >= 0 that solves q - 3 G de = sigma_y(e0 + de) for the trial von
// Mises stress q, by Newton's method safeguarded by bisection on [0, q / 3G] (to 1e-15
// relative).  flow(e, s, ds) gives the flow stress s at plastic strain e and its slope ds
// (HUGE_VAL where infinite: a bisection step is taken).  Returns 0 when q does not exceed the
// flow stress at e0.  Scalar code (pow, log inside): block forms call it lane by lane.

#include <cmath>

namespace impact3d {

// The trial stress's mean p, deviator (s0, s1, s2; the shears are sig[3..5]) and von Mises
// stress q (no back stress), in the one order of operations every kernel uses (same bits).
struct TrialDeviator {
  double p, s0, s1, s2, q;
};

inline TrialDeviator calc_trial_deviator(const double sig[6]) {
  TrialDeviator t;
  t.p = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  t.s0 = sig[0] - t.p;
  t.s1 = sig[1] - t.p;
  t.s2 = sig[2] - t.p;
  t.q = std::sqrt(1.5 * (t.s0 * t.s0 + t.s1 * t.s1 + t.s2 * t.s2 + 2.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5])));
  return t;
}

// The radial return of the trial stress by the plastic strain increment de > 0:
// sigma <- sigma - (3 G de / q) s, written as sig - rs s.
inline void apply_radial_return(double G3, double de, const TrialDeviator& t, double sig[6]) {
  const double rs = G3 * de / t.q;
  sig[0] -= rs * t.s0;
  sig[1] -= rs * t.s1;
  sig[2] -= rs * t.s2;
  sig[3] -= rs * sig[3];
  sig[4] -= rs * sig[4];
  sig[5] -= rs * sig[5];
}

// The returned stress p + scale s, given the mean p (after any cutoff), the deviator s0 s1 s2
// (the shears are sig[3..5]) and the factor scale = 1 - 3 G de / q, in the one order of
// operations the Johnson-Cook kernels use (same bits).
inline void set_scaled_deviator(double p, double scale, double s0, double s1, double s2, double sig[6]) {
  sig[0] = p + scale * s0;
  sig[1] = p + scale * s1;
  sig[2] = p + scale * s2;
  sig[3] *= scale;
  sig[4] *= scale;
  sig[5] *= scale;
}

template <class Flow>
double solve_radial_return(double q, double G3, double e0, Flow&& flow) {
  double s, ds;
  flow(e0, s, ds);
  if (!(q - s > 0.0)) return 0.0;
  double lo = 0.0, hi = q / G3, de = 0.0;
  for (int it = 0; it < 100; ++it) {
    flow(e0 + de, s, ds);
    const double g = q - G3 * de - s;
    if (g > 0.0) lo = de; else hi = de;
    double next = de + g / (G3 + ds);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::fabs(next - de) <= 1e-15 * next || hi - lo <= 1e-15 * hi;
    de = next;
    if (done) break;
  }
  return de;
}

}  // namespace impact3d
