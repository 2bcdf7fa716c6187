// Run-log lines about the model's state (run_report.h).

#include "impact3d/solve/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "impact3d/solve/mass_scaling.h"
#include "impact3d/solve/spot_weld.h"

namespace impact3d {

std::string energy_report(const State& s) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "     kinetic energy ....................... %14.6e\n"
                "     internal energy ...................... %14.6e\n"
                "     hourglass energy ..................... %14.6e\n"
                "     bulk viscosity energy ................ %14.6e\n"
                "     rigid-wall energy (taken by walls) ... %14.6e\n"
                "     contact energy ....................... %14.6e\n"
                "     external work ........................ %14.6e\n"
                "     total energy ......................... %14.6e\n"
                "     initial total energy ................. %14.6e\n"
                "     energy ratio (total/(initial+ext)) ... %14.6f",
                s.kinetic, s.internal, s.hourglass, s.bulk_viscous, s.wall_work, s.contact,
                s.external_work, s.total_energy(), s.initial_total, s.energy_ratio());
  return buf;
}

std::string mass_scaling_report(const ControlData& k, const State& s) {
  char buf[400];
  std::snprintf(buf, sizeof buf,
                " mass scaling (DT2MS %.5e%s): element steps held at >= %.5e, run step >= %.5e\n"
                "     added mass ........................... %14.6e\n"
                "     model mass without it ................ %14.6e\n"
                "     percentage increase .................. %14.6f",
                k.mass_scaling_dt, k.mass_scaling_first_only ? ", first cycle only" : "",
                std::fabs(k.mass_scaling_dt), k.tssf * std::fabs(k.mass_scaling_dt), s.added_mass, s.physical_mass,
                added_mass_percent(s));
  return buf;
}

std::string describe_solid_failure(const Model& m, const State& s, int e, FailCause cause) {
  const std::size_t E = std::size_t(e);
  const MaterialConstants& mc = s.mats[std::size_t(s.mat[E])];
  const double rv = s.vol0[E] > 0 ? s.vol[E] / s.vol0[E] : 0.0;
  char why[200];
  switch (cause) {
    case FailCause::plastic_strain:
      std::snprintf(why, sizeof why, "effective plastic strain %.6e reached the failure strain %.6e", s.eps_p[E], mc.fail_strain);
      break;
    case FailCause::time_step:
      std::snprintf(why, sizeof why, "its time step fell below TDEL %.6e", mc.tdel);
      break;
    case FailCause::damage:
      std::snprintf(why, sizeof why, "its damage reached 1 (effective plastic strain %.6e)", s.eps_p[E]);
      break;
    case FailCause::volume_high:
      std::snprintf(why, sizeof why, "relative volume %.6f above the erosion limit %.6f (TEROD)", rv, mc.vol_erode_hi);
      break;
    case FailCause::volume_low:
      std::snprintf(why, sizeof why, "relative volume %.6f below the erosion limit %.6f (CEROD)", rv, mc.vol_erode_lo);
      break;
    case FailCause::erosion:
      std::snprintf(why, sizeof why, "*MAT_ADD_EROSION criteria met (relative volume %.6f, effective plastic strain %.6e)", rv,
                    s.eps_p[E]);
      break;
    case FailCause::none:
      std::snprintf(why, sizeof why, "effective plastic strain %.6e", s.eps_p[E]);
      break;
  }
  char buf[320];
  std::snprintf(buf, sizeof buf, "solid element %d at cycle %d, time %.6e: %s", m.hex_id(e), s.cycle, s.time, why);
  return buf;
}

std::string describe_beam_failure(const Model& m, const State& s, int b) {
  const BeamState& bm = s.beams;
  const double* r = &bm.res[6 * std::size_t(b)];
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "beam element %d (material %d) at cycle %d, time %.6e: *MAT_SPOTWELD failure rule met "
                "(N %.4e, Q_s %.4e, Q_t %.4e, T %.4e, M_s %.4e, M_t %.4e)",
                m.beam_id(b), m.materials[std::size_t(bm.mat[std::size_t(b)])].number, s.cycle, s.time, r[0], r[1], r[2], r[3], r[4], r[5]);
  return buf;
}

std::string describe_weld_release(const Model& m, const State& s, int r) {
  const RigidBody& rb = s.rigid[std::size_t(r)];
  const SpotWeld& w = m.spot_welds[std::size_t(rb.weld)];
  // what released it: the time, else the plastic strain at a node (EP, EPSF), else the forces
  std::string why = s.time >= w.tfail ? "its failure time" : "its failure forces";
  if (s.time < w.tfail && w.epsf > 0) {
    for (int n : w.nodes) {
      const double e = spot_weld_node_plastic_strain(s, n);
      if (e < w.epsf) continue;
      char b[160];
      std::snprintf(b, sizeof b, "the plastic strain %.6e at node %d reached its failure strain %.6e", e, m.node_id(n), w.epsf);
      why = b;
      break;
    }
  }
  char buf[480];
  std::snprintf(buf, sizeof buf, "%s weld %d%s (nodes %d, %d%s) at cycle %d, time %.6e: %s",
                w.generalized ? "*CONSTRAINED_GENERALIZED_WELD_SPOT" : "*CONSTRAINED_SPOTWELD", rb.weld + 1,
                w.id ? (" WID " + std::to_string(w.id)).c_str() : "", m.node_id(w.nodes[0]), m.node_id(w.nodes[1]),
                w.nodes.size() > 2 ? ", ..." : "", s.cycle, s.time, why.c_str());
  return buf;
}

namespace {

void take_node(FinalShape& f, const State& s, int n) {
  const double p[3] = {s.x[std::size_t(n)], s.y[std::size_t(n)], s.z[std::size_t(n)]};
  if (!f.any_live) {
    for (int a = 0; a < 3; ++a) f.lo[a] = f.hi[a] = p[a];
    f.any_live = true;
    return;
  }
  for (int a = 0; a < 3; ++a) {
    f.lo[a] = std::min(f.lo[a], p[a]);
    f.hi[a] = std::max(f.hi[a], p[a]);
  }
}

// The live solids' extents and largest plastic strain.
void measure_solids(FinalShape& f, const State& s) {
  for (int e = 0; e < s.ne; ++e) {
    const std::size_t E = std::size_t(e);
    if (s.failed[E]) {
      ++f.failed_solids;
      continue;
    }
    for (int n : s.conn[E]) take_node(f, s, n);
    if (f.max_eps_solid < 0 || s.eps_p[E] > f.solid_eps) f.max_eps_solid = e, f.solid_eps = s.eps_p[E];
  }
}

// The live shells' extents and largest point plastic strain (plastic kernels only).
void measure_shells(FinalShape& f, const State& s) {
  const ShellState& sh = s.shells;
  for (int k = 0; k < sh.ns; ++k) {
    const std::size_t K = std::size_t(k);
    if (!sh.failed.empty() && sh.failed[K]) {
      ++f.failed_shells;
      continue;
    }
    for (int n : sh.conn[K]) take_node(f, s, n);
    if (sh.eps_p.empty()) continue;
    for (int p = 0; p < sh.nip[K]; ++p) {
      const double e = sh.eps_p[shell_point_at(sh, k, p)];
      if (f.max_eps_shell < 0 || e > f.shell_eps) f.max_eps_shell = k, f.shell_eps = e;
    }
  }
}

// The beams' extents (their two nodes; the orientation node is no part of the beam) and
// largest point plastic strain (beams are never deleted).
void measure_beams(FinalShape& f, const State& s) {
  const BeamState& bm = s.beams;
  for (int b = 0; b < bm.nb; ++b) {
    const std::size_t B = std::size_t(b);
    take_node(f, s, bm.conn[B][0]);
    take_node(f, s, bm.conn[B][1]);
    if (bm.eps_p.empty()) continue;
    for (int p = bm.ip_start[B]; p < bm.ip_start[B + 1]; ++p)
      if (f.max_eps_beam < 0 || bm.eps_p[std::size_t(p)] > f.beam_eps) f.max_eps_beam = b, f.beam_eps = bm.eps_p[std::size_t(p)];
  }
}

}  // namespace

FinalShape measure_final_shape(const State& s) {
  FinalShape f;
  measure_solids(f, s);
  measure_shells(f, s);
  measure_beams(f, s);
  return f;
}

std::vector<std::string> final_shape_lines(const Model& m, const State& s, const FinalShape& f) {
  std::vector<std::string> lines;
  char buf[300];
  if (f.failed_solids) {
    std::snprintf(buf, sizeof buf, "\n failed (deleted) solids: %d of %d (left out of the extents below)", f.failed_solids, s.ne);
    lines.push_back(buf);
  }
  if (f.failed_shells) {
    std::snprintf(buf, sizeof buf, "%s failed (deleted) shells: %d of %d (left out of the extents below)",
                  f.failed_solids ? "" : "\n", f.failed_shells, s.shells.ns);
    lines.push_back(buf);
  }
  if (f.any_live)
    std::snprintf(buf, sizeof buf, "\n final extents: x [%.6e, %.6e]  y [%.6e, %.6e]  z [%.6e, %.6e]", f.lo[0], f.hi[0],
                  f.lo[1], f.hi[1], f.lo[2], f.hi[2]);
  else
    std::snprintf(buf, sizeof buf, "\n final extents: none (no live element)");
  lines.push_back(buf);
  if (f.max_eps_solid >= 0) {
    std::snprintf(buf, sizeof buf, " maximum effective plastic strain %.5f in element %d", f.solid_eps, m.hex_id(f.max_eps_solid));
    lines.push_back(buf);
  }
  if (f.max_eps_shell >= 0) {
    std::snprintf(buf, sizeof buf, " maximum effective plastic strain of shells %.5f in shell %d", f.shell_eps,
                  m.shell_id(f.max_eps_shell));
    lines.push_back(buf);
  }
  if (f.max_eps_beam >= 0) {
    std::snprintf(buf, sizeof buf, " maximum effective plastic strain of beams %.5f in beam %d", f.beam_eps,
                  m.beam_id(f.max_eps_beam));
    lines.push_back(buf);
  }
  return lines;
}

}  // namespace impact3d
