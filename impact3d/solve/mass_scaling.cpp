#include "impact3d/solve/mass_scaling.h"

#include <cmath>
#include <limits>

#include "impact3d/init/shell_init.h"

namespace impact3d {

void init_mass_scaling(const Model& m, State& s) {
  if (m.control.mass_scaling_dt == 0) return;
  s.ms_factor.assign(std::size_t(s.ne), 1.0);
  s.shells.ms_factor.assign(std::size_t(s.shells.ns), 1.0);
  s.mat_added_mass.assign(s.mats.size(), 0.0);
  s.added_mass = 0;
  double total = 0;
  for (double mn : s.mass) total += mn;
  s.physical_mass = total;
}

namespace {

double node_speed2(const State& s, std::size_t k) {
  return s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k] + s.vz[k] * s.vz[k];
}

// The new factor of an element with unscaled step dt and factor f (f unchanged when none is
// needed): raised to (T / dt)^2 when its scaled step is below T; at the first cycle with
// DT2MS > 0 also lowered to it.
double new_factor(double dt, double f, double target, bool lower) {
  if (!(dt > 0) || !std::isfinite(dt)) return f;
  const double want = (target / dt) * (target / dt);
  if (dt * std::sqrt(f) < target) return want > f ? want : f;
  if (lower && want < f) return want;
  return f;
}

// Adds dm to a solid's nodes (1/8 per corner) and returns the kinetic energy that mass brings.
double add_mass_to_solid(State& s, int e, double dm) {
  double ke = 0;
  for (int n : s.conn[std::size_t(e)]) {
    const std::size_t k = std::size_t(n);
    s.mass[k] += dm / 8;
    ke += 0.5 * (dm / 8) * node_speed2(s, k);
  }
  return ke;
}

// Adds dm to a shell's nodes by its corner shares, with the rotary inertia those shares give.
double add_mass_to_shell(const Model& m, State& s, int k, double dm) {
  ShellState& sh = s.shells;
  const auto& c = sh.conn[std::size_t(k)];
  double ke = 0;
  for (int j = 0; j < 4; ++j) {
    const std::size_t n = std::size_t(c[std::size_t(j)]);
    const double mj = dm * corner_fraction(c, j);
    s.mass[n] += mj;
    ke += 0.5 * mj * node_speed2(s, n);
    const int r = sh.node_rot[n];
    if (r >= 0) {
      const double dI = m.shell_rotary_scale * shell_rotary_inertia(mj, sh.thick[std::size_t(k)], sh.area0[std::size_t(k)]);
      sh.inertia[std::size_t(r)] += dI;
      const std::size_t R = std::size_t(r);
      ke += 0.5 * dI * (sh.wx[R] * sh.wx[R] + sh.wy[R] * sh.wy[R] + sh.wz[R] * sh.wz[R]);
    }
  }
  return ke;
}

}  // namespace

ScaledStep scale_masses_for_time_step(const Model& m, State& s, double dt_min, int dt_elem, bool first_cycle,
                                      const MassScalingHook& hook) {
  ScaledStep out{dt_min, dt_elem};
  const ControlData& k = m.control;
  if (k.mass_scaling_dt == 0) return out;
  const bool scale = first_cycle || !k.mass_scaling_first_only;
  const double target = std::fabs(k.mass_scaling_dt);
  const bool lower = first_cycle && k.mass_scaling_dt > 0;
  double best = std::numeric_limits<double>::infinity();
  int arg = -1;
  double ke = 0;
  bool adding = false;
  // One element (number id in the step's numbering, solids then shells): its factor f anew
  // when scaling, the mass added (element_mass() its mass; add_mass(dm) spreads dm to its nodes
  // and returns the kinetic energy that adds) booked, and its scaled step against the smallest.
  const auto scale_element = [&](double dt, double& f, int mat, int id, const auto& element_mass, const auto& add_mass) {
    if (scale) {
      const double g = new_factor(dt, f, target, lower);
      if (g != f) {
        if (!adding && hook.before_adding) hook.before_adding(hook.ctx, s);
        adding = true;
        const double dm = (g - f) * element_mass();
        ke += add_mass(dm);
        s.added_mass += dm;
        s.mat_added_mass[std::size_t(mat)] += dm;
        f = g;
      }
    }
    const double dts = dt * std::sqrt(f);
    if (dts < best) {
      best = dts;
      arg = id;
    }
  };
  // solids, then shells, each in element order (one thread: the same bits for any count)
  for (int e = 0; e < s.ne; ++e) {
    const std::size_t E = std::size_t(e);
    scale_element(s.dt_e[E], s.ms_factor[E], s.mat[E], e, [&] { return s.mass_e[E]; },
                  [&](double dm) { return add_mass_to_solid(s, e, dm); });
  }
  ShellState& sh = s.shells;
  for (int j = 0; j < sh.ns; ++j) {
    const std::size_t J = std::size_t(j);
    const int mat = sh.mat[J];
    scale_element(sh.dt_e[J], sh.ms_factor[J], mat, s.ne + j, [&] { return s.mats[std::size_t(mat)].rho * sh.thick[J] * sh.area0[J]; },
                  [&](double dm) { return add_mass_to_shell(m, s, j, dm); });
  }
  s.external_work += ke;
  if (arg >= 0) {
    out.dt_min = best;
    out.dt_elem = arg;
  }
  return out;
}

double added_mass_percent(const State& s) {
  return s.physical_mass > 0 ? 100.0 * s.added_mass / s.physical_mass : 0.0;
}

}  // namespace impact3d
