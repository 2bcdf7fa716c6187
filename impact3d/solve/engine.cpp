#include "impact3d/solve/engine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "impact3d/contact/stonewall.h"
#include "impact3d/init/initialize.h"
#include "impact3d/parallel/distributed_cycle.h"
#include "impact3d/solve/element_processing.h"
#include "impact3d/solve/loads.h"
#include "impact3d/solve/mass_scaling.h"
#include "impact3d/solve/node_processing.h"
#include "impact3d/solve/node_ties.h"
#include "impact3d/solve/rigid_body.h"
#include "impact3d/solve/shell_processing.h"
#include "impact3d/solve/spot_weld.h"

namespace impact3d {

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
}  // namespace

Engine::Engine(const Model& m) : m_(m) {}

void Engine::calc_kinetic_energy() {
  calc_kinetic_energy_for_nodes(s_);
  s_.shells.rot_kinetic = calc_rotational_kinetic_energy(s_);
  s_.kinetic += s_.shells.rot_kinetic;
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

void Engine::gather_for_output() {
  if (!dist_) return;
  if (dist_->leads()) dist_->announce(parallel::DistributedCycle::Op::gather);
  dist_->gather_state(s_);
}

void Engine::gather_velocities() {
  if (!dist_) return;
  if (dist_->leads()) dist_->announce(parallel::DistributedCycle::Op::gather_velocities);
  dist_->gather_velocities(s_);
}

void Engine::release_followers(int code) {
  if (dist_ && dist_->leads()) dist_->announce(parallel::DistributedCycle::Op::finish, -1, code);
  dist_ = nullptr;
}

StepStatus Engine::process_elements() {
  ElementLoopResult r = dist_ ? calc_forces_for_elems(m_, s_, dist_->element_hooks()) : calc_forces_for_elems(m_, s_);
  s_.newly_failed.clear();
  s_.newly_failed_cause.clear();
  if (r.failed_now > 0) {  // failed in this pass: listed in element order (any thread count)
    for (int e = 0; e < s_.ne; ++e)
      if (s_.failed[std::size_t(e)] >= 2) {
        s_.newly_failed.push_back(e);
        s_.newly_failed_cause.push_back(FailCause(s_.failed[std::size_t(e)]));
        s_.failed[std::size_t(e)] = 1;
      }
  }
  s_.internal += r.die;
  s_.external_work += r.dsrc;  // an equation of state's energy deposition (form 6)
  s_.hourglass += r.dhg;
  s_.bulk_viscous += r.dbv;
  if (r.bad_volume_elem >= 0) {
    error_elem_ = r.bad_volume_elem;
    return StepStatus::negative_volume;
  }
  if (r.non_finite_elem >= 0) {
    error_elem_ = r.non_finite_elem;
    return StepStatus::non_finite;
  }
  // mass scaling: elements below the target step get mass (the step is then the scaled one)
  const ScaledStep sc = scale_masses_for_time_step(m_, s_, r.dt_min, r.dt_elem, s_.cycle == 0 && s_.dt_half == 0,
                                                   dist_ ? dist_->mass_scaling_hook() : MassScalingHook{});
  double dt = sc.dt_min;
  if (!std::isfinite(dt)) dt = m_.control.end_time / 1000;  // only rigid bodies
  s_.dt_next = m_.control.tssf * dt;
  s_.dt_elem = sc.dt_elem;
  if (m_.control.end_mass_percent > 0 && added_mass_percent(s_) >= m_.control.end_mass_percent)
    added_mass_limit_reached_ = true;
  return StepStatus::ok;
}

StepStatus Engine::initialize() {
  if (dist_ && dist_->leads()) dist_->announce(parallel::DistributedCycle::Op::initialize);
  initialize_state(m_, s_);
  contact_.initialize(m_, s_);
  s_.elastic_dt_wanted = contact_.uses_elastic_step();
  prepare_loads(m_, s_, loads_);
  if (dist_) dist_->setup(s_, m_, loads_);
  fixed_walls_ = fixed_walls_for_node_pass(m_);
  if (fixed_walls_.size() > kMaxFusedWalls) fixed_walls_.clear();
  s_.dt_half = 0;
  init_mass_scaling(m_, s_);
  calc_kinetic_energy();
  const double work0 = s_.external_work;
  StepStatus st = process_elements();
  if (st != StepStatus::ok) return st;
  if (m_.control.mass_scaling_dt != 0) {
    // mass added before the first cycle is part of the initial state, not external work
    s_.external_work = work0;
    calc_kinetic_energy();
  }
  if (m_.control.initial_dt > 0) s_.dt_next = std::min(s_.dt_next, m_.control.initial_dt);
  s_.dt0 = s_.dt_next;
  init_offset_tie_stiffness(s_);
  // ERODE: a deformable solid whose step TSSF dt_e falls below DTMIN x the first step is deleted
  // (the element pass's TDEL test) instead of the run ending
  if (m_.control.erode_small_steps && m_.control.min_step_factor > 0)
    for (MaterialConstants& mc : s_.mats)
      mc.tdel = std::max(mc.tdel, m_.control.min_step_factor * s_.dt0 / m_.control.tssf);
  s_.initial_total = s_.total_energy();
  return StepStatus::ok;
}

// Whether the energy books say the run has blown up: the total energy above
// kDivergedEnergyRatio times the initial energy plus the external work (message 4007). A
// physical run never gets there; an unstable one does within a few cycles of leaving the band
// of warning 5102, long before its elements turn inside out (if they ever do).
bool energy_diverged(const State& s) {
  const double ref = s.initial_total + s.external_work;
  return ref > 0 && s.total_energy() > kDivergedEnergyRatio * ref;
}

StepStatus Engine::step() {
  State& s = s_;
  if (dist_ && dist_->leads()) dist_->announce(parallel::DistributedCycle::Op::step, land_time_);
  if (finished()) return StepStatus::finished;
  // last step lands on the termination time
  const double remaining = m_.control.end_time - s.time;
  if (s.dt_next > remaining) s.dt_next = remaining;
  if (land_time_ > s.time && land_time_ - s.time > 1e-9 * s.dt_next) {
    // the steps up to the landing time shrink evenly (no abrupt short step: shells' rotations
    // do not take a step a tenth of the last one well)
    const double rem = land_time_ - s.time;
    const double n = std::ceil(rem / s.dt_next - 1e-9);
    s.dt_next = rem / n;
  }
  const double dt_next = s.dt_next;
  const double dt_n = s.cycle == 0 ? 0.5 * dt_next : 0.5 * (s.dt_half + dt_next);

  // external forces at x^n: loads, then contact penalty forces (walls act on velocities below)
  auto t = Clock::now();
  const bool has_fext = !contact_.empty() || loads_.has_loads || !s.ties.pen_slave.empty();
  if (has_fext) {
    std::fill(s.fext_x.begin(), s.fext_x.end(), 0.0);
    std::fill(s.fext_y.begin(), s.fext_y.end(), 0.0);
    std::fill(s.fext_z.begin(), s.fext_z.end(), 0.0);
  }
  if (loads_.has_loads) {
    apply_loads_to_nodes(m_, s, loads_, s.time);
    times_.loads += seconds_since(t);
    t = Clock::now();
  }
  if (!contact_.empty()) {
    contact_.apply(m_, s, dt_next);
    times_.contact += seconds_since(t);
    t = Clock::now();
  }
  if (!s.ties.pen_slave.empty()) {  // _OFFSET ties' springs
    apply_offset_ties(s);
    times_.contact += seconds_since(t);
    t = Clock::now();
  }
  // Without rigid bodies, and with no wall or only fixed walls on all nodes (applied node by
  // node), nothing else acts on the new velocities before the positions move: one fused pass
  // over the nodes.
  NodePass np;
  np.dt_n = dt_n;
  np.dt_next = dt_next;
  np.has_fext = has_fext;
  np.store_force = !s.rigid.empty() || !s.ties.empty();
  np.update_positions = s.rigid.empty() && s.ties.empty() && !loads_.has_motions &&
                        (m_.walls.empty() || !fixed_walls_.empty());
  np.walls = &fixed_walls_;
  if (dist_) dist_->node_pass(s, np);  // this rank's nodes (distributed_cycle.h)
  else update_velocities_for_nodes(s, np);
  if (!np.update_positions) {
    times_.nodes += seconds_since(t);
    t = Clock::now();
    if (!s.rigid.empty()) update_rigid_body_velocities(s, dt_n, dt_next);
    if (!m_.spot_welds.empty()) check_spot_weld_failure(m_, s, dt_n);
    if (!s.ties.empty()) tie_translations(s, dt_n);
    if (!m_.walls.empty()) {
      if (dist_) dist_->apply_walls(s, np);  // fixed walls on this rank's nodes (distributed_cycle.h)
      else apply_stonewalls_to_nodes(m_, s, dt_next, dt_n);
    }
    times_.walls += seconds_since(t);
    t = Clock::now();
    if (loads_.has_motions) {
      apply_prescribed_motions(m_, s, loads_, s.time, dt_n, dt_next, dist_ ? &dist_->owned_node_mask() : nullptr);
      if (!s.ties.empty()) tie_slave_velocities(s);  // (masters moved by a prescribed motion)
      times_.loads += seconds_since(t);
      t = Clock::now();
    }
    if (dist_) dist_->finish_node_pass(s, np);  // this rank's nodes move (distributed_cycle.h)
    else update_positions_for_nodes(s, dt_next);
  }
  times_.nodes += seconds_since(t);
  if (!contact_.empty()) {  // the contact forces' work, on the velocities the cycle reached
    t = Clock::now();
    contact_.book_energy(s, dt_n);
    times_.contact += seconds_since(t);
  }
  if (!s.ties.pen_slave.empty()) book_offset_tie_energy(s, dt_n);
  if (loads_.has_loads || loads_.has_motions) {
    t = Clock::now();
    if (dist_) dist_->book_external_work(s, dt_n);  // rank 0, from the terms its ranks sent
    else book_external_work(m_, s, loads_, dt_n);
    times_.loads += seconds_since(t);
  }
  t = Clock::now();
  if (!s.rigid.empty()) update_rigid_body_positions(s, dt_next);
  if (!m_.walls.empty()) update_moving_walls(m_, s, dt_next);
  times_.walls += seconds_since(t);
  t = Clock::now();
  if (loads_.has_rotations) capture_rotations(m_, s, loads_);
  if (!s.ties.empty()) save_tied_rotations(s);
  update_rotational_velocities_for_nodes(s, dt_n);  // shells' and beams' rotations (none: no-op)
  if (!s.ties.empty()) tie_rotations(s, dt_n);
  if (loads_.has_rotations) apply_prescribed_rotations(m_, s, loads_, s.time, dt_n, dt_next);
  times_.nodes += seconds_since(t);
  s.time += dt_next;
  s.cycle += 1;
  s.dt_half = dt_next;
  s.dt_vel = dt_n;
  t = Clock::now();
  StepStatus st = process_elements();
  times_.elements += seconds_since(t);
  if (st != StepStatus::ok) return st;
  if (!std::isfinite(s.kinetic)) {
    error_elem_ = -1;
    return StepStatus::non_finite;
  }
  if (energy_diverged(s)) return StepStatus::diverged;
  if (m_.control.min_step_factor > 0 && !m_.control.erode_small_steps && s.dt_next < m_.control.min_step_factor * s.dt0 &&
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
