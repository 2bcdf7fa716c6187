#pragma once
// The 8-node hexahedron in block form: the kernels of hexahedron.h written for a block of
// kLanes elements at once, one SIMD lane per element (struct-of-arrays [node][lane]).  Every
// lane does exactly the scalar kernel's operations in the same order, so a block gives the
// same bits as the scalar functions element by element (the tests check this), for any SIMD
// width the compiler picks (AVX-512 takes a block in one instruction per operation, AVX2 in
// two, SSE2 in four).  Requires IEEE arithmetic without contraction (-ffp-contract=off, set
// in CMakeLists.txt).
//
// The element pass (solve/element_processing.cpp) gathers a block's nodal data into a HexBlock,
// calls these in turn, and stores the results; see there for the order.

#include <cfloat>
#include <cmath>

#include "impact3d/element/cbrt_positive.h"
#include "impact3d/element/hex_volume_derivative.h"
#include "impact3d/material/material_point_block.h"

namespace impact3d {

// A block's working set: gathered nodal data and everything derived from it, around the material
// points (MaterialPointBlock: strain rate d, spin w, sig, back, eps_p, yielded, hist; the material
// kernels take that part).  About 20 KB, one per thread, reused block after block (stays in L1).
struct alignas(64) HexBlock : MaterialPointBlock {
  Lanes x[8], y[8], z[8], vx[8], vy[8], vz[8];  // x^n, v^{n-1/2}
  Lanes bx[8], by[8], bz[8];                    // b = dV/dx / V at the midpoint x^{n-1/2}
  Lanes dvdx[8], dvdy[8], dvdz[8];              // dV/dx at x^n
  Lanes fx[8], fy[8], fz[8];                    // corner forces
  Lanes v, vm, amax, rho, v0;                   // volume at x^n and midpoint, largest face, density, initial volume
  Lanes trd;                                    // trace of d
  Lanes old[6];                                 // stress at the start of the step
  Lanes hgs[12];                                // hourglass resultants (the previous pass's, then this one's)
  Lanes q, q_old;                               // bulk viscosity
  Lanes de_ie, de_hg, de_bv, dt;                // energy increments, element step
  Lanes hg_old, hg_new, dt_hg;                  // viscous hourglass: old and new resultants' power, stable step
  Lanes de_src;                                 // energy an equation of state deposited (in de_ie too)
  Lanes cs;                                     // sound speed per lane (groups with an equation of state)
  Lanes de_old;                                 // fully integrated solids: the old stress's share of de_ie
};

namespace hex_block_detail {
inline void quad_area_lanes(const Lanes* x, const Lanes* y, const Lanes* z, int a, int b, int c,
                            int d, Lanes& area) {
  IMPACT3D_FOR_LANES {
    const double d1x = x[c][l] - x[a][l], d1y = y[c][l] - y[a][l], d1z = z[c][l] - z[a][l];
    const double d2x = x[d][l] - x[b][l], d2y = y[d][l] - y[b][l], d2z = z[d][l] - z[b][l];
    const double nx = d1y * d2z - d1z * d2y;
    const double ny = d1z * d2x - d1x * d2z;
    const double nz = d1x * d2y - d1y * d2x;
    area[l] = 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
  }
}

constexpr double kGammaB[4][8] = {
    {1., 1., -1., -1., -1., -1., 1., 1.},
    {1., -1., -1., 1., -1., 1., 1., -1.},
    {1., -1., 1., -1., 1., -1., 1., -1.},
    {-1., 1., -1., 1., 1., -1., 1., -1.},
};
// The viscous hourglass forms' stable step M / (4 a_h mu) (hexahedron.cpp
// viscous_hourglass_step), lane form; M = rho V.
inline void viscous_hourglass_step_lanes(const Lanes (*g)[8], const Lanes& ah, const Lanes& rho, const Lanes& v,
                                         Lanes& dt) {
  IMPACT3D_FOR_LANES {
    double gram[4][4];
#pragma GCC unroll 16
    for (int a = 0; a < 4; ++a)
#pragma GCC unroll 16
      for (int b = a; b < 4; ++b) {
        double s = 0.0;
#pragma GCC unroll 16
        for (int n = 0; n < 8; ++n) s += g[a][n][l] * g[b][n][l];
        gram[a][b] = gram[b][a] = s;
      }
    double mu = 0.0;
#pragma GCC unroll 16
    for (int a = 0; a < 4; ++a) {
      const double row = std::fabs(gram[a][0]) + std::fabs(gram[a][1]) + std::fabs(gram[a][2]) + std::fabs(gram[a][3]);
      mu = row > mu ? row : mu;
    }
    const double den = 4.0 * ah[l] * mu;
    const double mass = rho[l] * v[l];
    dt[l] = den > 0.0 ? mass / den : DBL_MAX;
  }
}

}  // namespace hex_block_detail

// dV/dx at the nodes and the volume V = sum x dV/dx (calc_hex_volume_derivatives).
inline void calc_hex_volume_derivatives_block(const Lanes* x, const Lanes* y, const Lanes* z,
                                              Lanes* dvdx, Lanes* dvdy, Lanes* dvdz, Lanes& vol) {
#pragma GCC unroll 8
  for (const auto& c : kVolumeDerivativeNeighbours)
    IMPACT3D_FOR_LANES {
      volume_derivative([x, l](int n) { return x[n][l]; }, [y, l](int n) { return y[n][l]; }, [z, l](int n) { return z[n][l]; },
                        c + 1, dvdx[c[0]][l], dvdy[c[0]][l], dvdz[c[0]][l]);
    }
  IMPACT3D_FOR_LANES {
    double v = 0.0;
    #pragma GCC unroll 16
    for (int n = 0; n < 8; ++n) v += x[n][l] * dvdx[n][l];
    vol[l] = v;
  }
}

// Largest face area (calc_hex_max_face_area), faces in the same order.
inline void calc_hex_max_face_area_block(const Lanes* x, const Lanes* y, const Lanes* z, Lanes& amax) {
  using hex_block_detail::quad_area_lanes;
  alignas(64) Lanes b;
  quad_area_lanes(x, y, z, 0, 1, 2, 3, amax);
  static constexpr int kFaces[5][4] = {{4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& f : kFaces) {
    quad_area_lanes(x, y, z, f[0], f[1], f[2], f[3], b);
    IMPACT3D_FOR_LANES amax[l] = b[l] > amax[l] ? b[l] : amax[l];
  }
}

// Strain rate and spin from v and b (calc_hex_strain_rate), and trD.
inline void calc_hex_strain_rate_block(HexBlock& k) {
  IMPACT3D_FOR_LANES {
    double lxx = 0, lxy = 0, lxz = 0, lyx = 0, lyy = 0, lyz = 0, lzx = 0, lzy = 0, lzz = 0;
    #pragma GCC unroll 16
    for (int n = 0; n < 8; ++n) {
      lxx += k.vx[n][l] * k.bx[n][l];
      lxy += k.vx[n][l] * k.by[n][l];
      lxz += k.vx[n][l] * k.bz[n][l];
      lyx += k.vy[n][l] * k.bx[n][l];
      lyy += k.vy[n][l] * k.by[n][l];
      lyz += k.vy[n][l] * k.bz[n][l];
      lzx += k.vz[n][l] * k.bx[n][l];
      lzy += k.vz[n][l] * k.by[n][l];
      lzz += k.vz[n][l] * k.bz[n][l];
    }
    k.d[0][l] = lxx;
    k.d[1][l] = lyy;
    k.d[2][l] = lzz;
    k.d[3][l] = 0.5 * (lxy + lyx);
    k.d[4][l] = 0.5 * (lyz + lzy);
    k.d[5][l] = 0.5 * (lzx + lxz);
    k.w[0][l] = 0.5 * (lxy - lyx);
    k.w[1][l] = 0.5 * (lyz - lzy);
    k.w[2][l] = 0.5 * (lzx - lxz);
    k.trd[l] = lxx + lyy + lzz;
  }
}

// Kinematics of a gathered block over the step dt (= dt^{n-1/2}): b at the midpoint
// x^{n-1/2} = x^n - dt/2 v^{n-1/2}, dV/dx and V at x^n, the strain rate and spin, the
// largest face.  The midpoint volume is left in k.vm.
inline void calc_hex_kinematics_block(HexBlock& k, double dt) {
  alignas(64) Lanes xm[8], ym[8], zm[8];
  for (int j = 0; j < 8; ++j) {
    IMPACT3D_FOR_LANES {
      xm[j][l] = k.x[j][l] - 0.5 * dt * k.vx[j][l];
      ym[j][l] = k.y[j][l] - 0.5 * dt * k.vy[j][l];
      zm[j][l] = k.z[j][l] - 0.5 * dt * k.vz[j][l];
    }
  }
  calc_hex_volume_derivatives_block(xm, ym, zm, k.bx, k.by, k.bz, k.vm);
  calc_hex_volume_derivatives_block(k.x, k.y, k.z, k.dvdx, k.dvdy, k.dvdz, k.v);
  alignas(64) Lanes inv_vm;
  IMPACT3D_FOR_LANES inv_vm[l] = 1.0 / k.vm[l];
  for (int j = 0; j < 8; ++j) {
    IMPACT3D_FOR_LANES {
      k.bx[j][l] *= inv_vm[l];
      k.by[j][l] *= inv_vm[l];
      k.bz[j][l] *= inv_vm[l];
    }
  }
  calc_hex_strain_rate_block(k);
  calc_hex_max_face_area_block(k.x, k.y, k.z, k.amax);
}

// Bulk viscosity q (calc_bulk_viscosity with l = V / A_max), per lane.
inline void calc_hex_bulk_viscosity_block(HexBlock& k, double c, double q1, double q2) {
  IMPACT3D_FOR_LANES {
    const double len = k.v[l] / k.amax[l];
    const double trd = k.trd[l];
    const double q = k.rho[l] * len * (q1 * len * trd * trd - q2 * c * trd);
    k.q[l] = trd >= 0.0 ? 0.0 : q;
  }
}

// Stress-divergence corner forces with sigma - q I (calc_hex_stress_force), written.
inline void calc_hex_stress_force_block(HexBlock& k) {
  for (int n = 0; n < 8; ++n) {
    IMPACT3D_FOR_LANES {
      const double sxx = k.sig[0][l] - k.q[l], syy = k.sig[1][l] - k.q[l], szz = k.sig[2][l] - k.q[l];
      const double sxy = k.sig[3][l], syz = k.sig[4][l], szx = k.sig[5][l];
      k.fx[n][l] = sxx * k.dvdx[n][l] + sxy * k.dvdy[n][l] + szx * k.dvdz[n][l];
      k.fy[n][l] = sxy * k.dvdx[n][l] + syy * k.dvdy[n][l] + syz * k.dvdz[n][l];
      k.fz[n][l] = szx * k.dvdx[n][l] + syz * k.dvdy[n][l] + szz * k.dvdz[n][l];
    }
  }
}

// Hourglass forces added to the corner forces (calc_hex_hourglass_force); power in k.de_hg
// (times dt by the caller; for the stiffness forms the mean resultant's, as the scalar
// kernel's).  type as in HourglassInput; qhg != 0.  dt_hg is the step of the
// stiffness forms.
inline void calc_hex_hourglass_force_block(HexBlock& k, int type, double qhg, double c,
                                           double shear_modulus, double dt_hg) {
  using hex_block_detail::kGammaB;
  alignas(64) Lanes g[4][8];
  if (type <= 1) {
    for (int a = 0; a < 4; ++a)
      for (int n = 0; n < 8; ++n) IMPACT3D_FOR_LANES g[a][n][l] = kGammaB[a][n];
  } else {
    alignas(64) Lanes rv;
    IMPACT3D_FOR_LANES rv[l] = 1.0 / k.v[l];
    for (int a = 0; a < 4; ++a) {
      alignas(64) Lanes gx, gy, gz;
      IMPACT3D_FOR_LANES {
        double sx = 0.0, sy = 0.0, sz = 0.0;
        #pragma GCC unroll 16
        for (int n = 0; n < 8; ++n) {
          sx += kGammaB[a][n] * k.x[n][l];
          sy += kGammaB[a][n] * k.y[n][l];
          sz += kGammaB[a][n] * k.z[n][l];
        }
        gx[l] = sx * rv[l];
        gy[l] = sy * rv[l];
        gz[l] = sz * rv[l];
      }
      for (int n = 0; n < 8; ++n)
        IMPACT3D_FOR_LANES g[a][n][l] = kGammaB[a][n] - (gx[l] * k.dvdx[n][l] + gy[l] * k.dvdy[n][l] + gz[l] * k.dvdz[n][l]);
    }
  }
  // hourglass velocities h[3a + i]
  alignas(64) Lanes h[12];
  for (int a = 0; a < 4; ++a) {
    IMPACT3D_FOR_LANES {
      double hx = 0.0, hy = 0.0, hz = 0.0;
      #pragma GCC unroll 16
      for (int n = 0; n < 8; ++n) {
        hx += g[a][n][l] * k.vx[n][l];
        hy += g[a][n][l] * k.vy[n][l];
        hz += g[a][n][l] * k.vz[n][l];
      }
      h[3 * a][l] = hx;
      h[3 * a + 1][l] = hy;
      h[3 * a + 2][l] = hz;
    }
  }
  alignas(64) Lanes qf[12];  // the hourglass resultants Q_ia that act
  alignas(64) Lanes root;
  alignas(64) Lanes mean_corr;  // stiffness forms: kappa dt |h|^2 / 2 (the mean resultant's power)
  if (type <= 3) {
    IMPACT3D_FOR_LANES root[l] = cbrt_positive(k.v[l] * k.v[l]);
    alignas(64) Lanes ah;
    IMPACT3D_FOR_LANES {
      ah[l] = 0.25 * qhg * k.rho[l] * c * root[l];
      double po = 0.0;
      #pragma GCC unroll 16
      for (int m = 0; m < 12; ++m) po += k.hgs[m][l] * h[m][l];
      k.hg_old[l] = po;
      #pragma GCC unroll 16
      for (int m = 0; m < 12; ++m) {
        k.hgs[m][l] = ah[l] * h[m][l];
        qf[m][l] = k.hgs[m][l];
      }
    }
    hex_block_detail::viscous_hourglass_step_lanes(g, ah, k.rho, k.v, k.dt_hg);
  } else {
    IMPACT3D_FOR_LANES root[l] = cbrt_positive(k.v[l]);
    IMPACT3D_FOR_LANES {
      const double kappa = 0.25 * qhg * shear_modulus * root[l];
      const double kdt = kappa * dt_hg;
      #pragma GCC unroll 16
      for (int m = 0; m < 12; ++m) {
        k.hgs[m][l] += kdt * h[m][l];
        qf[m][l] = k.hgs[m][l];
      }
      double hh = 0.0;
      #pragma GCC unroll 16
      for (int m = 0; m < 12; ++m) hh += h[m][l] * h[m][l];
      mean_corr[l] = 0.5 * kdt * hh;
      k.hg_old[l] = 0.0;
      k.dt_hg[l] = DBL_MAX;
    }
  }
  IMPACT3D_FOR_LANES k.de_hg[l] = 0.0;  // the power, summed node by node
  for (int n = 0; n < 8; ++n) {
    IMPACT3D_FOR_LANES {
      double ax = 0.0, ay = 0.0, az = 0.0;
#pragma GCC unroll 16
      for (int a = 0; a < 4; ++a) {
        ax += qf[3 * a][l] * g[a][n][l];
        ay += qf[3 * a + 1][l] * g[a][n][l];
        az += qf[3 * a + 2][l] * g[a][n][l];
      }
      k.fx[n][l] += ax;
      k.fy[n][l] += ay;
      k.fz[n][l] += az;
      k.de_hg[l] += ax * k.vx[n][l] + ay * k.vy[n][l] + az * k.vz[n][l];
    }
  }
  if (type > 3) IMPACT3D_FOR_LANES k.de_hg[l] = k.de_hg[l] - mean_corr[l];
}

// The element step is the smaller of the wave step and the viscous hourglass forms' (k.dt_hg).
inline void limit_hex_time_step_block(HexBlock& k) {
  IMPACT3D_FOR_LANES k.dt[l] = k.dt_hg[l] < k.dt[l] ? k.dt_hg[l] : k.dt[l];
}

// Element step (calc_hex_time_step) into k.dt.
namespace hex_block_detail {
// One lane's step: length V / A_max over the sound speed c with the bulk viscosity's q (DBL_MAX
// where the element has no length or no speed).
inline double hex_lane_time_step(const HexBlock& k, int l, double c, double q1, double q2) {
  const double len = k.v[l] / k.amax[l];
  const double trd = k.trd[l];
  const double q = trd < 0.0 ? q2 * c + q1 * len * (-trd) : 0.0;
  const double den = q + std::sqrt(q * q + c * c);
  const double dt = len / den;
  return (k.amax[l] <= 0.0 || den <= 0.0) ? DBL_MAX : dt;
}
}  // namespace hex_block_detail

inline void calc_hex_time_step_block(HexBlock& k, double c, double q1, double q2) {
  IMPACT3D_FOR_LANES { k.dt[l] = hex_block_detail::hex_lane_time_step(k, l, c, q1, q2); }
}

// The same with a sound speed per lane (k.cs: groups with an equation of state).
inline void calc_hex_time_step_lanes_block(HexBlock& k, double q1, double q2) {
  IMPACT3D_FOR_LANES { k.dt[l] = hex_block_detail::hex_lane_time_step(k, l, k.cs[l], q1, q2); }
}

}  // namespace impact3d
