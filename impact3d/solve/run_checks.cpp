// The run checks (run_checks.h, docs/command-line.md "Run checks").

#include "impact3d/solve/run_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/messages.h"
#include "impact3d/solve/mass_scaling.h"

namespace impact3d {

namespace {

constexpr int kComponents = 7;
const char* const kComponentNames[kComponents] = {"kinetic",      "internal", "hourglass",    "bulk viscosity",
                                                  "rigid walls", "contact",  "external work"};

void energy_components(const State& s, double e[kComponents]) {
  e[0] = s.kinetic;
  e[1] = s.internal;
  e[2] = s.hourglass;
  e[3] = s.bulk_viscous;
  e[4] = s.wall_work;
  e[5] = s.contact;
  e[6] = s.external_work;
}

// The energy the run should hold: initial energy + external work (the ratio's denominator).
double reference_energy(const State& s) { return s.initial_total + s.external_work; }

// "material N" or "material N "title"" (the plot database's part N, POST-IMPACT's material N).
std::string material_name(const Model& m, std::size_t k) {
  const MaterialData& md = m.materials[k];
  std::string name = "material " + std::to_string(md.number);
  if (!md.title.empty()) name += " \"" + md.title + "\"";
  return name;
}

std::string at_cycle(const State& s) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "at cycle %d, time %.6e", s.cycle, s.time);
  return buf;
}

}  // namespace

RunChecks::RunChecks(const State& start, const RunCheckLimits& limits) : limits_(limits) {
  energy_components(start, start_);
}

std::vector<std::string> RunChecks::check_state(const RunSnapshot& now) {
  std::vector<std::string> lines;
  using Check = std::vector<std::string> (RunChecks::*)(const RunSnapshot&);
  for (Check check : {&RunChecks::check_hourglass_energy, &RunChecks::check_energy_ratio,
                      &RunChecks::check_contact_energy, &RunChecks::check_added_mass,
                      &RunChecks::check_contact_misses}) {
    std::vector<std::string> l = (this->*check)(now);
    lines.insert(lines.end(), l.begin(), l.end());
  }
  return lines;
}

bool RunChecks::first_time(const std::string& cause) {
  if (std::find(causes_.begin(), causes_.end(), cause) != causes_.end()) return false;
  causes_.push_back(cause);
  return true;
}

std::string RunChecks::say(int id, const std::string& detail, const std::string& reason) {
  reasons_.push_back(reason);
  return render(Diagnostic{id, message_def(id).severity, Location{}, detail});
}

// 5101, per material: hourglass energy above the share of its internal energy.
std::vector<std::string> RunChecks::check_hourglass_energy(const RunSnapshot& now) {
  const State& s = now.state;
  std::vector<std::string> lines;
  const double floor = limits_.hourglass_floor * std::fabs(reference_energy(s));
  const std::size_t n = std::min({s.mat_hourglass.size(), s.mat_internal.size(), now.model.materials.size()});
  peak_internal_.resize(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    // against the largest internal energy the part has had: an elastic part that gives its
    // strain energy back (a rebound) keeps the hourglass energy it took on the way
    const double hg = s.mat_hourglass[k], ie = s.mat_internal[k];
    peak_internal_[k] = std::max(peak_internal_[k], ie);
    const double against = peak_internal_[k];
    if (!(hg > floor) || !(hg > limits_.hourglass_of_internal * against)) continue;
    if (!first_time("hourglass " + std::to_string(k))) continue;
    const std::string name = material_name(now.model, k);
    char share[40] = "more than 1000 %";  // (an internal energy at round-off level)
    if (hg < 10 * against) std::snprintf(share, sizeof share, "%.1f %%", 100 * hg / against);
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "%s: hourglass energy %.4e = %s of its internal energy %.4e (the largest so far; limit %.0f %%) %s",
                  name.c_str(), hg, share, against, 100 * limits_.hourglass_of_internal, at_cycle(s).c_str());
    lines.push_back(say(5101, buf, "hourglass energy (" + name + ")"));
  }
  return lines;
}

// 5102: energy ratio outside the band, with the change of each energy since the start (as a
// share of the reference energy) and the one that moved most in the direction of the error.
// Judged on the time-centred ratio where it is known (the printed one swings with the energy in
// modes near the step's limit: 5106 says so when only the printed one leaves the band).
std::vector<std::string> RunChecks::check_energy_ratio(const RunSnapshot& now) {
  const State& s = now.state;
  const double printed = s.energy_ratio();
  const bool centred = std::isfinite(now.centred_ratio);
  const double ratio = centred ? now.centred_ratio : printed;
  const double ref = reference_energy(s);
  const double band = limits_.energy_ratio_band;
  if (ref == 0) return {};
  if (std::fabs(ratio - 1) <= band) return centred && std::fabs(printed - 1) > band ? energy_swing(now) : std::vector<std::string>{};
  const bool gained = ratio > 1;
  if (!first_time(gained ? "energy ratio high" : "energy ratio low")) return {};
  double e[kComponents];
  energy_components(s, e);
  std::string changes;
  int most = -1;
  double most_move = 0;
  for (int c = 0; c < kComponents; ++c) {
    // external work enters the denominator: its growth makes the ratio fall
    const double d = (e[c] - start_[c]) / std::fabs(ref);
    const double towards_error = (c == 6 ? -d : d) * (gained ? 1 : -1);
    if (towards_error > most_move) most_move = towards_error, most = c;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s %+.3f", changes.empty() ? "" : ", ", kComponentNames[c], d);
    changes += buf;
  }
  char printed_too[64] = "";
  if (centred) std::snprintf(printed_too, sizeof printed_too, " (time-centred; as printed %.5f)", printed);
  char buf[700];
  std::snprintf(buf, sizeof buf,
                "%.5f%s %s (band 1 +- %.2f): energy %s, %.1f %% of initial energy + external work; changes since the "
                "start, as shares of it: %s; moved most: %s",
                ratio, printed_too, at_cycle(s).c_str(), band, gained ? "gained" : "lost", 100 * std::fabs(ratio - 1),
                changes.c_str(), most >= 0 ? kComponentNames[most] : "none");
  return {say(5102, buf,
              std::string("energy ratio ") + (gained ? "above" : "below") + " the band (" +
                  (most >= 0 ? kComponentNames[most] : "none") + " moved most)")};
}

// 5106: the printed ratio leaves the band while the time-centred one holds: the kinetic energy
// (at t^{n+1/2}) and the element energies (at t^{n+1}) are half a step apart, and much of the
// energy sits in modes near the step's limit (a sudden load on a coarse mesh). Said once.
std::vector<std::string> RunChecks::energy_swing(const RunSnapshot& now) {
  if (!first_time("energy ratio swings")) return {};
  char buf[700];
  std::snprintf(buf, sizeof buf,
                "%.5f as printed %s, outside the band 1 +- %.2f, while the time-centred ratio is %.5f: no energy "
                "gained or lost, but much of it in modes near the step's limit (a sudden load on a coarse mesh; a "
                "smaller TSSFAC or a finer mesh resolves them; a printed ratio that keeps growing is a mode past the limit, "
                "which the time-centred book does not see: the run stops at 10, error 4007)",
                now.state.energy_ratio(), at_cycle(now.state).c_str(), limits_.energy_ratio_band, now.centred_ratio);
  return {say(5106, buf, "energy ratio swings (modes near the step's limit)")};
}

// 5103: contact energy below its (negative) share of the reference energy.
std::vector<std::string> RunChecks::check_contact_energy(const RunSnapshot& now) {
  const State& s = now.state;
  const double ref = std::fabs(reference_energy(s));
  if (ref == 0 || !(s.contact < limits_.contact_share * ref) || !first_time("contact energy")) return {};
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "contact energy %.4e = %.2f %% of initial energy + external work %.4e (limit %.1f %%) %s: contact "
                "forces did that much net work on the model",
                s.contact, 100 * s.contact / ref, ref, 100 * limits_.contact_share, at_cycle(s).c_str());
  return {say(5103, buf, "negative contact energy")};
}

// 5104: added mass (mass scaling) above its share of the model's mass, with the material that
// took the most.
std::vector<std::string> RunChecks::check_added_mass(const RunSnapshot& now) {
  const State& s = now.state;
  const double pct = added_mass_percent(s);
  if (!(pct > limits_.added_mass_percent) || !first_time("added mass")) return {};
  std::size_t most = 0;
  for (std::size_t k = 1; k < s.mat_added_mass.size(); ++k)
    if (s.mat_added_mass[k] > s.mat_added_mass[most]) most = k;
  std::string where;
  if (most < s.mat_added_mass.size() && most < now.model.materials.size() && s.added_mass > 0)
    where = ", most to " + material_name(now.model, most) + " (" +
            std::to_string(int(std::lround(100 * s.mat_added_mass[most] / s.added_mass))) + " % of it)";
  char buf[400];
  std::snprintf(buf, sizeof buf, "%.2f %% of the model's mass (limit %.1f %%) %s%s", pct, limits_.added_mass_percent,
                at_cycle(s).c_str(), where.c_str());
  return {say(5104, buf, "added mass")};
}

// 5105: slave nodes that contact found deeper than penetration growth allows and did not catch.
std::vector<std::string> RunChecks::check_contact_misses(const RunSnapshot& now) {
  if (now.contact_misses <= limits_.contact_misses || !first_time("contact misses")) return {};
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "%lld node-cycle(s) so far %s: nodes found deeper than penetration growth allows were left free "
                "(README, Contact)",
                now.contact_misses, at_cycle(now.state).c_str());
  return {say(5105, buf, "nodes not caught by contact")};
}

std::string RunChecks::verdict_line() const {
  std::string detail;
  if (reasons_.empty()) {
    detail = "clean: hourglass energy, energy ratio, contact energy, added mass and contact misses within their limits "
             "at every report";
  } else {
    detail = "suspect: ";
    for (std::size_t k = 0; k < reasons_.size(); ++k) detail += (k ? "; " : "") + reasons_[k];
    detail += " (the warnings above)";
  }
  return render(Diagnostic{5110, message_def(5110).severity, Location{}, detail});
}

}  // namespace impact3d
