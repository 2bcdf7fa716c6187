// *MAT_ADD_EROSION (MXPRES, MNPRES, SIGP1, SIGVM, VOLEPS, FAILTM, NCS, EXCL): a solid is deleted
// in the first cycle where its stress, volume or the time meets the criteria.  Each test runs
// the model once without erosion, finds the first cycle where some solids meet a criterion
// (computed here from the stress, independently of the solver's check), and requires the run
// with erosion to delete exactly those solids in exactly that cycle and none before; then the
// reader, its refusals and the converter.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/material/material.h"
#include "impact3d/solve/engine.h"
#include "tests/solve/test_models.h"

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
// cycles in, in the solids where rounding puts it first.
Model struck_bar(double v_top) {
  Model m = make_box_model({1, 1, 20, 0.0025, 0.0025, 0.05, 0, 0, 0}, copper_elastic(), 2e-5);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.z[std::size_t(n)] < 1e-12) m.bc[std::size_t(n)] = 3;
  set_velocity_field(m, [&](double, double, double z) { return std::array<double, 3>{0, 0, v_top * z / 0.05}; });
  return m;
}

using Criterion = std::function<bool(const double* sig, double vol_ratio, double t)>;

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

void expect_erosion_matches(const ErosionData& er, const Criterion& met, const char* what, double vz = -20) {
  Model plain = struck_bar(vz);
  const auto expected = first_meeting(plain, met);
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
  // the axial stress grows about 6 MPa a cycle, the pressure a third as fast
  ErosionData e = erosion();
  e.mxpres = 2.4e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return pressure_of(s) >= 2.4e8; }, "MXPRES");
  // pulled: tension
  e = erosion();
  e.mnpres = -4e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return pressure_of(s) <= -4e8; }, "MNPRES", 20);
}

TEST(Erosion, StressVolumeAndTimeCriteria) {
  ErosionData e = erosion();
  e.sigvm = 4.8e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return von_mises_of(s) >= 4.8e8; }, "SIGVM");
  e = erosion();
  e.sigp1 = 4.8e8;
  expect_erosion_matches(e, [](const double* s, double, double) { return largest_principal_of(s) >= 4.8e8; }, "SIGP1", 20);
  e = erosion();
  e.voleps = -3e-3;
  expect_erosion_matches(e, [](const double*, double v, double) { return v - 1 <= -3e-3; }, "VOLEPS");
  e = erosion();
  e.failtm = 4e-6;
  expect_erosion_matches(e, [](const double*, double, double t) { return t >= 4e-6; }, "FAILTM");
  // NCS 2: pressure and volumetric strain must hold at once
  e = erosion();
  e.mxpres = 1.5e8;
  e.voleps = -4e-3;
  e.ncs = 2;
  expect_erosion_matches(e, [](const double* s, double v, double) { return pressure_of(s) >= 1.5e8 && v - 1 <= -4e-3; }, "NCS 2");
  e.ncs = 1;  // either one: earlier
  expect_erosion_matches(e, [](const double* s, double v, double) { return pressure_of(s) >= 1.5e8 || v - 1 <= -4e-3; }, "NCS 1");
  // EXCL: a criterion equal to it is off (here MXPRES = EXCL = 1: only FAILTM acts)
  e = erosion();
  e.excl = 1;
  e.mxpres = 1;
  e.failtm = 4e-6;
  expect_erosion_matches(e, [](const double*, double, double t) { return t >= 4e-6; }, "EXCL");
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

struct Read {
  Model m;
  Diagnostics d;
  bool ok = false;
  std::string messages() const {
    std::ostringstream os;
    d.print(os);
    return os.str();
  }
};

Read read_text(const std::string& text) {
  Read r;
  DeckFile deck;
  deck.load_from_string("erosion.k", text);
  InputOptions o;
  r.ok = read_deck(deck, r.m, r.d, o);
  if (r.ok) r.ok = check_model(r.m, r.d);
  return r;
}

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
  // strain criteria, Tuler-Butcher and damage are not supported (1102, by field); an undefined
  // material is 1310; a rigid material 1102
  Read bad = read_text(hex_deck(kElastic,
                                "*MAT_ADD_EROSION\n         1       0.0       0.0     -0.10      0.30\n"
                                "       0.0       0.0       0.0      0.20      0.10     1.0E8       1.0\n"
                                "         1\n"
                                "*MAT_ADD_EROSION\n         5       0.0     1.0E9\n"));
  EXPECT_FALSE(bad.ok);
  for (const char* f : {"MNEPS", "EFFEPS", "MXEPS", "EPSSH", "SIGTH", "IMPULSE", "IDAM"})
    EXPECT_NE(bad.messages().find(std::string("\"") + f + "\""), std::string::npos) << f << "\n" << bad.messages();
  EXPECT_NE(bad.messages().find("error 1310"), std::string::npos) << bad.messages();
  Read rigid = read_text(hex_deck("*MAT_RIGID\n         1    7800.0   2.0e11       0.3\n",
                                  "*MAT_ADD_EROSION\n         1       0.0     1.0E9\n"));
  EXPECT_FALSE(rigid.ok);
  EXPECT_NE(rigid.messages().find("erosion of a rigid body"), std::string::npos) << rigid.messages();
}
