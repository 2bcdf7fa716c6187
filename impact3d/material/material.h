#pragma once
// Per-element constitutive updates (Jaumann rate, Voigt order xx yy zz xy yz zx, tensor shears).
// One function per material type; each is a small per-element update called from the element
// loop.

#include <array>
#include <cmath>
#include <vector>

#include "impact3d/model/model.h"  // ErosionData

namespace impact3d {

// Constants derived once at initialization from the deck's values.
struct MaterialConstants {
  int type = 0;        // DYNA3D type number (material_types.h)
  double rho = 0;      // initial density
  double E = 0, nu = 0;
  double G = 0, K = 0, lambda = 0;
  double sigma_y = 0;  // initial yield stress (type 3)
  double E_tan = 0;    // tangent modulus (type 3)
  double beta = 0;     // 1 isotropic, 0 kinematic hardening
  double E_p = 0;      // plastic hardening modulus E E_tan / (E - E_tan)
  double c = 0;        // dilatational wave speed sqrt((K + 4G/3)/rho)
  double rate_c = 0;   // Cowper-Symonds C (type 3; 0 = no strain-rate effect)
  double rate_inv_p = 0;  // 1 / P
  double fail_strain = 0;  // effective plastic strain at which a solid fails (0 = never)
  bool initially_elastic = false;  // the seed's fast path (type 3)
  double tdel = 0;         // a solid whose step falls below this is deleted (0 = never)
  double shell_tdel = 0;   // a shell whose step falls below this is deleted (*MAT_024 TDEL; ERODE
                           // leaves it: LS-DYNA's ERODE is for solids)
  int fail_history = -1;   // a solid whose history value of this index reaches 1 is deleted (damage)
  // *MAT_NULL TEROD / CEROD: a solid whose volume ratio V/V0 exceeds vol_erode_hi or falls
  // below vol_erode_lo is deleted (0: off)
  double vol_erode_hi = 0, vol_erode_lo = 0;
  // *MAT_ADD_EROSION: the criteria in use (an unused one is +inf, -inf for MNPRES), NCS
  bool erosion = false;
  double er_mxpres = 0, er_mnpres = 0, er_sigp1 = 0, er_sigvm = 0, er_vol_hi = 0, er_vol_lo = 0, er_failtm = 0;
  int er_ncs = 1;
  bool er_strain = false;  // some strain criterion is used (the solver then computes the strains)
  double er_mneps = 0, er_effeps = 0, er_mxeps = 0, er_epssh = 0;
  // Hardening curve sigma_y(eps_p), piecewise linear, the last slope extended (types with a
  // tabulated flow stress); slope[i] is the slope from point i to i + 1.
  std::vector<double> curve_eps, curve_sig, curve_slope;
  // Strain-rate scaling curve of the yield stress (type 24 LCSR): rate -> factor, piecewise
  // linear, its end values held beyond the first and last points; rate_slope[i] from i to i + 1.
  std::vector<double> rate_x, rate_f, rate_slope;
  // Equation of state (material/eos.h): form 0 none, 1 linear polynomial, 2 JWL, 3 Sack
  // Tuesday, 4 Gruneisen, 5 ratio of polynomials, 6 linear polynomial with energy deposition,
  // 8 tabulated compaction, 9 tabulated; its constants (form 1 and 6 C0-C6, form 2 A, B, R1,
  // R2, OMEG, form 3 A1, A2, A3, B1, B2, form 4 rho0 C^2, S1, S2, S3, GAMMA0, A; form 5 the
  // A_ij, ALPHA, BETA; forms 8, 9 EV1-EV10, C1-C10, T1-T10, GAMMA, form 8 K1-K10; then (index
  // kEosConstants) the number of table points); the initial relative volume V0; the pressure
  // cutoff (p >= eos_pc; -inf none); the first of the history values it keeps (the internal
  // energy per reference volume; form 8 then the most compacted ln V - ln V0); form 6's deposition
  // curve (times, rates, the rate's integral from the first time to each point)
  int eos_form = 0;
  std::array<double, kEosConstants + 1> eos{};
  double eos_v0 = 1, eos_ln_v0 = 0;  // V0 and ln V0
  double eos_pc = -HUGE_VAL;
  int eos_hist = -1;
  // a history value of the material that, once nonzero, leaves the point no tension (type 15's
  // spalled rubble): its EOS pressure is floored at 0 instead of eos_pc (-1: none)
  int no_tension_hist = -1;
  std::vector<double> eos_curve_t, eos_curve_f, eos_curve_F;
  // the type's other constants (its file names their places)
  std::array<double, 24> k{};
};

// Fill G, K, lambda, E_p, c from type, rho, E, nu, sigma_y, E_tan, beta.  When E is not given
// (E <= 0) but G and K are (the oblique-rod deck), E and nu are filled from them first.
// E_p = 0 (perfect plasticity) when E_tan <= 0 or E_tan >= E.
void derive_material_constants(MaterialConstants& m);

// *MAT_ADD_EROSION: the criteria of ErosionData as constants (none used: m.erosion false).
void derive_erosion_constants(const ErosionData& e, MaterialConstants& m);
// Whether a solid with stress sig (xx yy zz xy yz zx, tension positive), volume ratio V/V0 at
// time t and principal true strains eps (e1 >= e2 >= e3; read only when m.er_strain) meets at
// least NCS of the material's erosion criteria.
bool erosion_criteria_met(const MaterialConstants& m, const double sig[6], double vol_ratio, double t,
                          const double eps[3] = nullptr);
// Principal true strains (descending) of a hexahedron at its centre: ln of the principal
// stretches of F = dx/dX, from its initial (X) and current (x) corner coordinates.
void calc_hex_principal_strains(const double X[8][3], const double x[8][3], double eps[3]);

// sigma <- sigma + dt (W sigma - sigma W)  (rotation of the old stress by the spin).
void rotate_stress_jaumann(double sig[6], const double w[3], double dt);

// Type 1: sigma += dt (lambda trD I + 2 G D).  Call rotate_stress_jaumann first.
void update_stress_elastic(const MaterialConstants& m, const double d[6], double dt,
                           double sig[6]);

// Per-element history of the elastic-plastic material.
struct PlasticState {
  double* back;   // back stress alpha[6] (kinematic part)
  double* eps_p;  // effective plastic strain
  unsigned char* yielded;  // 0 until first yield (the "initially elastic" fast path switch)
};

// Type 3: elastic trial (after rotation of sig and back stress by the caller), von Mises yield
// on xi = s - alpha, yield stress sigma_y + beta E_p eps_p, times the Cowper-Symonds factor
// R = 1 + (rate / C)^(1/P) when C > 0, with rate = sqrt(D:D) the strain-rate norm (the LS-DYNA
// manual's definition for *MAT_PLASTIC_KINEMATIC, VP = 0: the yield stress is scaled), radial
// return
// d eps_p = f / (3G + E_p) (with rate scaling f / (3G + (1 - beta) E_p + R beta E_p), so that
// the returned stress lies on the scaled surface), s -= 2 G d eps_p n, back stress += (1 - beta) (2/3) E_p d eps_p n,
// with n = d(vm)/d(sigma) = 3 xi / (2 vm(xi)) the flow direction (so that in uniaxial stress the
// back stress component alpha_xx grows by (2/3) E_p d eps_p; the plain unit tensor xi/|xi| would
// be sqrt(3/2) too small).
// Returns the plastic strain increment (0 when elastic).
double update_stress_elastic_plastic(const MaterialConstants& m, const double d[6], double dt,
                                     double sig[6], double back[6], double& eps_p,
                                     unsigned char& yielded);

// Von Mises stress sqrt(3/2 s:s) of a Voigt stress (tensor shears).
double calc_von_mises(const double sig[6]);

}  // namespace impact3d
