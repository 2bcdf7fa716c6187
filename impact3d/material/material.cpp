// Per-element constitutive updates; see material.h.  Small straight-line functions on the
// caller's arrays: no heap, no globals, no exceptions (called inside the OpenMP element loop).

#include "impact3d/material/material.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace impact3d {

void derive_material_constants(MaterialConstants& m) {
  // Decks give either E and nu, or (the oblique-rod aluminium) G and K: complete whichever.
  if (m.E <= 0.0 && m.G > 0.0 && m.K > 0.0) {
    m.E = 9.0 * m.K * m.G / (3.0 * m.K + m.G);
    m.nu = (3.0 * m.K - 2.0 * m.G) / (2.0 * (3.0 * m.K + m.G));
  }
  m.G = m.E / (2.0 * (1.0 + m.nu));
  m.K = m.E / (3.0 * (1.0 - 2.0 * m.nu));
  m.lambda = m.K - 2.0 * m.G / 3.0;
  m.E_p = (m.E_tan > 0.0 && m.E_tan < m.E) ? m.E * m.E_tan / (m.E - m.E_tan) : 0.0;
  m.c = m.rho > 0.0 ? std::sqrt((m.K + 4.0 * m.G / 3.0) / m.rho) : 0.0;
}

void rotate_stress_jaumann(double sig[6], const double w[3], double dt) {
  // W = [[0, wxy, -wzx], [-wxy, 0, wyz], [wzx, -wyz, 0]].  Since sigma W = -(W sigma)^T,
  // W sigma - sigma W = M + M^T with M = W sigma.
  const double wxy = w[0] * dt, wyz = w[1] * dt, wzx = w[2] * dt;
  const double sxx = sig[0], syy = sig[1], szz = sig[2];
  const double sxy = sig[3], syz = sig[4], szx = sig[5];
  // Rows of M = W sigma (only the entries needed for the symmetric part).
  const double mxx = wxy * sxy - wzx * szx;
  const double myy = -wxy * sxy + wyz * syz;
  const double mzz = wzx * szx - wyz * syz;
  const double mxy = wxy * syy - wzx * syz;
  const double myx = -wxy * sxx + wyz * szx;
  const double myz = -wxy * szx + wyz * szz;
  const double mzy = wzx * sxy - wyz * syy;
  const double mzx = wzx * sxx - wyz * sxy;
  const double mxz = wxy * syz - wzx * szz;
  sig[0] = sxx + 2.0 * mxx;
  sig[1] = syy + 2.0 * myy;
  sig[2] = szz + 2.0 * mzz;
  sig[3] = sxy + mxy + myx;
  sig[4] = syz + myz + mzy;
  sig[5] = szx + mzx + mxz;
}

void update_stress_elastic(const MaterialConstants& m, const double d[6], double dt,
                           double sig[6]) {
  const double g2 = 2.0 * m.G * dt;
  const double lt = m.lambda * dt * (d[0] + d[1] + d[2]);
  sig[0] += lt + g2 * d[0];
  sig[1] += lt + g2 * d[1];
  sig[2] += lt + g2 * d[2];
  sig[3] += g2 * d[3];
  sig[4] += g2 * d[4];
  sig[5] += g2 * d[5];
}

double update_stress_elastic_plastic(const MaterialConstants& m, const double d[6], double dt,
                                     double sig[6], double back[6], double& eps_p,
                                     unsigned char& yielded) {
  update_stress_elastic(m, d, dt, sig);  // elastic trial
  const double p = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  // xi = s - alpha
  double xi[6];
  xi[0] = sig[0] - p - back[0];
  xi[1] = sig[1] - p - back[1];
  xi[2] = sig[2] - p - back[2];
  xi[3] = sig[3] - back[3];
  xi[4] = sig[4] - back[4];
  xi[5] = sig[5] - back[5];
  const double xx = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2] +
                    2.0 * (xi[3] * xi[3] + xi[4] * xi[4] + xi[5] * xi[5]);
  const double vm = std::sqrt(1.5 * xx);
  double sy = m.sigma_y + m.beta * m.E_p * eps_p;
  double rate_factor = 1.0;
  if (m.rate_c > 0.0) {
    const double rate = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] +
                                  2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5]));
    rate_factor = 1.0 + std::pow(rate / m.rate_c, m.rate_inv_p);
    sy *= rate_factor;
  }
  const double f = vm - sy;
  if (f <= 0.0) return 0.0;
  yielded = 1;
  // (without rate effects the plain form, so rate-free results keep their bits)
  const double deps = m.rate_c > 0.0 ? f / (3.0 * m.G + (1.0 - m.beta) * m.E_p + rate_factor * m.beta * m.E_p)
                                     : f / (3.0 * m.G + m.E_p);
  // Flow direction n = d(vm)/d(sigma) = 3 xi / (2 vm): s -= 2 G deps n, alpha += (1 - beta)
  // (2/3) E_p deps n.
  const double rs = 3.0 * m.G * deps / vm;
  const double ra = (1.0 - m.beta) * m.E_p * deps / vm;
  for (int k = 0; k < 6; ++k) {
    sig[k] -= rs * xi[k];
    back[k] += ra * xi[k];
  }
  eps_p += deps;
  return deps;
}

double calc_von_mises(const double sig[6]) {
  const double p = (sig[0] + sig[1] + sig[2]) * (1.0 / 3.0);
  const double sx = sig[0] - p, sy = sig[1] - p, sz = sig[2] - p;
  const double ss = sx * sx + sy * sy + sz * sz +
                    2.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]);
  return std::sqrt(1.5 * ss);
}

}  // namespace impact3d

namespace impact3d {

void derive_erosion_constants(const ErosionData& e, MaterialConstants& m) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  auto used = [&](double v) { return v != e.excl && v != 0; };
  m.erosion = false;
  m.er_mxpres = used(e.mxpres) ? e.mxpres : inf;
  m.er_mnpres = used(e.mnpres) ? e.mnpres : -inf;
  m.er_sigp1 = used(e.sigp1) ? e.sigp1 : inf;
  m.er_sigvm = used(e.sigvm) ? e.sigvm : inf;
  m.er_vol_hi = used(e.voleps) && e.voleps > 0 ? e.voleps : inf;
  m.er_vol_lo = used(e.voleps) && e.voleps < 0 ? e.voleps : -inf;
  m.er_failtm = used(e.failtm) ? e.failtm : inf;
  m.er_ncs = e.ncs > 0 ? e.ncs : 1;
  m.er_mneps = used(e.mneps) ? e.mneps : -inf;
  m.er_effeps = used(e.effeps) ? e.effeps : inf;
  m.er_mxeps = used(e.mxeps) ? e.mxeps : inf;
  m.er_epssh = used(e.epssh) ? e.epssh : inf;
  m.er_strain = m.er_mneps > -inf || m.er_effeps < inf || m.er_mxeps < inf || m.er_epssh < inf;
  m.erosion = e.active && (m.er_mxpres < inf || m.er_mnpres > -inf || m.er_sigp1 < inf || m.er_sigvm < inf ||
                           m.er_vol_hi < inf || m.er_vol_lo > -inf || m.er_failtm < inf || m.er_strain);
}

namespace {

// Largest eigenvalue of a symmetric 3x3 tensor (xx yy zz xy yz zx), trigonometric form.
double largest_principal(const double s[6]) {
  const double p1 = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  const double q = (s[0] + s[1] + s[2]) / 3;
  if (p1 == 0) return std::max({s[0], s[1], s[2]});
  const double a = s[0] - q, b = s[1] - q, c = s[2] - q;
  const double p2 = a * a + b * b + c * c + 2 * p1;
  const double p = std::sqrt(p2 / 6);
  // det((S - q I) / p) / 2
  const double B00 = a / p, B11 = b / p, B22 = c / p, B01 = s[3] / p, B12 = s[4] / p, B02 = s[5] / p;
  const double det = B00 * (B11 * B22 - B12 * B12) - B01 * (B01 * B22 - B12 * B02) + B02 * (B01 * B12 - B11 * B02);
  const double r = std::clamp(det / 2, -1.0, 1.0);
  return q + 2 * p * std::cos(std::acos(r) / 3);
}

}  // namespace

void calc_hex_principal_strains(const double X[8][3], const double x[8][3], double eps[3]) {
  // dN/dxi at the centre: the corner signs / 8 (corners 1-4 at zeta = -1, 5-8 at +1)
  static const double sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                      sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  Eigen::Matrix3d J0 = Eigen::Matrix3d::Zero(), J = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d g(sx[a] / 8, sy[a] / 8, sz[a] / 8);
    J0 += Eigen::Vector3d(X[a][0], X[a][1], X[a][2]) * g.transpose();
    J += Eigen::Vector3d(x[a][0], x[a][1], x[a][2]) * g.transpose();
  }
  const Eigen::Matrix3d F = J * J0.inverse();
  const Eigen::Vector3d lam = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(F * F.transpose()).eigenvalues();
  // ascending eigenvalues of the left Cauchy-Green tensor: ln sqrt(lambda), descending
  for (int i = 0; i < 3; ++i) eps[i] = 0.5 * std::log(std::max(lam(2 - i), 1e-300));
}

bool erosion_criteria_met(const MaterialConstants& m, const double sig[6], double vol_ratio, double t,
                          const double eps[3]) {
  const double pressure = -(sig[0] + sig[1] + sig[2]) / 3;
  int met = 0;
  met += pressure >= m.er_mxpres;
  met += pressure <= m.er_mnpres;
  met += t >= m.er_failtm;
  const double ev = vol_ratio - 1;
  met += ev >= m.er_vol_hi || ev <= m.er_vol_lo;
  if (m.er_sigvm < std::numeric_limits<double>::infinity()) {
    const double sx = sig[0] + pressure, sy = sig[1] + pressure, sz = sig[2] + pressure;
    const double j2 = 0.5 * (sx * sx + sy * sy + sz * sz) + sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5];
    met += std::sqrt(3 * j2) >= m.er_sigvm;
  }
  if (m.er_sigp1 < std::numeric_limits<double>::infinity()) met += largest_principal(sig) >= m.er_sigp1;
  if (m.er_strain && eps) {
    met += eps[0] >= m.er_mxeps;
    met += eps[2] <= m.er_mneps;
    met += 0.5 * (eps[0] - eps[2]) >= m.er_epssh;
    const double em = (eps[0] + eps[1] + eps[2]) / 3;
    const double d0 = eps[0] - em, d1 = eps[1] - em, d2 = eps[2] - em;
    met += std::sqrt(2.0 / 3.0 * (d0 * d0 + d1 * d1 + d2 * d2)) >= m.er_effeps;
  }
  return met >= m.er_ncs;
}

}  // namespace impact3d
