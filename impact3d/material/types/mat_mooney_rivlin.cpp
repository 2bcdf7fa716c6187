// Type 27, *MAT_MOONEY-RIVLIN_RUBBER: LS-DYNA's compressible Mooney-Rivlin rubber, the strain
// energy per reference volume
//   W = A (I1 - 3) + B (I2 - 3) + C (I3^-2 - 1) + D (I3 - 1)^2,
//   C = A / 2 + B (no stress in the reference state),
//   D = (A (5 nu - 2) + B (11 nu - 5)) / (2 (1 - 2 nu)) (the small-strain bulk modulus of PR),
// with I1, I2, I3 the invariants of the left Cauchy-Green tensor b = F F^T (those of C = F^T F).
// Small strains: shear modulus G = 2 (A + B), bulk modulus 2 G (1 + nu) / (3 (1 - 2 nu)) (the
// time step and hourglass forms use them).  Cauchy stress
//   sigma = (2 / J) ((A + B I1) b - B b^2 + I3 W3 I),  W3 = dW/dI3 = -2 C I3^-3 + 2 D (I3 - 1),
// J = sqrt(I3).  For incompressible uniaxial stress (stretch s) the nominal stress is
// 2 (A + B / s) (s - 1 / s^2).
//
// Solids keep b - I (xx yy zz xy yz zx) as their six history values, updated each step from the
// velocity gradient L = D + W at the midpoint geometry (the strain rate d and spin w the element
// gives): b <- dF b dF^T with dF = (I - dt/2 L)^-1 (I + dt/2 L), which is the exact increment
// dx^{n+1}/dx^n of a constant-gradient step (x^{n+1} = x^n + dt v) written at the midpoint: a
// rigid rotation leaves the stress's invariants unchanged (dF orthogonal), and the stress
// depends on the total b only (no rate integration: the energy of a closed path returns).
// Shells: the incompressible plane-stress form (plane_stress.h,
// update_plane_stress_mooney_rivlin).
//
// Card 2 (SGL, SW, ST, LCID) asks LS-DYNA to fit A and B to a force-elongation curve when A =
// B = 0: not implemented (message 1102 on LCID); with A or B given LS-DYNA ignores it, and so
// does IMPACT-3D.  REF = 1 (the reference geometry of *INITIAL_FOAM_REFERENCE_GEOMETRY): 1102.
//
// Fixed format (an IMPACT-3D choice; no DYNA3D manual at hand fixes type 27): LS-DYNA's fields in
// order, 8 E10 fields per card: card 3 PR, A, B, REF; card 4 SGL, SW, ST, LCID.
//
// The block form runs the scalar kernel lane by lane (a 3x3 inverse and products per lane);
// same bits by construction.

#include <cmath>
#include <cstdio>
#include <ostream>

#include "impact3d/material/material_types.h"
#include "impact3d/material/plane_stress.h"

namespace impact3d {

namespace {

enum Par { pA, pB, pRef, pSgl, pSw, pSt, pLcid, kNumPar };
enum K { kA, kB, kC, kD };

void mooney_rivlin_constants(double A, double B, double nu, double& C, double& D) {
  C = 0.5 * A + B;
  D = (A * (5.0 * nu - 2.0) + B * (11.0 * nu - 5.0)) / (2.0 * (1.0 - 2.0 * nu));
}

void mooney_rivlin_stress(const MaterialConstants& m, const double b[6], double sig[6]) {
  const double A = m.k[kA], B = m.k[kB], C = m.k[kC], D = m.k[kD];
  const double xx = b[0], yy = b[1], zz = b[2], xy = b[3], yz = b[4], zx = b[5];
  const double I1 = xx + yy + zz;
  // b^2 (symmetric)
  const double q0 = xx * xx + xy * xy + zx * zx, q1 = xy * xy + yy * yy + yz * yz, q2 = zx * zx + yz * yz + zz * zz;
  const double q3 = xx * xy + xy * yy + zx * yz, q4 = xy * zx + yy * yz + yz * zz, q5 = zx * xx + yz * xy + zz * zx;
  const double I3 = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * zx) + zx * (xy * yz - yy * zx);
  const double J = std::sqrt(I3);
  const double W3 = -2.0 * C / (I3 * I3 * I3) + 2.0 * D * (I3 - 1.0);
  const double f = 2.0 / J, a = A + B * I1, p = I3 * W3;
  sig[0] = f * (a * xx - B * q0 + p);
  sig[1] = f * (a * yy - B * q1 + p);
  sig[2] = f * (a * zz - B * q2 + p);
  sig[3] = f * (a * xy - B * q3);
  sig[4] = f * (a * yz - B * q4);
  sig[5] = f * (a * zx - B * q5);
}

// b <- dF b dF^T, dF = (I - h L)^-1 (I + h L), h = dt / 2; g = b - I in and out.
void update_left_cauchy_green(const double d[6], const double w[3], double dt, double g[6]) {
  const double h = 0.5 * dt;
  double L[3][3] = {{d[0], d[3] + w[0], d[5] - w[2]}, {d[3] - w[0], d[1], d[4] + w[1]}, {d[5] + w[2], d[4] - w[1], d[2]}};
  double P[3][3], M[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double e = i == j ? 1.0 : 0.0;
      P[i][j] = e + h * L[i][j];
      M[i][j] = e - h * L[i][j];
    }
  // M^-1 by cofactors
  double c[3][3];
  c[0][0] = M[1][1] * M[2][2] - M[1][2] * M[2][1];
  c[0][1] = M[0][2] * M[2][1] - M[0][1] * M[2][2];
  c[0][2] = M[0][1] * M[1][2] - M[0][2] * M[1][1];
  c[1][0] = M[1][2] * M[2][0] - M[1][0] * M[2][2];
  c[1][1] = M[0][0] * M[2][2] - M[0][2] * M[2][0];
  c[1][2] = M[0][2] * M[1][0] - M[0][0] * M[1][2];
  c[2][0] = M[1][0] * M[2][1] - M[1][1] * M[2][0];
  c[2][1] = M[0][1] * M[2][0] - M[0][0] * M[2][1];
  c[2][2] = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  const double inv_det = 1.0 / (M[0][0] * c[0][0] + M[0][1] * c[1][0] + M[0][2] * c[2][0]);
  double F[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F[i][j] = inv_det * (c[i][0] * P[0][j] + c[i][1] * P[1][j] + c[i][2] * P[2][j]);
  const double b[3][3] = {{1.0 + g[0], g[3], g[5]}, {g[3], 1.0 + g[1], g[4]}, {g[5], g[4], 1.0 + g[2]}};
  double T[3][3];  // F b
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[i][j] = F[i][0] * b[0][j] + F[i][1] * b[1][j] + F[i][2] * b[2][j];
  auto fbf = [&](int i, int j) { return T[i][0] * F[j][0] + T[i][1] * F[j][1] + T[i][2] * F[j][2]; };
  g[0] = fbf(0, 0) - 1.0;
  g[1] = fbf(1, 1) - 1.0;
  g[2] = fbf(2, 2) - 1.0;
  g[3] = fbf(0, 1);
  g[4] = fbf(1, 2);
  g[5] = fbf(2, 0);
}

void update_point(const MaterialConstants& m, const double d[6], double dt, SolidPointState& st) {
  update_left_cauchy_green(d, st.w, dt, st.hist);
  const double b[6] = {1.0 + st.hist[0], 1.0 + st.hist[1], 1.0 + st.hist[2], st.hist[3], st.hist[4], st.hist[5]};
  mooney_rivlin_stress(m, b, st.sig);
}

void update_block(const MaterialConstants& m, MaterialPointBlock& k, double dt) {
  update_block_lane_by_lane(m, k, dt, 6, update_point);
}

void check(MaterialData& md, const MaterialType& t, const ParamReport& report) {
  const double A = par(md, pA), B = par(md, pB);
  if (A == 0 && B == 0) {
    if (par(md, pLcid) != 0)
      report(*find_param(t, "LCID"), 1102, "A and B fitted to the force-elongation curve LCID (A = B = 0); give A and B");
    else
      report(*find_param(t, "A"), 1003, "A and B are both zero (no stiffness); give A and B");
    return;
  }
  if (!(A + B > 0)) report(*find_param(t, "B"), 1003, "the shear modulus 2 (A + B) must be positive");
}

void derive(const MaterialData& d, const Model&, MaterialConstants& c) {
  c.k[kA] = par(d, pA);
  c.k[kB] = par(d, pB);
  mooney_rivlin_constants(c.k[kA], c.k[kB], d.nu, c.k[kC], c.k[kD]);
  const double G = 2.0 * (c.k[kA] + c.k[kB]);
  c.E = 2.0 * G * (1.0 + d.nu);  // derive_material_constants: G, K, wave speed
}

void echo(std::ostream& os, const MaterialData& md) {
  double C, D;
  mooney_rivlin_constants(par(md, pA), par(md, pB), md.nu, C, D);
  char b[128];
  echo_line(os, "strain energy", "A (I1-3) + B (I2-3) + C (I3^-2 - 1) + D (I3-1)^2");
  std::snprintf(b, sizeof b, "%.6e, D %.6e", C, D);
  echo_line(os, "C = A/2 + B", b);
  std::snprintf(b, sizeof b, "%.6e (stress)", 2.0 * (par(md, pA) + par(md, pB)));
  echo_line(os, "shear modulus 2 (A + B)", b);
}

MaterialParam p(const char* key, int kcard, int kfield, int index, ParamCheck check = ParamCheck::none,
                const char* detail = "", const char* label = nullptr, const char* unit = "") {
  return {.key = key, .label = label, .kcard = kcard, .kfield = kfield, .fcard = kcard + 3, .fcol = 1 + 10 * (kfield - (kcard == 0 ? 2 : 0)),
          .index = index, .check = check, .detail = detail, .unit = unit};
}

}  // namespace

double update_plane_stress_mooney_rivlin(const MaterialConstants& m, const double d[5], double dt, double sig[5],
                                         double b[3]) {
  const double h = 0.5 * dt;
  // dF = (I - h D)^-1 (I + h D) in the plane
  const double p00 = 1.0 + h * d[0], p11 = 1.0 + h * d[1], p01 = h * d[2];
  const double m00 = 1.0 - h * d[0], m11 = 1.0 - h * d[1], m01 = -h * d[2];
  const double inv_det = 1.0 / (m00 * m11 - m01 * m01);
  const double f00 = inv_det * (m11 * p00 - m01 * p01), f01 = inv_det * (m11 * p01 - m01 * p11);
  const double f10 = inv_det * (m00 * p01 - m01 * p00), f11 = inv_det * (m00 * p11 - m01 * p01);
  const double bxx = 1.0 + b[0], byy = 1.0 + b[1], bxy = b[2];
  const double t00 = f00 * bxx + f01 * bxy, t01 = f00 * bxy + f01 * byy;  // dF b
  const double t10 = f10 * bxx + f11 * bxy, t11 = f10 * bxy + f11 * byy;
  const double nxx = t00 * f00 + t01 * f01, nyy = t10 * f10 + t11 * f11, nxy = t00 * f10 + t01 * f11;
  b[0] = nxx - 1.0, b[1] = nyy - 1.0, b[2] = nxy;
  const double A = m.k[kA], B = m.k[kB];
  const double bzz = 1.0 / (nxx * nyy - nxy * nxy);
  const double a = A + B * (nxx + nyy + bzz);
  const double szz = 2.0 * (a * bzz - B * bzz * bzz);
  const double s = std::sqrt(bzz);  // thickness stretch
  sig[0] = s * (2.0 * (a * nxx - B * (nxx * nxx + nxy * nxy)) - szz);
  sig[1] = s * (2.0 * (a * nyy - B * (nyy * nyy + nxy * nxy)) - szz);
  sig[2] = s * 2.0 * (a * nxy - B * nxy * (nxx + nyy));
  sig[3] += 2.0 * m.G * dt * d[3];
  sig[4] += 2.0 * m.G * dt * d[4];
  return -(d[0] + d[1]);
}

const MaterialType& mat_mooney_rivlin_type() {
  static const MaterialType t{.number = 27, .name = "Mooney-Rivlin rubber", .keywords = {"MAT_MOONEY-RIVLIN_RUBBER", "MAT_027"},
      .params = {
          {.key = "PR", .fname = "nu", .label = "Poisson's ratio PR", .kcard = 0, .kfield = 2, .fcard = 3, .fcol = 1,
           .field = &MaterialData::nu, .check = ParamCheck::poisson, .msg = 1209},
          p("A", 0, 3, pA, ParamCheck::none, "", "A", "stress"),
          p("B", 0, 4, pB, ParamCheck::none, "", "B", "stress"),
          p("REF", 0, 5, pRef, ParamCheck::unsupported, "REF = 1 (the reference geometry of *INITIAL_FOAM_REFERENCE_GEOMETRY)"),
          p("SGL", 1, 0, pSgl, ParamCheck::non_negative, "must not be negative (specimen gauge length)"),
          p("SW", 1, 1, pSw, ParamCheck::non_negative, "must not be negative (specimen width)"),
          p("ST", 1, 2, pSt, ParamCheck::non_negative, "must not be negative (specimen thickness)"),
          p("LCID", 1, 3, pLcid, ParamCheck::integer, "must be a curve number"),
      },
      .num_par = kNumPar, .keyword_cards = 2,
      .check = check, .derive = derive, .echo = echo,
      .solid = {HexKernel::deformable, update_point, update_block, false},
      .history = {"b_xx - 1", "b_yy - 1", "b_zz - 1", "b_xy", "b_yz", "b_zx"},
  };
  return t;
}

}  // namespace impact3d
