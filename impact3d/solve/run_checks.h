#pragma once
// The run checks (docs/command-line.md "Run checks"): what an analyst checks by hand in a run's energies,
// checked at every report of the run log and at the end.  Each cause is said once, as a
// numbered warning (5101-5105) in the printed file and on the terminal, naming the material
// (part) or the energy it is about; the run ends with a verdict (5110): clean, or suspect with
// its reasons.  impact3d --strict turns a suspect verdict into exit code 7.

#include <limits>
#include <string>
#include <vector>

#include "impact3d/model/model.h"
#include "impact3d/model/state.h"

namespace impact3d {

// The thresholds: one table.  A share is of the reference energy (initial energy + external
// work, the energy ratio's denominator) unless said otherwise.
struct RunCheckLimits {
  double hourglass_of_internal = 0.10;  // 5101: a material's hourglass / its (largest) internal energy
  double hourglass_floor = 1e-3;        //       ... once its hourglass energy is this share
  double energy_ratio_band = 0.05;      // 5102: |energy ratio - 1|
  double contact_share = -0.01;         // 5103: contact energy below this share
  double added_mass_percent = 5.0;      // 5104: added mass, percent of the model's mass
  long long contact_misses = 0;         // 5105: node-cycles not caught by contact, above this
};
inline constexpr RunCheckLimits kRunCheckLimits{};

// What the checks see of a run at one report: the state and the contact misses counted so far.
struct RunSnapshot {
  const Model& model;
  const State& state;
  long long contact_misses = 0;
  // The time-centred energy ratio at t^n (run_cycle.h), which the central-difference update
  // holds for linear forces; NaN where not known (before the first cycle, distributed runs):
  // 5102 then judges the ratio as printed.
  double centred_ratio = std::numeric_limits<double>::quiet_NaN();
};

class RunChecks {
 public:
  // Takes the energies at the start of the run (or of the restart) for the changes 5102 names.
  explicit RunChecks(const State& start, const RunCheckLimits& limits = kRunCheckLimits);

  // The checks at one report: the lines of the causes not said before (rendered messages).
  std::vector<std::string> check_state(const RunSnapshot& now);
  bool suspect() const { return !reasons_.empty(); }
  // The verdict (message 5110): clean, or suspect with the reasons, one line.
  std::string verdict_line() const;

 private:
  std::vector<std::string> check_hourglass_energy(const RunSnapshot& now);
  std::vector<std::string> check_energy_ratio(const RunSnapshot& now);
  std::vector<std::string> energy_swing(const RunSnapshot& now);
  std::vector<std::string> check_contact_energy(const RunSnapshot& now);
  std::vector<std::string> check_added_mass(const RunSnapshot& now);
  std::vector<std::string> check_contact_misses(const RunSnapshot& now);
  // The rendered message, and the reason kept for the verdict, the first time a cause is seen.
  bool first_time(const std::string& cause);
  std::string say(int id, const std::string& detail, const std::string& reason);

  RunCheckLimits limits_;
  double start_[7];                  // kinetic, internal, hourglass, bulk, walls, contact, external work
  std::vector<double> peak_internal_;  // per material: its largest internal energy at a report
  std::vector<std::string> causes_;  // said
  std::vector<std::string> reasons_;
};

}  // namespace impact3d
