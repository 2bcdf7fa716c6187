#include "impact3d/element/hex_sri.h"
#include "impact3d/element/hexahedron.h"

namespace impact3d {

namespace {
// natural coordinates of the nodes
constexpr double kXi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr double kGauss = 0.57735026918962576451;  // 1 / sqrt(3)
}  // namespace

double calc_hex_sri_point_gradients(const double x[8], const double y[8], const double z[8], int g,
                                    double bx[8], double by[8], double bz[8]) {
  const double p = kXi[g][0] * kGauss, q = kXi[g][1] * kGauss, r = kXi[g][2] * kGauss;
  double dn[8][3];  // dN_I / d(xi, eta, zeta)
  for (int n = 0; n < 8; ++n) {
    const double a = 1.0 + p * kXi[n][0], b = 1.0 + q * kXi[n][1], c = 1.0 + r * kXi[n][2];
    dn[n][0] = 0.125 * kXi[n][0] * b * c;
    dn[n][1] = 0.125 * kXi[n][1] * a * c;
    dn[n][2] = 0.125 * kXi[n][2] * a * b;
  }
  double j[3][3] = {};  // j[i][k] = d x_i / d xi_k
  for (int n = 0; n < 8; ++n)
    for (int k = 0; k < 3; ++k) {
      j[0][k] += x[n] * dn[n][k];
      j[1][k] += y[n] * dn[n][k];
      j[2][k] += z[n] * dn[n][k];
    }
  // cofactors: inv(j)[k][i] = cof[i][k] / det
  const double c00 = j[1][1] * j[2][2] - j[1][2] * j[2][1];
  const double c01 = j[1][2] * j[2][0] - j[1][0] * j[2][2];
  const double c02 = j[1][0] * j[2][1] - j[1][1] * j[2][0];
  const double c10 = j[0][2] * j[2][1] - j[0][1] * j[2][2];
  const double c11 = j[0][0] * j[2][2] - j[0][2] * j[2][0];
  const double c12 = j[0][1] * j[2][0] - j[0][0] * j[2][1];
  const double c20 = j[0][1] * j[1][2] - j[0][2] * j[1][1];
  const double c21 = j[0][2] * j[1][0] - j[0][0] * j[1][2];
  const double c22 = j[0][0] * j[1][1] - j[0][1] * j[1][0];
  const double det = j[0][0] * c00 + j[0][1] * c01 + j[0][2] * c02;
  const double inv = det != 0.0 ? 1.0 / det : 0.0;
  // dN/dx_i = sum_k dN/dxi_k inv(j)[k][i] = sum_k dN/dxi_k cof[i][k] / det
  for (int n = 0; n < 8; ++n) {
    bx[n] = (dn[n][0] * c00 + dn[n][1] * c01 + dn[n][2] * c02) * inv;
    by[n] = (dn[n][0] * c10 + dn[n][1] * c11 + dn[n][2] * c12) * inv;
    bz[n] = (dn[n][0] * c20 + dn[n][1] * c21 + dn[n][2] * c22) * inv;
  }
  return det;
}

void calc_hex_sri_strain_rate(const double bx[8], const double by[8], const double bz[8],
                              const double vx[8], const double vy[8], const double vz[8],
                              double trd_mean, double d[6], double w[3]) {
  calc_hex_strain_rate(bx, by, bz, vx, vy, vz, d, w);
  const double shift = (trd_mean - (d[0] + d[1] + d[2])) / 3.0;  // the point's trace -> the mean one
  d[0] += shift;
  d[1] += shift;
  d[2] += shift;
}

double add_hex_sri_point_forces(const double sig[6], const double bx[8], const double by[8],
                                const double bz[8], double detj, double fx[8], double fy[8],
                                double fz[8]) {
  const double p = (sig[0] + sig[1] + sig[2]) / 3.0;
  const double sxx = (sig[0] - p) * detj, syy = (sig[1] - p) * detj, szz = (sig[2] - p) * detj;
  const double sxy = sig[3] * detj, syz = sig[4] * detj, szx = sig[5] * detj;
  for (int n = 0; n < 8; ++n) {
    fx[n] += sxx * bx[n] + sxy * by[n] + szx * bz[n];
    fy[n] += sxy * bx[n] + syy * by[n] + syz * bz[n];
    fz[n] += szx * bx[n] + syz * by[n] + szz * bz[n];
  }
  return p * detj;
}

}  // namespace impact3d
