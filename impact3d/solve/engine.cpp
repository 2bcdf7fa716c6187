#include "impact3d/solve/engine.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impact3d/contact/stonewall.h"
#include "impact3d/init/initialize.h"
#include "impact3d/solve/element_processing.h"
#include "impact3d/solve/rigid_body.h"

namespace impact3d {

Engine::Engine(const Model& m) : m_(m) {}

void Engine::calc_kinetic_energy() {
  double ke = 0;
  for (int i = 0; i < s_.nn; ++i) {
    const std::size_t k = std::size_t(i);
    ke += 0.5 * s_.mass[k] * (s_.vx[k] * s_.vx[k] + s_.vy[k] * s_.vy[k] + s_.vz[k] * s_.vz[k]);
  }
  s_.kinetic = ke;
}

double Engine::kinetic_energy_of_material(int mat) const {
  double ke = 0;
  for (int e = 0; e < s_.ne; ++e) {
    if (s_.mat[std::size_t(e)] != mat) continue;
    const double mc = s_.mass_e[std::size_t(e)] / 8;
    for (int n : s_.conn[std::size_t(e)]) {
      const std::size_t k = std::size_t(n);
      ke += 0.5 * mc * (s_.vx[k] * s_.vx[k] + s_.vy[k] * s_.vy[k] + s_.vz[k] * s_.vz[k]);
    }
  }
  return ke;
}

StepStatus Engine::process_elements() {
  ElementLoopResult r = calc_forces_for_elems(m_, s_);
  // energy increments, summed serially in element order (same bits for any thread count)
  double die = 0, dhg = 0, dbv = 0;
  s_.newly_failed.clear();
  for (int e = 0; e < s_.ne; ++e) {
    const std::size_t k = std::size_t(e);
    if (s_.failed[k] == 2) {  // failed in this pass: listed in element order (any thread count)
      s_.failed[k] = 1;
      s_.newly_failed.push_back(e);
    }
    s_.ie_e[k] += s_.de_ie[k];
    s_.hg_e[k] += s_.de_hg[k];
    s_.bv_e[k] += s_.de_bv[k];
    die += s_.de_ie[k];
    dhg += s_.de_hg[k];
    dbv += s_.de_bv[k];
  }
  s_.internal += die;
  s_.hourglass += dhg;
  s_.bulk_viscous += dbv;
  if (r.bad_volume_elem >= 0) {
    error_elem_ = r.bad_volume_elem;
    return StepStatus::negative_volume;
  }
  if (r.non_finite_elem >= 0) {
    error_elem_ = r.non_finite_elem;
    return StepStatus::non_finite;
  }
  double dt = r.dt_min;
  if (!std::isfinite(dt)) dt = m_.control.end_time / 1000;  // only rigid bodies
  s_.dt_next = m_.control.tssf * dt;
  s_.dt_elem = r.dt_elem;
  return StepStatus::ok;
}

StepStatus Engine::initialize() {
  initialize_state(m_, s_);
  contact_.initialize(m_, s_);
  s_.dt_half = 0;
  calc_kinetic_energy();
  StepStatus st = process_elements();
  if (st != StepStatus::ok) return st;
  if (m_.control.initial_dt > 0) s_.dt_next = std::min(s_.dt_next, m_.control.initial_dt);
  s_.dt0 = s_.dt_next;
  s_.initial_total = s_.total_energy();
  return StepStatus::ok;
}

StepStatus Engine::step() {
  State& s = s_;
  if (finished()) return StepStatus::finished;
  // last step lands on the termination time
  const double remaining = m_.control.end_time - s.time;
  if (s.dt_next > remaining) s.dt_next = remaining;
  const double dt_next = s.dt_next;
  const double dt_n = s.cycle == 0 ? 0.5 * dt_next : 0.5 * (s.dt_half + dt_next);

  const int nn = s.nn;
  // external forces at x^n: contact penalty forces (walls act on velocities below)
  if (!contact_.empty()) {
    std::fill(s.fext_x.begin(), s.fext_x.end(), 0.0);
    std::fill(s.fext_y.begin(), s.fext_y.end(), 0.0);
    std::fill(s.fext_z.begin(), s.fext_z.end(), 0.0);
    contact_.apply(m_, s, dt_next);
  }
  sum_forces_for_nodes(s);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nn; ++i) {
    const std::size_t k = std::size_t(i);
    const double inv_m = s.mass[k] > 0 ? 1.0 / s.mass[k] : 0.0;
    s.ax[k] = s.fx[k] * inv_m;
    s.ay[k] = s.fy[k] * inv_m;
    s.az[k] = s.fz[k] * inv_m;
    s.vx_old[k] = s.vx[k];
    s.vy_old[k] = s.vy[k];
    s.vz_old[k] = s.vz[k];
    const uint8_t f = s.fix[k];
    if (f & 1) s.ax[k] = 0;
    if (f & 2) s.ay[k] = 0;
    if (f & 4) s.az[k] = 0;
    s.vx[k] += dt_n * s.ax[k];
    s.vy[k] += dt_n * s.ay[k];
    s.vz[k] += dt_n * s.az[k];
  }
  if (!s.rigid.empty()) update_rigid_body_velocities(s, dt_n, dt_next);
  if (!m_.walls.empty()) apply_stonewalls_to_nodes(m_, s, dt_next, dt_n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nn; ++i) {
    const std::size_t k = std::size_t(i);
    s.x[k] += dt_next * s.vx[k];
    s.y[k] += dt_next * s.vy[k];
    s.z[k] += dt_next * s.vz[k];
  }
  if (!s.rigid.empty()) update_rigid_body_positions(s, dt_next);
  if (!m_.walls.empty()) update_moving_walls(m_, s, dt_next);
  s.time += dt_next;
  s.cycle += 1;
  s.dt_half = dt_next;
  calc_kinetic_energy();
  StepStatus st = process_elements();
  if (st != StepStatus::ok) return st;
  if (!std::isfinite(s.kinetic)) {
    error_elem_ = -1;
    return StepStatus::non_finite;
  }
  if (m_.control.min_step_factor > 0 && s.dt_next < m_.control.min_step_factor * s.dt0 &&
      !finished())
    return StepStatus::dt_too_small;
  return finished() ? StepStatus::finished : StepStatus::ok;
}

StepStatus Engine::run_to_end() {
  StepStatus st = initialize();
  while (st == StepStatus::ok) st = step();
  return st;
}

}  // namespace impact3d
