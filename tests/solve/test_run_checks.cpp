// The run checks (impact3d/solve/run_checks.h, docs/command-line.md "Run checks", issue 25): each warning at
// its threshold of the one table, said once per cause; the verdict; decks that trip a warning
// and one that trips none, run as impact3d runs them.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "impact3d/init/shell_init.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/run_checks.h"
#include "../support/deck_text.h"

using namespace impact3d;

namespace {

// A model of two materials and a state of energies as the checks read them: initial energy
// 100, no external work, everything else set by the test.
struct Books {
  Model m;
  State s;
  Books() {
    for (int k = 0; k < 2; ++k) {
      MaterialData md;
      md.number = k + 1;
      md.title = k == 0 ? "plate" : "bird";
      m.materials.push_back(md);
    }
    s.initial_total = 100;
    s.kinetic = 100;
    s.mat_internal.assign(2, 0.0);
    s.mat_hourglass.assign(2, 0.0);
    s.mat_added_mass.assign(2, 0.0);
    s.physical_mass = 10;
  }
};

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

int count_of(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(RunChecks, CleanBooksSayNothingAndTheVerdictIsClean) {
  Books b;
  RunChecks c(b.s);
  b.s.kinetic = 60;
  b.s.internal = 40;
  b.s.mat_internal = {30, 10};
  b.s.mat_hourglass = {2.9, 0.9};  // below 10 % of each
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());
  EXPECT_FALSE(c.suspect());
  EXPECT_NE(c.verdict_line().find("info 5110: run verdict: clean"), std::string::npos) << c.verdict_line();
}

// 5101: per material, against its largest internal energy so far; once per material.
TEST(RunChecks, HourglassEnergyOfAPartAboveTenPercentOfItsInternalEnergy) {
  Books b;
  RunChecks c(b.s);
  b.s.mat_internal = {30, 10};
  b.s.mat_hourglass = {2.9, 1.1};  // material 2: 11 %
  std::string out = joined(c.check_state({b.m, b.s, 0}));
  EXPECT_EQ(count_of(out, "warning 5101"), 1) << out;
  EXPECT_NE(out.find("material 2 \"bird\": hourglass energy 1.1000e+00 = 11.0 % of its internal energy 1.0000e+01"),
            std::string::npos)
      << out;
  // the bird gives its strain energy back (a rebound): still against its largest, and not said again
  b.s.mat_internal = {30, 0.5};
  b.s.mat_hourglass = {2.9, 1.2};
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());
  // the plate now too
  b.s.mat_hourglass = {3.1, 1.2};
  out = joined(c.check_state({b.m, b.s, 0}));
  EXPECT_EQ(count_of(out, "warning 5101"), 1) << out;
  EXPECT_NE(out.find("material 1 \"plate\""), std::string::npos) << out;
  EXPECT_TRUE(c.suspect());
  const std::string v = c.verdict_line();
  EXPECT_NE(v.find("suspect: hourglass energy (material 2 \"bird\"); hourglass energy (material 1 \"plate\")"),
            std::string::npos)
      << v;
  // an hourglass energy below the floor (0.1 % of the reference energy) is noise, not a cause
  Books q;
  RunChecks cq(q.s);
  q.s.mat_internal = {0.01, 0};
  q.s.mat_hourglass = {0.09, 0};
  EXPECT_TRUE(cq.check_state({q.m, q.s, 0}).empty());
}

// 5102: outside 1 +- 5 %, with the energy that moved; gain and loss are two causes.
TEST(RunChecks, EnergyRatioOutsideItsBandNamesTheEnergyThatMoved) {
  Books b;
  RunChecks c(b.s);
  b.s.kinetic = 50;
  b.s.internal = 54.9;  // ratio 1.049: inside
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());
  b.s.hourglass = 10;  // ratio 1.149: hourglass energy appeared from nowhere
  std::string out = joined(c.check_state({b.m, b.s, 0}));
  EXPECT_EQ(count_of(out, "warning 5102"), 1) << out;
  EXPECT_NE(out.find("1.14900 at cycle"), std::string::npos) << out;
  EXPECT_NE(out.find("energy gained, 14.9 %"), std::string::npos) << out;
  EXPECT_NE(out.find("kinetic -0.500, internal +0.549, hourglass +0.100"), std::string::npos) << out;
  EXPECT_NE(out.find("moved most: internal"), std::string::npos) << out;
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());  // said once
  // the other side is another cause; external work counts against the ratio
  b.s.hourglass = 0;
  b.s.internal = 40;
  b.s.external_work = 20;  // (50 + 40) / 120 = 0.75
  out = joined(c.check_state({b.m, b.s, 0}));
  EXPECT_EQ(count_of(out, "warning 5102"), 1) << out;
  EXPECT_NE(out.find("energy lost, 25.0 %"), std::string::npos) << out;
  EXPECT_NE(out.find("moved most: kinetic"), std::string::npos) << out;
  EXPECT_NE(c.verdict_line().find("energy ratio above the band (internal moved most); energy ratio below the band"),
            std::string::npos)
      << c.verdict_line();
}

// 5102 with the time-centred ratio known (a run's checks): judged on it, the printed ratio
// beside it; 5106 when only the printed ratio leaves the band (the swing of energy in modes near
// the step's limit), said once; it makes the verdict suspect with its own reason.
TEST(RunChecks, TimeCentredRatioJudgesThePrintedSwing) {
  Books b;
  RunChecks c(b.s);
  b.s.kinetic = 70;
  b.s.internal = 60;  // printed 1.30
  std::string out = joined(c.check_state({b.m, b.s, 0, 1.0004}));
  EXPECT_EQ(count_of(out, "warning 5102"), 0) << out;
  EXPECT_EQ(count_of(out, "warning 5106"), 1) << out;
  EXPECT_NE(out.find("1.30000 as printed at cycle"), std::string::npos) << out;
  EXPECT_NE(out.find("while the time-centred ratio is 1.00040: no energy gained or lost"), std::string::npos) << out;
  EXPECT_TRUE(c.check_state({b.m, b.s, 0, 1.0004}).empty());  // said once
  EXPECT_TRUE(c.suspect());
  EXPECT_NE(c.verdict_line().find("suspect: energy ratio swings (modes near the step's limit)"), std::string::npos)
      << c.verdict_line();
  // the time-centred ratio out of the band: 5102, on it
  out = joined(c.check_state({b.m, b.s, 0, 1.08}));
  EXPECT_EQ(count_of(out, "warning 5102"), 1) << out;
  EXPECT_NE(out.find("1.08000 (time-centred; as printed 1.30000) at cycle"), std::string::npos) << out;
  EXPECT_NE(out.find("energy gained, 8.0 %"), std::string::npos) << out;
  // both inside: nothing
  Books q;
  RunChecks cq(q.s);
  q.s.kinetic = 60;
  q.s.internal = 42;
  EXPECT_TRUE(cq.check_state({q.m, q.s, 0, 1.001}).empty());
}

// 5103: contact energy below -1 % of initial energy + external work.
TEST(RunChecks, NegativeContactEnergyBeyondOnePercent) {
  Books b;
  RunChecks c(b.s);
  b.s.kinetic = 100.9;
  b.s.contact = -0.9;
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());
  b.s.kinetic = 101.1;
  b.s.contact = -1.1;
  const std::string out = joined(c.check_state({b.m, b.s, 0}));
  EXPECT_EQ(count_of(out, "warning 5103"), 1) << out;
  EXPECT_NE(out.find("contact energy -1.1000e+00 = -1.10 % of initial energy + external work 1.0000e+02"),
            std::string::npos)
      << out;
  EXPECT_EQ(count_of(out, "warning 5102"), 0) << out;  // the ratio itself holds: only 5103 tells
}

// 5104: added mass above 5 % of the model's mass, naming the material that took the most.
TEST(RunChecks, AddedMassAboveFivePercent) {
  Books b;
  RunChecks c(b.s);
  b.s.added_mass = 0.5;  // 5 %: not above
  b.s.mat_added_mass = {0.1, 0.4};
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());
  b.s.added_mass = 0.6;
  b.s.mat_added_mass = {0.1, 0.5};
  const std::string out = joined(c.check_state({b.m, b.s, 0}));
  EXPECT_EQ(count_of(out, "warning 5104"), 1) << out;
  EXPECT_NE(out.find("6.00 % of the model's mass (limit 5.0 %)"), std::string::npos) << out;
  EXPECT_NE(out.find("most to material 2 \"bird\" (83 % of it)"), std::string::npos) << out;
}

// 5105: nodes that contact found too deep and left free.
TEST(RunChecks, NodesNotCaughtByContact) {
  Books b;
  RunChecks c(b.s);
  EXPECT_TRUE(c.check_state({b.m, b.s, 0}).empty());
  const std::string out = joined(c.check_state({b.m, b.s, 3}));
  EXPECT_EQ(count_of(out, "warning 5105"), 1) << out;
  EXPECT_NE(out.find("3 node-cycle(s) so far"), std::string::npos) << out;
  EXPECT_TRUE(c.check_state({b.m, b.s, 7}).empty());
}

namespace {

// One free unit hexahedron (mm, t, s; steel) with nodal velocities vx(node), TSSF 0.5 (a free
// single solid's breathing mode needs it), and DT2MS when not 0.
std::string one_hex_deck(const double vx[8], double dt2ms) {
  const int xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::string s = "*KEYWORD\n*TITLE\none hex\n*CONTROL_TERMINATION\n   2.0E-05\n*CONTROL_TIMESTEP\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "       0.0       0.5         0       0.0%10.3g\n", dt2ms);
  s += buf;
  s += "*PART\ncube\n         1         1         1\n*SECTION_SOLID\n         1         1\n"
       "*MAT_ELASTIC\n         17.85000E-9  200000.0       0.3\n*NODE\n";
  for (int i = 0; i < 8; ++i) {
    std::snprintf(buf, sizeof buf, "%8d%16.1f%16.1f%16.1f\n", i + 1, double(xyz[i][0]), double(xyz[i][1]), double(xyz[i][2]));
    s += buf;
  }
  s += "*ELEMENT_SOLID\n       1       1       1       2       3       4       5       6       7       8\n"
       "*INITIAL_VELOCITY_NODE\n";
  for (int i = 0; i < 8; ++i) {
    std::snprintf(buf, sizeof buf, "%10d%10.1f       0.0       0.0\n", i + 1, vx[i]);
    s += buf;
  }
  return s + "*END\n";
}

struct RunResult {
  int code = -1;
  std::string log;
};

RunResult run_deck(const std::string& text, const std::string& name, bool strict) {
  RunResult r;
  Model m;
  Diagnostics d;
  DeckFile deck;
  deck.load_from_string(name + ".k", text);
  if (!read_deck(deck, m, d, InputOptions{}) || !check_model(m, d)) {
    std::ostringstream os;
    d.print(os);
    r.log = os.str();
    return r;
  }
  const std::filesystem::path dir = test_support::empty_run_folder("run_checks", name);
  RunOptions o = test_support::run_options_in(dir);
  o.strict = strict;
  {
    std::ofstream printed(o.printed);
    r.code = run_simulation(m, o, printed);
  }
  std::ifstream in(o.printed);
  r.log.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
}

}  // namespace

// A rigid translation: no warning, a clean verdict, exit 0 even with --strict.
TEST(RunChecksDecks, TranslatingHexIsClean) {
  const double vx[8] = {1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000};
  const RunResult r = run_deck(one_hex_deck(vx, 0), "translating", true);
  EXPECT_EQ(r.code, 0) << r.log;
  EXPECT_EQ(count_of(r.log, "warning 51"), 0) << r.log;
  EXPECT_NE(r.log.find("info 5110: run verdict: clean"), std::string::npos) << r.log;
}

// The pure hourglass mode (1 -1 1 -1 1 -1 1 -1 in x: orthogonal to every linear field, so the
// one-point solid sees no strain): its kinetic energy goes to the viscous hourglass control,
// none to internal energy.  5101 names the part; --strict exits 7, without it 0.
TEST(RunChecksDecks, HourglassModeTripsTheHourglassCheck) {
  const double vx[8] = {1000, -1000, 1000, -1000, 1000, -1000, 1000, -1000};
  const RunResult strict = run_deck(one_hex_deck(vx, 0), "hourglass", true);
  EXPECT_EQ(strict.code, exit_code::suspect_run) << strict.log;
  EXPECT_EQ(count_of(strict.log, "warning 5101"), 1) << strict.log;
  EXPECT_NE(strict.log.find("warning 5101: hourglass energy of a part is large against its internal energy: material 1 \"cube\""),
            std::string::npos)
      << strict.log;
  EXPECT_NE(strict.log.find("info 5110: run verdict: suspect: hourglass energy (material 1 \"cube\")"), std::string::npos)
      << strict.log;
  EXPECT_NE(strict.log.find("N o r m a l   t e r m i n a t i o n"), std::string::npos) << strict.log;
  EXPECT_EQ(run_deck(one_hex_deck(vx, 0), "hourglass_lenient", false).code, 0);
}

// Mass scaling to a step about 6.5 times the solid's: 5104.
TEST(RunChecksDecks, MassScalingTripsTheAddedMassCheck) {
  const double vx[8] = {1000, 1000, 1000, 1000, 1000, 1000, 1000, 1000};
  const RunResult r = run_deck(one_hex_deck(vx, -1e-6), "added_mass", true);
  EXPECT_EQ(r.code, exit_code::suspect_run) << r.log;
  EXPECT_EQ(count_of(r.log, "warning 5104"), 1) << r.log;
  EXPECT_NE(r.log.find("most to material 1 \"cube\" (100 % of it)"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find("info 5110: run verdict: suspect: added mass"), std::string::npos) << r.log;
}

// A run that blows up stops (4007, exit 5) instead of ending "Normal termination": the free
// hexahedron in its hourglass mode (x velocities 1 -1 1 -1 1 -1 1 -1), TSSFAC 0.9, with the
// stiffness form at QM 50 (far past any sensible value: the hourglass stiffness, which the step
// does not see, makes the mode unstable). Before 4007 this run ended normally with an energy
// ratio of 1.4e43 and exit code 0 (2026-11-28); it now stops on the first cycle past 10.
TEST(RunChecksDecks, DivergingRunStopsWithAnError) {
  const double vx[8] = {1000, -1000, 1000, -1000, 1000, -1000, 1000, -1000};
  std::string s = one_hex_deck(vx, 0);
  auto replace = [&s](const std::string& a, const std::string& b) {
    const std::size_t at = s.find(a);
    ASSERT_NE(at, std::string::npos) << a;
    s.replace(at, a.size(), b);
  };
  replace("       0.0       0.5", "       0.0       0.9");
  replace("         1         1         1\n", "         1         1         1         0         1\n");
  replace("*NODE\n", "*HOURGLASS\n         1         4      50.0\n*NODE\n");
  const RunResult r = run_deck(s, "diverging", false);
  EXPECT_EQ(r.code, exit_code::error_termination) << r.log;
  const std::size_t at = r.log.find("error 4007: the run diverged: its energy grew without a source: total energy ");
  ASSERT_NE(at, std::string::npos) << r.log;
  const std::size_t times = r.log.find(" is ", at);
  ASSERT_NE(times, std::string::npos) << r.log;
  const double ratio = std::stod(r.log.substr(times + 4, 12));
  EXPECT_GT(ratio, kDivergedEnergyRatio) << r.log;
  EXPECT_LT(ratio, 1e4) << r.log;  // the first cycle past the limit, not 1e43
  EXPECT_NE(r.log.find("E r r o r   t e r m i n a t i o n   (the run diverged"), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("N o r m a l   t e r m i n a t i o n"), std::string::npos) << r.log;
}

namespace {

// Two strips of 6 x `wide` shells (10 mm, t = 1 mm, steel, nu as given) sharing the nodes of
// the line x = 60 mm; the upper one (x 40-100 mm) lies 1 mm above the lower (x 0-60 mm) but for
// that line: a kink. The upper strip's own nodes start at 1 m/s along x; TSSFAC as given.
std::string kinked_strips_deck(int wide, double nu, double tssfac) {
  std::map<std::array<long, 3>, int> ids;
  std::string nodes, elements;
  char buf[160];
  auto node = [&](int i, int j, bool up) {
    const std::array<long, 3> k{i, j, up && i != 6 ? 1 : 0};
    auto [it, added] = ids.emplace(k, int(ids.size()) + 1);
    if (added) {
      std::snprintf(buf, sizeof buf, "%8d%16.8g%16.8g%16.8g\n", it->second, 0.01 * i, 0.01 * j, 0.001 * double(k[2]));
      nodes += buf;
    }
    return it->second;
  };
  std::set<int> lower, upper;
  int e = 0;
  for (int part = 1; part <= 2; ++part)
    for (int j = 0; j < wide; ++j)
      for (int i = part == 1 ? 0 : 4; i < (part == 1 ? 6 : 10); ++i) {
        const bool up = part == 2;
        const int c[4] = {node(i, j, up), node(i + 1, j, up), node(i + 1, j + 1, up), node(i, j + 1, up)};
        std::snprintf(buf, sizeof buf, "%8d%8d%8d%8d%8d%8d\n", ++e, part, c[0], c[1], c[2], c[3]);
        elements += buf;
        (up ? upper : lower).insert(c, c + 4);
      }
  std::snprintf(buf, sizeof buf, "*CONTROL_TIMESTEP\n       0.0%10.3f\n", tssfac);
  std::string s = "*KEYWORD\n*TITLE\nkinked strips\n" + std::string(buf) +
                  "*CONTROL_TERMINATION\n    0.0005\n*PART\nlower\n         1         1         1\n*PART\nupper\n"
                  "         2         1         1\n*SECTION_SHELL\n         1         2       1.0         2\n"
                  "     0.001     0.001     0.001     0.001\n*MAT_ELASTIC\n";
  std::snprintf(buf, sizeof buf, "         1    7850.0   2.1e+11%10.3f\n", nu);
  s += buf + ("*NODE\n" + nodes) + "*ELEMENT_SHELL\n" + elements + "*INITIAL_VELOCITY_NODE\n";
  for (int n : upper)
    if (!lower.count(n)) {
      std::snprintf(buf, sizeof buf, "%8d       1.0       0.0       0.0\n", n);
      s += buf;
    }
  return s + "*END\n";
}

double final_energy_ratio(const std::string& log) {
  const std::string key = "energy ratio (total/(initial+ext)) ...";
  const std::size_t at = log.rfind(key);
  return at == std::string::npos ? -1 : std::stod(log.substr(at + key.size()));
}

}  // namespace

// The thickness-shear mode of a one-point shell (every node turning by theta, no translation:
// gamma = theta over the whole shell) has omega^2 = kappa G h A / (4 I) with I each corner's
// rotary inertia; with I = m_corner max(h^2/12, A/8), m_corner = rho h A / 4, its step 2 / omega
// is at least sqrt(1 / (kappa (1 - nu))) L / c (c the plate wave speed, L = sqrt(A)) = 1.095 at
// nu = 0, above any TSSFAC: the rotations never set the step (docs/shells.md, "Kinks and the
// rotary inertia"; before, m (h^2 + A)/12 gave 0.894 at nu = 0).
TEST(ShellRotaryInertia, ThicknessShearModeIsSlowerThanTheStep) {
  const double kappa = 5.0 / 6.0, E = 2.1e11, rho = 7850;
  for (double nu : {0.0, 0.3, 0.49})
    for (double h_over_L : {0.001, 0.1, 0.5, 2.0}) {
      const double L = 0.01, A = L * L, h = h_over_L * L, G = E / (2 * (1 + nu));
      const double I = shell_rotary_inertia(rho * h * A / 4, h, A);
      const double omega = std::sqrt(kappa * G * h * A / (4 * I));
      const double c = std::sqrt(E / (rho * (1 - nu * nu)));
      EXPECT_GE(2 / omega, std::min(1.0954, std::sqrt(1 / (kappa * (1 - nu)))) * L / c * (1 - 1e-12))
          << "nu " << nu << " h/L " << h_over_L;
    }
}

// Two kinked strips 4 shells wide of a material with nu = 0 at TSSFAC 0.9 run to their end
// (before the rotary inertia m max(h^2/12, A/8): error 4001, a shell turned inside out at cycle
// 22), as does a one-element-wide pair with nu = 0.3 (before: 4001 at cycle 48). The printed
// ratio swings (the velocity jump puts energy in modes near the step's limit: 5106), the run ends
// normally.
TEST(ShellRotaryInertia, KinkedStripAtNuZeroRunsAtTheDefaultStep) {
  for (auto [wide, nu] : {std::pair{4, 0.0}, std::pair{1, 0.3}}) {
    const RunResult r = run_deck(kinked_strips_deck(wide, nu, 0.9), "kinked_" + std::to_string(wide), false);
    EXPECT_EQ(r.code, 0) << r.log;
    EXPECT_NE(r.log.find("N o r m a l   t e r m i n a t i o n"), std::string::npos) << r.log;
    EXPECT_EQ(r.log.find("E r r o r"), std::string::npos) << r.log;
    const double ratio = final_energy_ratio(r.log);
    EXPECT_GT(ratio, 0.95) << r.log;
    EXPECT_LT(ratio, 1.3) << r.log;
  }
}

// A free strip of 6 x 1 Belytschko-Tsay shells (10 mm, 1 mm steel with nu = 0, IHQ 1 QM 0.1,
// TSSFAC 0.9) whose right half starts at 1 m/s along it: a velocity jump on a mesh this coarse
// puts much of the energy in modes near the step's limit, and the printed ratio swings (1.07 at
// cycle 100, kinetic energy half a step behind the element energies); the time-centred ratio
// stays at 1.0001 (docs/shells.md, "Energy books under sudden loads"). 5106, not 5102 (before the
// viscous hourglass fix and this check: "energy gained", 5102). The last step lands on the end
// time at 0.2 of the step: the time-centred book takes the velocity increment as an equal step
// would have made it (without that, the end check said 5102, 1.076).
TEST(RunChecksDecks, StruckShellStripSwingsButHoldsItsBalance) {
  std::string s = "*KEYWORD\n*TITLE\nstrip\n*CONTROL_TERMINATION\n    0.0005\n*PART\nstrip\n         1         1         1\n"
                  "*SECTION_SHELL\n         1         2       1.0         2\n     0.001     0.001     0.001     0.001\n"
                  "*MAT_ELASTIC\n         1    7850.0   2.1e+11       0.0\n*NODE\n";
  char buf[120];
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 7; ++i) {
      std::snprintf(buf, sizeof buf, "%8d%16.3f%16.3f%16.1f\n", 7 * j + i + 1, 0.01 * i, 0.01 * j, 0.0);
      s += buf;
    }
  s += "*ELEMENT_SHELL\n";
  for (int i = 0; i < 6; ++i) {
    std::snprintf(buf, sizeof buf, "%8d%8d%8d%8d%8d%8d\n", i + 1, 1, i + 1, i + 2, i + 9, i + 8);
    s += buf;
  }
  s += "*INITIAL_VELOCITY_NODE\n";
  for (int n : {5, 6, 7, 12, 13, 14}) {
    std::snprintf(buf, sizeof buf, "%8d       1.0       0.0       0.0\n", n);
    s += buf;
  }
  s += "*END\n";
  const RunResult r = run_deck(s, "struck_strip", false);
  EXPECT_EQ(r.code, 0) << r.log;
  EXPECT_EQ(count_of(r.log, "warning 5102"), 0) << r.log;
  EXPECT_EQ(count_of(r.log, "warning 5106"), 1) << r.log;
  const std::size_t at = r.log.find("while the time-centred ratio is ");
  ASSERT_NE(at, std::string::npos) << r.log;
  const double centred = std::stod(r.log.substr(at + 32, 8));
  EXPECT_NEAR(centred, 1.0, 1e-3) << r.log;
  EXPECT_NE(r.log.find("N o r m a l   t e r m i n a t i o n"), std::string::npos) << r.log;
}
