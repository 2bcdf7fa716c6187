#pragma once
// The constitutive updates of material.h in block form: one SIMD lane per material point of a
// MaterialPointBlock (a solid of a HexBlock, a shell's trial point), each lane doing the scalar
// function's operations in the same order (same bits).

#include <cmath>

#include "impact3d/material/material_point_block.h"
#include "impact3d/material/material.h"

namespace impact3d {

// sigma <- sigma + dt (W sigma - sigma W) on 6 lane arrays (rotate_stress_jaumann).
inline void rotate_stress_jaumann_block(Lanes* sig, const Lanes* w, double dt) {
  IMPACT3D_FOR_LANES {
    const double wxy = w[0][l] * dt, wyz = w[1][l] * dt, wzx = w[2][l] * dt;
    const double sxx = sig[0][l], syy = sig[1][l], szz = sig[2][l];
    const double sxy = sig[3][l], syz = sig[4][l], szx = sig[5][l];
    const double mxx = wxy * sxy - wzx * szx;
    const double myy = -wxy * sxy + wyz * syz;
    const double mzz = wzx * szx - wyz * syz;
    const double mxy = wxy * syy - wzx * syz;
    const double myx = -wxy * sxx + wyz * szx;
    const double myz = -wxy * szx + wyz * szz;
    const double mzy = wzx * sxy - wyz * syy;
    const double mzx = wzx * sxx - wyz * sxy;
    const double mxz = wxy * syz - wzx * szz;
    sig[0][l] = sxx + 2.0 * mxx;
    sig[1][l] = syy + 2.0 * myy;
    sig[2][l] = szz + 2.0 * mzz;
    sig[3][l] = sxy + mxy + myx;
    sig[4][l] = syz + myz + mzy;
    sig[5][l] = szx + mzx + mxz;
  }
}

// Type 1 (update_stress_elastic).
inline void update_stress_elastic_block(const MaterialConstants& m, const Lanes* d, double dt, Lanes* sig) {
  const double g2 = 2.0 * m.G * dt;
  IMPACT3D_FOR_LANES {
    const double lt = m.lambda * dt * (d[0][l] + d[1][l] + d[2][l]);
    sig[0][l] += lt + g2 * d[0][l];
    sig[1][l] += lt + g2 * d[1][l];
    sig[2][l] += lt + g2 * d[2][l];
    sig[3][l] += g2 * d[3][l];
    sig[4][l] += g2 * d[4][l];
    sig[5][l] += g2 * d[5][l];
  }
}

// Type 3 (update_stress_elastic_plastic) after the caller's Jaumann rotation of sig (and of
// back when WithBack).  WithBack = false when the back stress stays zero (isotropic
// hardening, or no hardening): it is then neither read nor written (s - p - 0 = s - p).
// yielded is set to 1 in the lanes that yield.
template <bool WithBack>
inline void update_stress_elastic_plastic_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_stress_elastic_block(m, k.d, dt, k.sig);  // elastic trial
  alignas(64) Lanes rate_factor;
  const bool rate = m.rate_c > 0.0;
  if (rate) {
    IMPACT3D_FOR_LANES {
      rate_factor[l] = std::sqrt(k.d[0][l] * k.d[0][l] + k.d[1][l] * k.d[1][l] + k.d[2][l] * k.d[2][l] +
                                 2.0 * (k.d[3][l] * k.d[3][l] + k.d[4][l] * k.d[4][l] + k.d[5][l] * k.d[5][l]));
    }
    for (int l = 0; l < kLanes; ++l) rate_factor[l] = 1.0 + std::pow(rate_factor[l] / m.rate_c, m.rate_inv_p);
  } else {
    IMPACT3D_FOR_LANES rate_factor[l] = 1.0;
  }
  const double G3 = 3.0 * m.G, beta_ep = m.beta * m.E_p, kin = (1.0 - m.beta) * m.E_p;
  const double plain_den = 3.0 * m.G + m.E_p;
  IMPACT3D_FOR_LANES {
    const double p = (k.sig[0][l] + k.sig[1][l] + k.sig[2][l]) * (1.0 / 3.0);
    const double xi0 = WithBack ? k.sig[0][l] - p - k.back[0][l] : k.sig[0][l] - p;
    const double xi1 = WithBack ? k.sig[1][l] - p - k.back[1][l] : k.sig[1][l] - p;
    const double xi2 = WithBack ? k.sig[2][l] - p - k.back[2][l] : k.sig[2][l] - p;
    const double xi3 = WithBack ? k.sig[3][l] - k.back[3][l] : k.sig[3][l];
    const double xi4 = WithBack ? k.sig[4][l] - k.back[4][l] : k.sig[4][l];
    const double xi5 = WithBack ? k.sig[5][l] - k.back[5][l] : k.sig[5][l];
    const double xx = xi0 * xi0 + xi1 * xi1 + xi2 * xi2 + 2.0 * (xi3 * xi3 + xi4 * xi4 + xi5 * xi5);
    const double vm = std::sqrt(1.5 * xx);
    const double sy0 = m.sigma_y + beta_ep * k.eps_p[l];
    const double sy = rate ? sy0 * rate_factor[l] : sy0;
    const double f = vm - sy;
    const bool yields = f > 0.0;
    const double deps = rate ? f / (G3 + kin + rate_factor[l] * beta_ep) : f / plain_den;
    const double rs = G3 * deps / vm;
    k.sig[0][l] = yields ? k.sig[0][l] - rs * xi0 : k.sig[0][l];
    k.sig[1][l] = yields ? k.sig[1][l] - rs * xi1 : k.sig[1][l];
    k.sig[2][l] = yields ? k.sig[2][l] - rs * xi2 : k.sig[2][l];
    k.sig[3][l] = yields ? k.sig[3][l] - rs * xi3 : k.sig[3][l];
    k.sig[4][l] = yields ? k.sig[4][l] - rs * xi4 : k.sig[4][l];
    k.sig[5][l] = yields ? k.sig[5][l] - rs * xi5 : k.sig[5][l];
    if (WithBack) {
      const double ra = kin * deps / vm;
      k.back[0][l] = yields ? k.back[0][l] + ra * xi0 : k.back[0][l];
      k.back[1][l] = yields ? k.back[1][l] + ra * xi1 : k.back[1][l];
      k.back[2][l] = yields ? k.back[2][l] + ra * xi2 : k.back[2][l];
      k.back[3][l] = yields ? k.back[3][l] + ra * xi3 : k.back[3][l];
      k.back[4][l] = yields ? k.back[4][l] + ra * xi4 : k.back[4][l];
      k.back[5][l] = yields ? k.back[5][l] + ra * xi5 : k.back[5][l];
    }
    k.eps_p[l] = yields ? k.eps_p[l] + deps : k.eps_p[l];
    k.yielded[l] = yields ? 1.0 : k.yielded[l];
  }
}

// The von Mises stress of each lane's trial stress, no back stress (calc_trial_deviator's q).
inline void calc_von_mises_block(const MaterialPointBlock& k, Lanes q) {
  IMPACT3D_FOR_LANES {
    const double p = (k.sig[0][l] + k.sig[1][l] + k.sig[2][l]) * (1.0 / 3.0);
    const double s0 = k.sig[0][l] - p, s1 = k.sig[1][l] - p, s2 = k.sig[2][l] - p;
    q[l] = std::sqrt(1.5 * (s0 * s0 + s1 * s1 + s2 * s2 +
                            2.0 * (k.sig[3][l] * k.sig[3][l] + k.sig[4][l] * k.sig[4][l] + k.sig[5][l] * k.sig[5][l])));
  }
}

// The plastic strain increment for trial von Mises stress q at plastic strain e0 of the
// piecewise-linear flow stress R x (curve_sig + curve_slope (e - curve_eps)) (types 10 and 24;
// 0 when the root is not positive: elastic; R = 1 is the rate-free form exactly).  The block
// form below repeats these operations lane by lane.
inline double calc_piecewise_linear_increment(const MaterialConstants& m, double q, double e0, double R) {
  const double* ce = m.curve_eps.data();
  const double* cs = m.curve_sig.data();
  const double* ch = m.curve_slope.data();
  const int ns = int(m.curve_slope.size());
  const double G3 = 3.0 * m.G;
  double de = 0.0;
  bool found = false;
  for (int i = 0; i < ns; ++i) {
    const double h = cs[i] + ch[i] * (e0 - ce[i]);
    const double cand = (q - R * h) / (G3 + R * ch[i]);
    const double e = e0 + cand;
    const double lo = i == 0 ? -HUGE_VAL : ce[i];
    const double hi = i == ns - 1 ? HUGE_VAL : ce[i + 1];
    if (!found && e >= lo && e <= hi) {
      de = cand;
      found = true;
    }
  }
  return de > 0.0 ? de : 0.0;
}

// One segment of calc_piecewise_linear_increment_block in every lane (a function of its own:
// inlined, GCC peels the first and last segments off the loop and runs their lanes scalar).
[[gnu::noinline]] inline void piecewise_linear_segment_block(double G3, double cei, double csi, double chi,
                                                             double lo, double hi, const Lanes e0, const Lanes q,
                                                             const Lanes R, Lanes de, Lanes found) {
  IMPACT3D_FOR_LANES {
    const double h = csi + chi * (e0[l] - cei);
    const double cand = (q[l] - R[l] * h) / (G3 + R[l] * chi);
    const double e = e0[l] + cand;
    const bool take = (found[l] == 0.0) & (e >= lo) & (e <= hi);
    de[l] = take ? cand : de[l];
    found[l] = take ? 1.0 : found[l];
  }
}

// The plastic strain increment de of each lane for the piecewise-linear flow stress R x
// (curve_sig + curve_slope (e - curve_eps)) of the material's segments: on each segment i the
// candidate (q - R h_i(e0)) / (3G + R slope_i), taken where e0 + candidate lies on segment i
// (the first such segment; de <= 0: elastic).  R = 1 gives the rate-free form exactly.
inline void calc_piecewise_linear_increment_block(const MaterialConstants& m, const MaterialPointBlock& k, const Lanes q,
                                                  const Lanes R, Lanes de) {
  alignas(64) Lanes found;
  IMPACT3D_FOR_LANES {
    de[l] = 0.0;
    found[l] = 0.0;
  }
  const double* ce = m.curve_eps.data();
  const double* cs = m.curve_sig.data();
  const double* ch = m.curve_slope.data();
  const int ns = int(m.curve_slope.size());
  const double G3 = 3.0 * m.G;
  for (int i = 0; i < ns; ++i) {
    const double lo = i == 0 ? -HUGE_VAL : ce[i];
    const double hi = i == ns - 1 ? HUGE_VAL : ce[i + 1];
    piecewise_linear_segment_block(G3, ce[i], cs[i], ch[i], lo, hi, k.eps_p, q, R, de, found);
  }
}

// apply_radial_return in the lanes with de > 0 (q: the trial von Mises stress), and their
// plastic strain and yield flag.
inline void apply_radial_return_block(double G3, const Lanes q, const Lanes de, MaterialPointBlock& k) {
  IMPACT3D_FOR_LANES {
    const double dl = de[l] > 0.0 ? de[l] : 0.0;
    const bool yields = dl > 0.0;
    const double p = (k.sig[0][l] + k.sig[1][l] + k.sig[2][l]) * (1.0 / 3.0);
    const double rs = G3 * dl / q[l];
    const double s0 = k.sig[0][l] - p, s1 = k.sig[1][l] - p, s2 = k.sig[2][l] - p;
    k.sig[0][l] = yields ? k.sig[0][l] - rs * s0 : k.sig[0][l];
    k.sig[1][l] = yields ? k.sig[1][l] - rs * s1 : k.sig[1][l];
    k.sig[2][l] = yields ? k.sig[2][l] - rs * s2 : k.sig[2][l];
    k.sig[3][l] = yields ? k.sig[3][l] - rs * k.sig[3][l] : k.sig[3][l];
    k.sig[4][l] = yields ? k.sig[4][l] - rs * k.sig[4][l] : k.sig[4][l];
    k.sig[5][l] = yields ? k.sig[5][l] - rs * k.sig[5][l] : k.sig[5][l];
    k.eps_p[l] = yields ? k.eps_p[l] + dl : k.eps_p[l];
    k.yielded[l] = yields ? 1.0 : k.yielded[l];
  }
}

}  // namespace impact3d
