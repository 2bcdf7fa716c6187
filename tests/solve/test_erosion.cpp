// *MAT_ADD_EROSION (MXPRES, MNPRES, SIGP1, SIGVM, VOLEPS, FAILTM, NCS, EXCL): a solid is deleted
// in the first cycle where its stress, volume or the time meets the criteria.  Each test runs
// the model once without erosion, finds the first cycle where some solids meet a criterion
// (computed here from the stress, independently of the solver's check), and requires the run
// with erosion to delete exactly those solids in exactly that cycle and none before; then the
// reader, its refusals and the converter.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/material/material.h"
#include "impact3d/material/material_types.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "tests/solve/test_models.h"
#include "../support/deck_text.h"

using namespace impact3d;
using namespace solve_test;

namespace {

double pressure_of(const double* s) { return -(s[0] + s[1] + s[2]) / 3; }
double von_mises_of(const double* s) {
  const double p = pressure_of(s);
  const double a = s[0] + p, b = s[1] + p, c = s[2] + p;
  return std::sqrt(1.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}
double largest_principal_of(const double* s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues().maxCoeff();
}

// Elastic copper bar of 20 solids (2.5 mm square, 50 mm long) whose bottom end is held while the
// rest starts with vz growing linearly to v_top at the top: a uniform stretch (v_top > 0) or
// squeeze, so the stress grows steadily (about E v_top / L t) and crosses a criterion some
// cycles in, in the solids where rounding puts it first. TSSFAC 0.5: a bar one solid across is
// not stable at 0.9 under this sudden start (its energy grew 44-fold by cycle 6, which error
// 4007 now stops; README, "The step").
Model struck_bar(double v_top) {
  Model m = make_box_model({1, 1, 20, 0.0025, 0.0025, 0.05, 0, 0, 0}, copper_elastic(), 2e-5);
  m.control.tssf = 0.5;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.z[std::size_t(n)] < 1e-12) m.bc[std::size_t(n)] = 3;
  set_velocity_field(m, [&](double, double, double z) { return std::array<double, 3>{0, 0, v_top * z / 0.05}; });
  return m;
}

using Criterion = std::function<bool(const double* sig, double vol_ratio, double t)>;

// Principal true strains (descending) of solid k of the bar from its faces: the stretches along
// x, y, z are the distances between opposite faces' mean positions over the initial ones (the
// bar deforms without shear).
std::array<double, 3> face_strains(const Model& m, const State& s, int k) {
  const auto& c = s.conn[std::size_t(k)];
  auto mean = [&](const std::vector<double>& v, std::initializer_list<int> corners) {
    double t = 0;
    for (int j : corners) t += v[std::size_t(c[std::size_t(j)])];
    return t / 4;
  };
  auto stretch = [&](const std::vector<double>& cur, const std::vector<double>& ini, std::initializer_list<int> lo,
                     std::initializer_list<int> hi) {
    return (mean(cur, hi) - mean(cur, lo)) / (mean(ini, hi) - mean(ini, lo));
  };
  std::array<double, 3> e = {std::log(stretch(s.x, m.x, {0, 3, 4, 7}, {1, 2, 5, 6})),
                             std::log(stretch(s.y, m.y, {0, 1, 4, 5}, {2, 3, 6, 7})),
                             std::log(stretch(s.z, m.z, {0, 1, 2, 3}, {4, 5, 6, 7}))};
  std::sort(e.begin(), e.end(), std::greater<double>());
  return e;
}
using StrainCriterion = std::function<bool(const std::array<double, 3>& eps)>;

// First cycle of the plain run where some solid meets the criterion, and those solids.
std::pair<int, std::vector<int>> first_meeting(const Model& m, const Criterion& met) {
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = e.step();
    const State& s = e.state();
    std::vector<int> which;
    for (int k = 0; k < s.ne; ++k)
      if (met(&s.sig[6 * std::size_t(k)], s.vol[std::size_t(k)] / s.vol0[std::size_t(k)], s.time)) which.push_back(k);
    if (!which.empty()) return {s.cycle, which};
  }
  return {-1, {}};
}

// The same with a criterion on the solids' principal strains.
std::pair<int, std::vector<int>> first_meeting_strain(const Model& m, const StrainCriterion& met) {
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = e.step();
    std::vector<int> which;
    for (int k = 0; k < e.state().ne; ++k)
      if (met(face_strains(m, e.state(), k))) which.push_back(k);
    if (!which.empty()) return {e.state().cycle, which};
  }
  return {-1, {}};
}

// The first cycle of the eroding run that deletes solids, and those solids.
std::pair<int, std::vector<int>> first_deletion(const Model& m) {
  Engine e(m);
  EXPECT_EQ(e.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = e.step();
    if (!e.state().newly_failed.empty()) return {e.state().cycle, e.state().newly_failed};
  }
  return {-1, {}};
}

void expect_erosion_matches(const ErosionData& er, const Criterion& met, const char* what, double vz = -40) {
  Model plain = struck_bar(vz);
  const auto expected = first_meeting(plain, met);
  ASSERT_GT(expected.first, 2) << what << ": the plain run never meets the criterion, or at once";
  Model eroding = plain;
  eroding.materials[0].erosion = er;
  const auto got = first_deletion(eroding);
  EXPECT_EQ(got.first, expected.first) << what;
  EXPECT_EQ(got.second, expected.second) << what;
}

void expect_strain_erosion_matches(const ErosionData& er, const StrainCriterion& met, const char* what, double vz) {
  Model plain = struck_bar(vz);
  const auto expected = first_meeting_strain(plain, met);
  ASSERT_GT(expected.first, 2) << what << ": the plain run never meets the criterion, or at once";
  Model eroding = plain;
  eroding.materials[0].erosion = er;
  const auto got = first_deletion(eroding);
  EXPECT_EQ(got.first, expected.first) << what;
  EXPECT_EQ(got.second, expected.second) << what;
}

ErosionData erosion() {
  ErosionData e;
  e.active = true;
  return e;
}

}  // namespace

TEST(Erosion, PressureCriteriaDeleteTheSolidsThatReachThem) {
  // the axial stress grows about 24 MPa a cycle (v_top 40 m/s, TSSFAC 0.5), the pressure a third as fast
  ErosionData e = erosion();
  e.mxpres = 2.4e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return pressure_of(s) >= 2.4e8; }, "MXPRES");
  // pulled: tension
  e = erosion();
  e.mnpres = -4e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return pressure_of(s) <= -4e8; }, "MNPRES", 40);
}

TEST(Erosion, StressVolumeAndTimeCriteria) {
  ErosionData e = erosion();
  e.sigvm = 4.8e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return von_mises_of(s) >= 4.8e8; }, "SIGVM");
  e = erosion();
  e.sigp1 = 4.8e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return largest_principal_of(s) >= 4.8e8; }, "SIGP1", 40);
  e = erosion();
  e.voleps = -3e-3;
  expect_erosion_matches(e, [](const double*, double v, double) { return v - 1 <= -3e-3; }, "VOLEPS");
  e = erosion();
  e.failtm = 4e-6;
  expect_erosion_matches(e, [](const double*, double, double t) { return t >= 4e-6; }, "FAILTM");
  // NCS 2: pressure and volumetric strain must hold at once
  e = erosion();
  e.mxpres = 1.5e8;
  e.voleps = -3e-3;
  e.ncs = 2;
  expect_erosion_matches(e, [](const double* s, double v, double) { return pressure_of(s) >= 1.5e8 && v - 1 <= -3e-3; }, "NCS 2");
  e.ncs = 1;  // either one: earlier
  expect_erosion_matches(e, [](const double* s, double v, double) { return pressure_of(s) >= 1.5e8 || v - 1 <= -3e-3; }, "NCS 1");
  // EXCL: a criterion equal to it is off (here MXPRES = EXCL = 1: only FAILTM acts)
  e = erosion();
  e.excl = 1;
  e.mxpres = 1;
  e.failtm = 4e-6;
  expect_erosion_matches(e, [](const double*, double, double t) { return t >= 4e-6; }, "EXCL");
}

// *MAT_NULL TEROD / CEROD: the struck bar of a null material (water-like: linear polynomial,
// p = 2.2 GPa mu; sides on rollers: uniaxial strain) is deleted in the first cycle the plain run's V/V0 exceeds TEROD (stretched) or
// falls below CEROD (squeezed), solid by solid; the other limit never acts.
TEST(Erosion, NullMaterialErodesByRelativeVolume) {
  auto null_bar = [](double v_top, double terod, double cerod) {
    Model m = struck_bar(v_top);
    MaterialData& md = m.materials[0];
    md.type = 9;
    set_param_defaults(md, material_type(9));
    md.rho = 1000;
    md.eos.form = 1;
    md.eos.c[1] = 2.2e9;
    param_value(md, *find_param(material_type(9), "TEROD")) = terod;
    param_value(md, *find_param(material_type(9), "CEROD")) = cerod;
    for (int n = 0; n < m.num_nodes(); ++n) m.bc[std::size_t(n)] = m.z[std::size_t(n)] < 1e-12 ? 7 : 4;  // sides on rollers
    m.control.end_time = 4e-5;
    m.control.tssf = 0.5;  // a free column one solid wide: its breathing mode needs a smaller step than 0.9 L / c
    return m;
  };
  for (double v_top : {40.0, -40.0}) {
    const double terod = 1.01, cerod = 0.99;
    Model plain = null_bar(v_top, 0, 0);
    const auto expected = first_meeting(plain, [&](const double*, double v, double) { return v > terod || v < cerod; });
    ASSERT_GT(expected.first, 10) << v_top;
    // only the limit on this side is set, then both
    const auto one = first_deletion(null_bar(v_top, v_top > 0 ? terod : 0, v_top > 0 ? 0 : cerod));
    const auto both = first_deletion(null_bar(v_top, terod, cerod));
    std::printf("MAT_NULL %s: V/V0 %s %.3f first in cycle %d (%zu solids); deleted in cycle %d (%zu solids)\n",
                v_top > 0 ? "TEROD" : "CEROD", v_top > 0 ? ">" : "<", v_top > 0 ? terod : cerod, expected.first,
                expected.second.size(), one.first, one.second.size());
    EXPECT_EQ(one.first, expected.first);
    EXPECT_EQ(one.second, expected.second);
    EXPECT_EQ(both.first, expected.first);
    EXPECT_EQ(both.second, expected.second);
    // the limit on the other side alone deletes nothing
    EXPECT_EQ(first_deletion(null_bar(v_top, v_top > 0 ? 0 : terod, v_top > 0 ? cerod : 0)).first, -1);
  }
}

// Strain criteria (true strains at the solid's centre): a stretched bar reaches MXEPS, EFFEPS and
// EPSSH, a squeezed one MNEPS, in the cycle its face-to-face stretches say.
TEST(Erosion, StrainCriteria) {
  const double eps_z = 1.5e-3;  // the bar's axial strain grows about 2e-4 a cycle
  ErosionData e = erosion();
  e.mxeps = eps_z;
  expect_strain_erosion_matches(e, [&](const std::array<double, 3>& p) { return p[0] >= eps_z; }, "MXEPS", 20);
  e = erosion();
  e.mneps = -eps_z;
  expect_strain_erosion_matches(e, [&](const std::array<double, 3>& p) { return p[2] <= -eps_z; }, "MNEPS", -20);
  auto effective = [](const std::array<double, 3>& p) {
    const double m = (p[0] + p[1] + p[2]) / 3;
    return std::sqrt(2.0 / 3.0 * ((p[0] - m) * (p[0] - m) + (p[1] - m) * (p[1] - m) + (p[2] - m) * (p[2] - m)));
  };
  e = erosion();
  e.effeps = eps_z;
  expect_strain_erosion_matches(e, [&](const std::array<double, 3>& p) { return effective(p) >= eps_z; }, "EFFEPS", 20);
  e = erosion();
  e.epssh = eps_z / 2;
  expect_strain_erosion_matches(e, [&](const std::array<double, 3>& p) { return 0.5 * (p[0] - p[2]) >= eps_z / 2; }, "EPSSH", 20);
}

// The centre strains of a hexahedron stretched by (1.2, 0.9, 1.05) and then turned by a rigid
// rotation: ln of the stretches, in descending order.
TEST(Erosion, PrincipalStrainsIgnoreRotation) {
  double X[8][3], x[8][3];
  static const double cx[8] = {0, 1, 1, 0, 0, 1, 1, 0}, cy[8] = {0, 0, 1, 1, 0, 0, 1, 1}, cz[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (int a = 0; a < 8; ++a) {
    X[a][0] = 0.02 * cx[a];
    X[a][1] = 0.02 * cy[a];
    X[a][2] = 0.02 * cz[a];
    const Eigen::Vector3d y = R * Eigen::Vector3d(1.2 * X[a][0], 0.9 * X[a][1], 1.05 * X[a][2]) + Eigen::Vector3d(1, -2, 3);
    for (int i = 0; i < 3; ++i) x[a][i] = y(i);
  }
  double eps[3];
  calc_hex_principal_strains(X, x, eps);
  EXPECT_NEAR(eps[0], std::log(1.2), 1e-12);
  EXPECT_NEAR(eps[1], std::log(1.05), 1e-12);
  EXPECT_NEAR(eps[2], std::log(0.9), 1e-12);
}

// *CONTROL_TIMESTEP ERODE = 1 with DTMIN: a block crushed on its mid-plane (plastic copper,
// 2 x 400 m/s) whose flattening solids would end the run (message 4003) loses them instead, in
// the cycle their step TSSF dt_e falls below DTMIN x the first step, and runs to the end.
TEST(Erosion, ErodeDeletesSolidsBelowTheMinimumStep) {
  Model m = make_box_model({6, 6, 6, 0.01, 0.01, 0.01, 0, 0, 0}, copper_plastic(), 2e-5);
  set_velocity_field(m, [](double, double, double z) {
    const double d = z - 0.005;
    return std::array<double, 3>{0, 0, d > 1e-9 ? -400.0 : d < -1e-9 ? 400.0 : 0.0};
  });
  m.control.min_step_factor = 0.6;
  // without ERODE the run stops when the step falls below 0.6 dt0
  Engine plain(m);
  ASSERT_EQ(plain.initialize(), StepStatus::ok);
  StepStatus st = StepStatus::ok;
  std::vector<std::vector<double>> steps;  // each cycle's element steps (before it ends)
  while (st == StepStatus::ok) {
    st = plain.step();
    steps.push_back(plain.state().dt_e);
  }
  ASSERT_EQ(st, StepStatus::dt_too_small);
  const int stop_cycle = plain.state().cycle;
  const double limit = 0.6 * plain.state().dt0;
  // the solids whose step first falls below the limit, and when
  int first = -1;
  std::vector<int> below;
  for (std::size_t c = 0; c < steps.size() && first < 0; ++c) {
    for (int k = 0; k < int(steps[c].size()); ++k)
      if (m.control.tssf * steps[c][std::size_t(k)] < limit) below.push_back(k);
    if (!below.empty()) first = int(c) + 1;
  }
  ASSERT_GT(first, 1);
  EXPECT_LE(first, stop_cycle);
  // with ERODE those solids go in that cycle, and the run reaches its end
  m.control.erode_small_steps = true;
  Engine er(m);
  ASSERT_EQ(er.initialize(), StepStatus::ok);
  int deleted_at = -1;
  std::vector<int> deleted;
  st = StepStatus::ok;
  while (st == StepStatus::ok) {
    st = er.step();
    if (deleted_at < 0 && !er.state().newly_failed.empty()) {
      deleted_at = er.state().cycle;
      deleted = er.state().newly_failed;
    }
  }
  EXPECT_EQ(st, StepStatus::finished);
  EXPECT_EQ(deleted_at, first);
  EXPECT_EQ(deleted, below);
  int nfailed = 0;
  for (auto f : er.state().failed) nfailed += f != 0;
  EXPECT_GT(nfailed, 0);
  EXPECT_LT(nfailed, er.state().ne);
  EXPECT_GE(er.state().dt_next, 0.0);
}

// The solver's principal-stress check on stresses with known eigenvalues.
TEST(Erosion, PrincipalStressOfAShearState) {
  ErosionData e = erosion();
  MaterialConstants c;
  // pure shear xy = 1 plus 0.5 in zz: eigenvalues 1, 0.5, -1
  const double sig[6] = {0, 0, 0.5, 1, 0, 0};
  e.sigp1 = 0.999999;
  derive_erosion_constants(e, c);
  EXPECT_TRUE(erosion_criteria_met(c, sig, 1, 0));
  e.sigp1 = 1.000001;
  derive_erosion_constants(e, c);
  EXPECT_FALSE(erosion_criteria_met(c, sig, 1, 0));
  // a general tensor against Eigen
  const double g[6] = {3e8, -1e8, 2e8, 1.5e8, -0.7e8, 0.4e8};
  const double l1 = largest_principal_of(g);
  e.sigp1 = l1 * (1 - 1e-12);
  derive_erosion_constants(e, c);
  EXPECT_TRUE(erosion_criteria_met(c, g, 1, 0));
  e.sigp1 = l1 * (1 + 1e-12);
  derive_erosion_constants(e, c);
  EXPECT_FALSE(erosion_criteria_met(c, g, 1, 0));
}

namespace {

using Read = test_support::ReadDeck;

Read read_text(const std::string& text) { return test_support::read_deck_text(text, "erosion.k"); }

std::string hex_deck(const std::string& mat, const std::string& extra) {
  return "*KEYWORD\n*TITLE\nerosion\n*CONTROL_TERMINATION\n   1.0E-05\n*DATABASE_BINARY_D3PLOT\n   5.0E-07\n"
         "*PART\nblock\n         1         1         1\n*SECTION_SOLID\n         1         1\n" + mat +
         "*NODE\n"
         "       1             0.0             0.0             0.0\n       2            0.01             0.0             0.0\n"
         "       3            0.01            0.01             0.0\n       4             0.0            0.01             0.0\n"
         "       5             0.0             0.0            0.01\n       6            0.01             0.0            0.01\n"
         "       7            0.01            0.01            0.01\n       8             0.0            0.01            0.01\n"
         "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7       8\n" + extra + "*END\n";
}
const char* kElastic = "*MAT_ELASTIC\n         1    7800.0   2.0e11       0.3\n";

}  // namespace

TEST(ErosionInput, ReadsRefusesAndConverts) {
  Read r = read_text(hex_deck(kElastic,
                              "*MAT_ADD_EROSION_TITLE\nsteel erosion\n"
                              "$#     mid      excl    mxpres     mneps    effeps    voleps    numfip       ncs\n"
                              "         1       0.0     1.0E9       0.0       0.0     -0.25         1         2\n"
                              "$#  mnpres     sigp1     sigvm     mxeps     epssh     sigth   impulse    failtm\n"
                              "    -2.0E8     5.0E8     9.0E8       0.0       0.0       0.0       0.0    1.0E-3\n"));
  ASSERT_TRUE(r.ok) << r.messages();
  const ErosionData& e = r.m.materials[0].erosion;
  EXPECT_TRUE(e.active);
  EXPECT_DOUBLE_EQ(e.mxpres, 1e9);
  EXPECT_DOUBLE_EQ(e.voleps, -0.25);
  EXPECT_EQ(e.ncs, 2);
  EXPECT_DOUBLE_EQ(e.mnpres, -2e8);
  EXPECT_DOUBLE_EQ(e.sigp1, 5e8);
  EXPECT_DOUBLE_EQ(e.sigvm, 9e8);
  EXPECT_DOUBLE_EQ(e.failtm, 1e-3);
  // keyword round trip; the fixed format cannot hold it (exit 2, nothing written)
  const std::string kw = std::string(IMPACT3D_BINARY_DIR) + "/erosion.k";
  const std::string fixed = std::string(IMPACT3D_BINARY_DIR) + "/erosion.dyn";
  std::ostringstream log;
  ASSERT_EQ(write_converted_decks(r.m, kw, "", log), exit_code::ok) << log.str();
  Read back;
  {
    DeckFile deck;
    ASSERT_TRUE(deck.load(kw, back.d));
    InputOptions o;
    back.ok = read_deck(deck, back.m, back.d, o) && check_model(back.m, back.d);
  }
  ASSERT_TRUE(back.ok) << back.messages();
  std::string diff;
  for (const auto& l : model_differences(r.m, back.m)) diff += l + "\n";
  EXPECT_EQ(diff, "");
  std::ostringstream flog;
  EXPECT_EQ(write_converted_decks(r.m, "", fixed, flog), exit_code::input_error);
  EXPECT_NE(flog.str().find("*MAT_ADD_EROSION"), std::string::npos) << flog.str();
  // Tuler-Butcher and damage are not supported (1102, by field); an undefined material is 1310;
  // a rigid material 1102
  Read bad = read_text(hex_deck(kElastic,
                                "*MAT_ADD_EROSION\n         1       0.0       0.0     -0.10      0.30\n"
                                "       0.0       0.0       0.0      0.20      0.10     1.0E8       1.0\n"
                                "         1\n"
                                "*MAT_ADD_EROSION\n         5       0.0     1.0E9\n"));
  EXPECT_FALSE(bad.ok);
  for (const char* f : {"SIGTH", "IMPULSE", "IDAM"})
    EXPECT_NE(bad.messages().find(std::string("\"") + f + "\""), std::string::npos) << f << "\n" << bad.messages();
  EXPECT_NE(bad.messages().find("error 1310"), std::string::npos) << bad.messages();
  // ERODE (*CONTROL_TIMESTEP field 7) round trips through both formats (fixed: card 9 cols 71-75)
  std::string ed = hex_deck(kElastic, "*CONTROL_TIMESTEP\n       0.0       0.9         0       0.0       0.0         0         1\n");
  ed.replace(ed.find("   1.0E-05\n"), 11, "   1.0E-05         0       0.5\n");
  Read er = read_text(ed);
  ASSERT_TRUE(er.ok) << er.messages();
  EXPECT_TRUE(er.m.control.erode_small_steps);
  EXPECT_DOUBLE_EQ(er.m.control.min_step_factor, 0.5);
  std::ostringstream elog;
  ASSERT_EQ(write_converted_decks(er.m, kw, fixed, elog), exit_code::ok) << elog.str();
  for (const std::string& path : {kw, fixed}) {
    Read b;
    DeckFile deck;
    ASSERT_TRUE(deck.load(path, b.d));
    InputOptions o;
    b.ok = read_deck(deck, b.m, b.d, o) && check_model(b.m, b.d);
    ASSERT_TRUE(b.ok) << path << "\n" << b.messages();
    EXPECT_TRUE(b.m.control.erode_small_steps) << path;
  }
  Read bad_erode = read_text(hex_deck(kElastic, "*CONTROL_TIMESTEP\n       0.0       0.9         0       0.0       0.0         0         2\n"));
  EXPECT_FALSE(bad_erode.ok);
  EXPECT_NE(bad_erode.messages().find("ERODE"), std::string::npos) << bad_erode.messages();
  Read rigid = read_text(hex_deck("*MAT_RIGID\n         1    7800.0   2.0e11       0.3\n",
                                  "*MAT_ADD_EROSION\n         1       0.0     1.0E9\n"));
  EXPECT_FALSE(rigid.ok);
  EXPECT_NE(rigid.messages().find("erosion of a rigid body"), std::string::npos) << rigid.messages();
}

// Message 5004 names what deleted the solid (issue 25 defect 5): the squeezed null-material
// bar's solids go by CEROD, and the message says so (it said "effective plastic strain reached
// the failure strain" for every deletion).
TEST(Erosion, DeletionMessageNamesTheCause) {
  Model m = struck_bar(-40.0);
  MaterialData& md = m.materials[0];
  md.type = 9;
  set_param_defaults(md, material_type(9));
  md.rho = 1000;
  md.eos.form = 1;
  md.eos.c[1] = 2.2e9;
  param_value(md, *find_param(material_type(9), "CEROD")) = 0.99;
  for (int n = 0; n < m.num_nodes(); ++n) m.bc[std::size_t(n)] = m.z[std::size_t(n)] < 1e-12 ? 7 : 4;
  m.control.end_time = 4e-5;
  m.control.tssf = 0.5;
  const std::filesystem::path dir = test_support::empty_run_folder("erosion_message");
  RunOptions o = test_support::run_options_in(dir);
  std::ostringstream printed;
  run_simulation(m, o, printed);
  const std::string log = printed.str();
  const std::size_t at = log.find("info 5004: solid element failed and is deleted: solid element ");
  ASSERT_NE(at, std::string::npos) << log;
  const std::string line = log.substr(at, log.find('\n', at) - at);
  EXPECT_NE(line.find("below the erosion limit 0.990000 (CEROD)"), std::string::npos) << line;
  double rv = 0;
  ASSERT_NE(line.find("relative volume "), std::string::npos) << line;
  ASSERT_EQ(std::sscanf(line.c_str() + line.find("relative volume "), "relative volume %lf", &rv), 1) << line;
  EXPECT_LT(rv, 0.99);
  EXPECT_GT(rv, 0.9);
  EXPECT_EQ(log.find("plastic strain reached"), std::string::npos) << log;
}
