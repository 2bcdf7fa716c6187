// *CASE (issue 16, verification): tests/cli/case_blocks.k has a base case (no initial velocity)
// and child cases 1 (vx = 100 m/s) and 2 (vz = 50 m/s) on one free 10 mm steel cube.  The
// impact3d binary runs the base case, case=1 and case=2 one after the other in one folder; each
// case's own glstat (the base case's next to o=, case N's in caseN/) must hold its own initial
// velocity: kinetic energy 1/2 m v^2 with m = rho V = 7.8 g (39 J, 9.75 J, 0) and the global
// velocity components, constant over the run (a rigid translation), and no run may change
// another run's files.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const std::string kImpact3d = IMPACT3D_BINARY_DIR "/impact3d";
const std::string kDeck = IMPACT3D_SOURCE_DIR "/tests/cli/case_blocks.k";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Every file under dir (relative path -> contents).
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return out;
}

// The values of a glstat line ("kinetic energy......   3.90000E+01"), one per state.
std::vector<double> glstat_values(const std::string& text, const std::string& label) {
  std::vector<double> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    const std::size_t k = l.find(label);
    if (k == std::string::npos || k > 2) continue;
    const std::size_t last = l.find_last_of(' ');  // the value is the last field
    v.push_back(std::strtod(l.c_str() + last + 1, nullptr));
  }
  return v;
}

struct Case {
  std::string arg;     // "" (base), "case=1", "case=2"
  std::string folder;  // where its outputs go, relative to the run folder
  double vx, vy, vz;   // its initial velocity (the deck's)
};

}  // namespace

TEST(CaseRuns, EachCaseGetsItsOwnVelocityAndItsOwnFiles) {
  const fs::path dir = fs::temp_directory_path() / ("impact3d_case_runs_" + std::to_string(long(::getpid())));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const double rho = 7800.0, volume = 1e-6, mass = rho * volume;
  const std::vector<Case> cases = {{"", ".", 0, 0, 0}, {"case=1", "case1", 100, 0, 0}, {"case=2", "case2", 0, 0, 50}};
  std::map<std::string, std::string> before;  // every file after the previous runs
  for (const Case& c : cases) {
    const std::string cmd = "cd '" + dir.string() + "' && '" + kImpact3d + "' i='" + kDeck + "' " + c.arg +
                            " ncpu=1 > run.log 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd << "\n" << slurp(dir / "run.log");
    std::map<std::string, std::string> after = files_under(dir);
    // the earlier runs' files are all still there, unchanged (run.log is this test's)
    for (const auto& [path, text] : before) {
      if (path == "run.log") continue;
      ASSERT_TRUE(after.count(path)) << c.arg << " removed " << path;
      EXPECT_TRUE(after[path] == text) << "running '" << c.arg << "' changed " << path;
    }
    // this run wrote its own glstat, d3plot and d3hsp in its folder
    const fs::path out = dir / c.folder;
    for (const char* f : {"glstat", "d3plot", "d3hsp"}) EXPECT_TRUE(fs::exists(out / f)) << c.arg << ": " << f;
    const std::string glstat = slurp(out / "glstat");
    const std::vector<double> ke = glstat_values(glstat, "kinetic energy");
    const std::vector<double> vx = glstat_values(glstat, "global x velocity");
    const std::vector<double> vy = glstat_values(glstat, "global y velocity");
    const std::vector<double> vz = glstat_values(glstat, "global z velocity");
    ASSERT_GE(ke.size(), 2u) << c.arg << "\n" << glstat;
    ASSERT_EQ(vx.size(), ke.size());
    ASSERT_EQ(vy.size(), ke.size());
    ASSERT_EQ(vz.size(), ke.size());
    const double ke_exact = 0.5 * mass * (c.vx * c.vx + c.vy * c.vy + c.vz * c.vz);
    // glstat prints 6 significant digits: 1e-5 relative (the base case: exactly 0)
    for (std::size_t k = 0; k < ke.size(); ++k) {
      EXPECT_NEAR(ke[k], ke_exact, 1e-5 * ke_exact) << c.arg << " state " << k;
      EXPECT_NEAR(vx[k], c.vx, 1e-5 * 100) << c.arg << " state " << k;
      EXPECT_NEAR(vy[k], c.vy, 1e-5 * 100) << c.arg << " state " << k;
      EXPECT_NEAR(vz[k], c.vz, 1e-5 * 100) << c.arg << " state " << k;
    }
    before = std::move(after);
  }
  // the three folders are distinct: the base case's glstat is not a case's
  EXPECT_NE(slurp(dir / "glstat"), slurp(dir / "case1" / "glstat"));
  EXPECT_NE(slurp(dir / "case1" / "glstat"), slurp(dir / "case2" / "glstat"));
  if (!HasFailure()) fs::remove_all(dir);
}
