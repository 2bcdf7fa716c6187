#include "impact3d/solve/element_processing.h"

#include <cmath>
#include <limits>

#include "impact3d/element/hexahedron.h"
#include "impact3d/material/material.h"

namespace impact3d {

namespace {

struct ElemOut {
  double dt = 0;
  bool bad_volume = false;
  bool non_finite = false;
};

inline ElemOut calc_forces_for_elem(const Model& m, State& s, int e) {
  ElemOut out;
  const std::size_t E = std::size_t(e);
  const auto& cn = s.conn[E];
  double x[8], y[8], z[8], vx[8], vy[8], vz[8];
  for (int j = 0; j < 8; ++j) {
    const std::size_t n = std::size_t(cn[std::size_t(j)]);
    x[j] = s.x[n]; y[j] = s.y[n]; z[j] = s.z[n];
    vx[j] = s.vx[n]; vy[j] = s.vy[n]; vz[j] = s.vz[n];
  }
  double* cfx = &s.cfx[8 * E];
  double* cfy = &s.cfy[8 * E];
  double* cfz = &s.cfz[8 * E];
  s.de_ie[E] = s.de_hg[E] = s.de_bv[E] = 0;
  if (s.rigid_elem[E] || s.failed[E]) {  // rigid, or failed and deleted: no internal forces
    for (int j = 0; j < 8; ++j) cfx[j] = cfy[j] = cfz[j] = 0;
    out.dt = std::numeric_limits<double>::infinity();
    s.dt_e[E] = out.dt;
    return out;
  }
  const int mi = s.mat[E];
  const MaterialConstants& mc = s.mats[std::size_t(mi)];
  const MaterialData& md = m.materials[std::size_t(mi)];
  const double dt = s.dt_half;  // step from x^{n-1} to x^n

  // midpoint kinematics: x^{n-1/2} = x^n - dt/2 v^{n-1/2}
  double xm[8], ym[8], zm[8], bx[8], by[8], bz[8];
  for (int j = 0; j < 8; ++j) {
    xm[j] = x[j] - 0.5 * dt * vx[j];
    ym[j] = y[j] - 0.5 * dt * vy[j];
    zm[j] = z[j] - 0.5 * dt * vz[j];
  }
  const double vm = calc_hex_volume_derivatives(xm, ym, zm, bx, by, bz);
  double dvdx[8], dvdy[8], dvdz[8];
  const double v = calc_hex_volume_derivatives(x, y, z, dvdx, dvdy, dvdz);
  if (!(v > 0) || !(vm > 0)) {
    out.bad_volume = true;
    out.dt = 0;
    s.dt_e[E] = 0;
    s.vol[E] = v;
    return out;
  }
  const double inv_vm = 1.0 / vm;
  for (int j = 0; j < 8; ++j) { bx[j] *= inv_vm; by[j] *= inv_vm; bz[j] *= inv_vm; }
  double d[6], w[3];
  calc_hex_strain_rate(bx, by, bz, vx, vy, vz, d, w);
  const double trd = d[0] + d[1] + d[2];

  // stress update sigma^{n-1} -> sigma^n over dt
  double* sig = &s.sig[6 * E];
  double old[6];
  for (int k = 0; k < 6; ++k) old[k] = sig[k];
  if (dt > 0) {
    rotate_stress_jaumann(sig, w, dt);
    if (mc.type == 1) {
      update_stress_elastic(mc, d, dt, sig);
    } else {
      double* back = &s.back[6 * E];
      // The seed's "initially elastic" path: until an element first yields its back stress is
      // exactly zero, so its rotation is skipped; the yield check still runs every cycle.
      if (!(mc.initially_elastic && !s.yielded[E])) rotate_stress_jaumann(back, w, dt);
      update_stress_elastic_plastic(mc, d, dt, sig, back, s.eps_p[E], s.yielded[E]);
    }
    // stress work (trapezoid in stress, midpoint volume)
    double pw = 0;
    for (int k = 0; k < 3; ++k) pw += 0.5 * (old[k] + sig[k]) * d[k];
    for (int k = 3; k < 6; ++k) pw += (old[k] + sig[k]) * d[k];  // 2 * 0.5 for shear pairs
    s.de_ie[E] = pw * vm * dt;
    // failure: the element is deleted once its plastic strain reaches the failure strain; its
    // stress work up to now stays in the internal energy, its mass stays on the nodes
    if (mc.fail_strain > 0 && s.eps_p[E] >= mc.fail_strain) {
      s.failed[E] = 2;
      // the books as for a stress and viscosity that are zero from now on (trapezoid with a
      // zero end): only the old stress and q did work over this step
      double pw0 = 0;
      for (int k = 0; k < 3; ++k) pw0 += 0.5 * old[k] * d[k];
      for (int k = 3; k < 6; ++k) pw0 += old[k] * d[k];
      s.de_ie[E] = pw0 * vm * dt;
      s.de_bv[E] = -0.5 * s.q[E] * trd * vm * dt;
      for (int k = 0; k < 6; ++k) sig[k] = 0;
      s.q[E] = 0;
      for (int j = 0; j < 8; ++j) cfx[j] = cfy[j] = cfz[j] = 0;
      s.vol[E] = v;
      out.dt = std::numeric_limits<double>::infinity();
      s.dt_e[E] = out.dt;
      return out;
    }
  }
  s.vol[E] = v;
  const double rho = mc.rho * s.vol0[E] / v;

  // bulk viscosity (compression only), from the midpoint strain rate.  Its work over this step
  // is booked like the stress work (trapezoid): the q of the previous cycle acted in the forces
  // over this step, the new one acts over the next.  Booking q^{n+1} trD^{n+1/2} alone counts
  // as dissipated the work of a q that never acted in this interval: behind a front the strain
  // rate alternates in sign from step to step and q only exists in the compressive half, so
  // that form books energy no force removed (a 1-D elastic column on a wall showed twice its
  // kinetic energy as bulk viscous energy).
  const double q_old = s.q[E];
  const double amax = calc_hex_max_face_area(x, y, z);
  const double q = calc_bulk_viscosity(rho, mc.c, v / amax, trd, md.q1, md.q2);
  s.q[E] = q;
  s.de_bv[E] = -0.5 * (q_old + q) * trd * vm * dt;

  // stress divergence with sigma - q I, at x^n
  double se[6] = {sig[0] - q, sig[1] - q, sig[2] - q, sig[3], sig[4], sig[5]};
  calc_hex_stress_force(se, dvdx, dvdy, dvdz, cfx, cfy, cfz);

  // hourglass control
  HourglassInput hin{md.hourglass_type, md.hourglass_coef, rho, mc.c, mc.G, v, s.dt_next > 0 ? s.dt_next : dt};
  const double hg_power =
      calc_hex_hourglass_force(hin, x, y, z, dvdx, dvdy, dvdz, vx, vy, vz, &s.hgs[12 * E], cfx, cfy, cfz);
  s.de_hg[E] = hg_power * dt;

  // element time step
  out.dt = calc_hex_time_step(v, amax, mc.c, trd, md.q1, md.q2);
  s.dt_e[E] = out.dt;
  double check = sig[0] + sig[1] + sig[2] + sig[3] + sig[4] + sig[5];
  for (int j = 0; j < 8; ++j) check += cfx[j] + cfy[j] + cfz[j];
  if (!std::isfinite(check)) out.non_finite = true;
  return out;
}

}  // namespace

ElementLoopResult calc_forces_for_elems(const Model& m, State& s) {
  const int ne = s.ne;
  int bad = std::numeric_limits<int>::max();
  int nonfin = std::numeric_limits<int>::max();
#pragma omp parallel for schedule(static) reduction(min : bad, nonfin)
  for (int e = 0; e < ne; ++e) {
    ElemOut o = calc_forces_for_elem(m, s, e);
    if (o.bad_volume && e < bad) bad = e;
    if (o.non_finite && e < nonfin) nonfin = e;
  }
  ElementLoopResult r;
  r.bad_volume_elem = bad == std::numeric_limits<int>::max() ? -1 : bad;
  r.non_finite_elem = nonfin == std::numeric_limits<int>::max() ? -1 : nonfin;
  // smallest step, lowest element on ties: a serial scan keeps it deterministic
  double dtmin = std::numeric_limits<double>::infinity();
  int arg = -1;
  for (int e = 0; e < ne; ++e)
    if (s.dt_e[std::size_t(e)] < dtmin) { dtmin = s.dt_e[std::size_t(e)]; arg = e; }
  r.dt_min = dtmin;
  r.dt_elem = arg;
  return r;
}

void sum_forces_for_nodes(State& s) {
  const int nn = s.nn;
#pragma omp parallel for schedule(static)
  for (int i = 0; i < nn; ++i) {
    double fx = 0, fy = 0, fz = 0;
    for (int k = s.corner_start[std::size_t(i)]; k < s.corner_start[std::size_t(i) + 1]; ++k) {
      const std::size_t c = std::size_t(s.corner_list[std::size_t(k)]);
      fx += s.cfx[c];
      fy += s.cfy[c];
      fz += s.cfz[c];
    }
    s.fx[std::size_t(i)] = s.fext_x[std::size_t(i)] - fx;
    s.fy[std::size_t(i)] = s.fext_y[std::size_t(i)] - fy;
    s.fz[std::size_t(i)] = s.fext_z[std::size_t(i)] - fz;
  }
}

}  // namespace impact3d
