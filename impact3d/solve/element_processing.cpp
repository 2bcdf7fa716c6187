#include "impact3d/solve/element_processing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impact3d/element/hex_block.h"
#include "impact3d/element/hex_sri.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_block.h"
#include "impact3d/solve/element_groups.h"
#include "impact3d/solve/beam_processing.h"
#include "impact3d/solve/shell_processing.h"

namespace impact3d {

namespace {

// Below this many blocks (512 solids) the element pass runs on one thread: waking the sleeping
// thread (passive wait, thread_policy.h) and the barrier at the end of the pass cost about
// 10-15 us a cycle, more than half of a pass this short saves. Measured on Taylor bars of 64 to
// 8000 solids with ncpu=2 (docs/performance.md, "Threads on small models"): 64 and 128 solids
// (one and two chunks) lose, 256 even, from 504 solids two threads win.
constexpr int kMinBlocksForThreads = 64;
// Blocks handed to a thread at a time (dynamic schedule: a thread slowed by another process
// simply takes fewer; every block writes only its own slots, so the bits do not change).
constexpr int kBlocksPerChunk = 8;

// What stays the same over a group for one pass.
struct GroupPass {
  const MaterialConstants* mc;
  const MaterialData* md;
  HexKernel kernel;
  const SolidKernel* solid;  // the material type's stress update
  int history;    // history values per solid
  double dt;      // dt^{n-1/2}: the step from x^{n-1} to x^n
  double dt_hg;   // step of the hourglass stiffness forms
  bool with_back; // type 3 with a kinematic part: the back stress is carried
  bool hg_state;  // hourglass types 4, 5 carry resultants
  bool eos;       // the pressure comes from an equation of state (material/eos.h)
  bool sri;       // fully integrated selective-reduced solids (ELFORM 2, element/hex_sri.h)
  double time;    // t^n (erosion by failure time)
  const Model* model;  // initial coordinates (erosion by strain)
  bool elastic_dt;     // contact wants the solids' elastic step (State::elastic_dt_wanted)
};

// Lane l of a block holds element elems[l], or repeats lane 0's element (padding, inactive).
void gather_hex_block(const State& s, const GroupPass& gp, const int* elems, HexBlock& k) {
  int e[kLanes];
  for (int l = 0; l < kLanes; ++l) e[l] = elems[l] >= 0 ? elems[l] : elems[0];
  // node indices corner by corner, then the six nodal fields (hardware gathers were slower
  // here than the scalar loads the compiler makes of this loop)
  alignas(64) int nodes[8][kLanes];
  for (int l = 0; l < kLanes; ++l) {
    const auto& cn = s.conn[std::size_t(e[l])];
    for (int j = 0; j < 8; ++j) nodes[j][l] = cn[std::size_t(j)];
  }
  const double *px = s.x.data(), *py = s.y.data(), *pz = s.z.data();
  const double *pvx = s.vx.data(), *pvy = s.vy.data(), *pvz = s.vz.data();
  for (int j = 0; j < 8; ++j) {
    IMPACT3D_FOR_LANES {
      const int n = nodes[j][l];
      k.x[j][l] = px[n];
      k.y[j][l] = py[n];
      k.z[j][l] = pz[n];
      k.vx[j][l] = pvx[n];
      k.vy[j][l] = pvy[n];
      k.vz[j][l] = pvz[n];
    }
  }
  for (int l = 0; l < kLanes; ++l) {
    const std::size_t E = std::size_t(e[l]);
    for (int c = 0; c < 6; ++c) k.sig[c][l] = s.sig[6 * E + std::size_t(c)];
    k.q_old[l] = s.q[E];
    k.rho[l] = s.vol0[E];  // rho0 V0 / V once V is known
    k.v0[l] = s.vol0[E];
  }
  if (gp.solid->plastic_strain) {
    for (int l = 0; l < kLanes; ++l) {
      const std::size_t E = std::size_t(e[l]);
      k.eps_p[l] = s.eps_p[E];
      k.yielded[l] = s.yielded[E];
      if (gp.with_back)
        for (int c = 0; c < 6; ++c) k.back[c][l] = s.back[6 * E + std::size_t(c)];
    }
  }
  const std::size_t hs = std::size_t(s.hist_stride);
  for (int l = 0; l < kLanes; ++l)
    for (int h = 0; h < gp.history; ++h) k.hist[h][l] = s.hist[hs * std::size_t(e[l]) + std::size_t(h)];
  if (gp.hg_state)
    for (int l = 0; l < kLanes; ++l)
      for (int m = 0; m < 12; ++m) k.hgs[m][l] = s.hgs[12 * std::size_t(e[l]) + std::size_t(m)];
}

// Stress update sigma^{n-1} -> sigma^n over dt and the stress work (trapezoid in stress,
// midpoint volume).
void update_stress_block(const GroupPass& gp, HexBlock& k) {
  for (int c = 0; c < 6; ++c) IMPACT3D_FOR_LANES k.old[c][l] = k.sig[c][l];
  const double dt = gp.dt;
  IMPACT3D_FOR_LANES k.de_src[l] = 0;
  if (!(dt > 0)) {
    IMPACT3D_FOR_LANES k.de_ie[l] = 0;
    return;
  }
  rotate_stress_jaumann_block(k.sig, k.w, dt);
  // (a back stress that is still zero rotates to zero: the seed's "initially elastic" skip
  // of that rotation gives the same bits)
  if (gp.with_back) rotate_stress_jaumann_block(k.back, k.w, dt);
  gp.solid->update_block(*gp.mc, k, dt);  // the material type's kernel (material_types.h)
  if (gp.eos) {  // the pressure from the equation of state, the energy with it (material/eos.h)
    const int h = gp.mc->eos_hist, nh = gp.history - h;  // its history values: h .. h + nh - 1
    const int rubble = gp.mc->no_tension_hist;             // the material's no-tension flag, if any
    for (int l = 0; l < kLanes; ++l) {
      double old[6], d[6], sig[6], hv[2] = {0, 0};
      for (int c = 0; c < 6; ++c) old[c] = k.old[c][l], d[c] = k.d[c][l], sig[c] = k.sig[c][l];
      for (int j = 0; j < nh && j < 2; ++j) hv[j] = k.hist[h + j][l];
      k.cs[l] = update_stress_eos_point(*gp.mc, old, d, k.v[l], k.vm[l], k.v0[l], dt, k.q_old[l], k.q[l], sig, hv,
                                        gp.time, k.de_src[l], rubble >= 0 && k.hist[rubble][l] != 0.0);
      for (int j = 0; j < nh && j < 2; ++j) k.hist[h + j][l] = hv[j];
      for (int c = 0; c < 6; ++c) k.sig[c][l] = sig[c];
    }
  }
  IMPACT3D_FOR_LANES {
    double pw = 0;
    #pragma GCC unroll 16
    for (int c = 0; c < 3; ++c) pw += 0.5 * (k.old[c][l] + k.sig[c][l]) * k.d[c][l];
    for (int c = 3; c < 6; ++c) pw += (k.old[c][l] + k.sig[c][l]) * k.d[c][l];  // 2 * 0.5 for shear pairs
    k.de_ie[l] = pw * k.vm[l] * dt + k.de_src[l];
  }
}

// Hourglass forces and their books.  The stiffness forms book their mean resultant's work over
// the step just done (k.de_hg); the viscous forms leave their resultants' power at the old and
// the new velocities (k.hg_old, k.hg_new) for calc_forces_for_elems to book over the velocity
// step between (hexahedron.h), and their stable step in k.dt_hg.
void calc_hourglass_for_hex_block(const GroupPass& gp, HexBlock& k) {
  const MaterialData& md = *gp.md;
  IMPACT3D_FOR_LANES k.hg_old[l] = k.hg_new[l] = 0;
  IMPACT3D_FOR_LANES k.dt_hg[l] = DBL_MAX;
  if (md.hourglass_coef == 0.0) {
    IMPACT3D_FOR_LANES k.de_hg[l] = 0;
    return;
  }
  calc_hex_hourglass_force_block(k, md.hourglass_type, md.hourglass_coef, gp.mc->c, gp.mc->G, gp.dt_hg);
  if (md.hourglass_type <= 3) {
    IMPACT3D_FOR_LANES k.hg_new[l] = k.de_hg[l];
    IMPACT3D_FOR_LANES k.de_hg[l] = 0;
  } else {
    IMPACT3D_FOR_LANES k.de_hg[l] = k.de_hg[l] * gp.dt;
  }
}

// Kinematics, density and bulk viscosity of a gathered block, and the viscosity's work.
void calc_hex_kinematics_and_viscosity_block(const GroupPass& gp, HexBlock& k) {
  const MaterialConstants& mc = *gp.mc;
  const MaterialData& md = *gp.md;
  calc_hex_kinematics_block(k, gp.dt);
  IMPACT3D_FOR_LANES k.rho[l] = mc.rho * k.rho[l] / k.v[l];
  // Bulk viscosity from the midpoint strain rate; its work over this step is booked like the
  // stress work (trapezoid): the q of the previous cycle acted in the forces over this step,
  // the new one acts over the next (see hexahedron.h).  Computed before the stress (it does not
  // depend on it) so that an equation of state books its work into the element's energy.
  calc_hex_bulk_viscosity_block(k, mc.c, md.q1, md.q2);
  IMPACT3D_FOR_LANES k.de_bv[l] = -0.5 * (k.q_old[l] + k.q[l]) * k.trd[l] * k.vm[l] * gp.dt;
}

// One block of a deformable group: kinematics, stress, bulk viscosity, forces, hourglass,
// step.  Results stay in k; store_hex_block writes them.
void calc_forces_for_hex_block(const GroupPass& gp, HexBlock& k) {
  const MaterialConstants& mc = *gp.mc;
  const MaterialData& md = *gp.md;
  calc_hex_kinematics_and_viscosity_block(gp, k);
  if (gp.eos) IMPACT3D_FOR_LANES k.cs[l] = mc.c;
  update_stress_block(gp, k);
  calc_hex_stress_force_block(k);
  calc_hourglass_for_hex_block(gp, k);
  if (gp.eos) calc_hex_time_step_lanes_block(k, md.q1, md.q2);  // the element's own sound speed
  else calc_hex_time_step_block(k, mc.c, md.q1, md.q2);
  limit_hex_time_step_block(k);
}

// A fully integrated solid's Gauss points (hex_sri.h) read from and written to State::pt_*.
struct SriPoint {
  SolidPointState st;
  std::size_t p;  // the point's index
  void load(const State& s, const GroupPass& gp) {
    for (std::size_t c = 0; c < 6; ++c) st.sig[c] = s.pt_sig[6 * p + c];
    if (gp.with_back)
      for (std::size_t c = 0; c < 6; ++c) st.back[c] = s.pt_back[6 * p + c];
    st.eps_p = s.pt_eps_p[p];
    st.yielded = s.pt_yielded[p];
    const std::size_t hs = std::size_t(s.hist_stride);
    for (int h = 0; h < gp.history; ++h) st.hist[h] = s.pt_hist[hs * p + std::size_t(h)];
  }
  void store(State& s, const GroupPass& gp) const {
    for (std::size_t c = 0; c < 6; ++c) s.pt_sig[6 * p + c] = st.sig[c];
    if (gp.with_back)
      for (std::size_t c = 0; c < 6; ++c) s.pt_back[6 * p + c] = st.back[c];
    s.pt_eps_p[p] = st.eps_p;
    s.pt_yielded[p] = st.yielded;
    const std::size_t hs = std::size_t(s.hist_stride);
    for (int h = 0; h < gp.history; ++h) s.pt_hist[hs * p + std::size_t(h)] = st.hist[h];
  }
};

// The stress power of a step (trapezoid in stress; shear pairs twice) and the old stress's share.
void sri_point_power(const double old[6], const double sig[6], const double d[6], double& pw, double& pw0) {
  pw = 0, pw0 = 0;
  for (int c = 0; c < 3; ++c) pw += 0.5 * (old[c] + sig[c]) * d[c], pw0 += 0.5 * old[c] * d[c];
  for (int c = 3; c < 6; ++c) pw += (old[c] + sig[c]) * d[c], pw0 += old[c] * d[c];
}

// Lane l (solid e) of a fully integrated block whose kinematics and bulk viscosity are done:
// each Gauss point's stress update with its own strain rate (the element's mean trD) and spin
// at the midpoint x^{n-1/2}, the stress work, then the B-bar corner forces at x^n (hex_sri.h).
// The lane's sig, eps_p, yielded and history become the means of the points (what
// store_hex_block writes to the element: output, failure criteria).  A point whose Jacobian is
// not positive makes the lane's volume that Jacobian (the run stops on a bad volume).
void calc_forces_for_sri_lane(State& s, const GroupPass& gp, HexBlock& k, int l, int e) {
  const double dt = gp.dt;
  double x[8], y[8], z[8], xm[8], ym[8], zm[8], vx[8], vy[8], vz[8];
  for (int j = 0; j < 8; ++j) {
    x[j] = k.x[j][l], y[j] = k.y[j][l], z[j] = k.z[j][l];
    vx[j] = k.vx[j][l], vy[j] = k.vy[j][l], vz[j] = k.vz[j][l];
    xm[j] = x[j] - 0.5 * dt * vx[j], ym[j] = y[j] - 0.5 * dt * vy[j], zm[j] = z[j] - 0.5 * dt * vz[j];
  }
  double mean[6] = {0, 0, 0, 0, 0, 0}, eps = 0, yielded = 0, hist[kMaxHistory] = {}, de = 0, de0 = 0;
  double worst = k.v[l];  // the smallest Jacobian met
  SriPoint pt;
  double b[3][8];
  for (int g = 0; g < kSriPoints; ++g) {
    pt.p = std::size_t(s.pt_first[std::size_t(e)] + g);
    pt.load(s, gp);
    const double jm = calc_hex_sri_point_gradients(xm, ym, zm, g, b[0], b[1], b[2]);
    worst = std::min(worst, jm);
    double d[6], old[6];
    calc_hex_sri_strain_rate(b[0], b[1], b[2], vx, vy, vz, k.trd[l], d, pt.st.w);
    for (int c = 0; c < 6; ++c) old[c] = pt.st.sig[c];
    if (dt > 0) {
      rotate_stress_jaumann(pt.st.sig, pt.st.w, dt);
      if (gp.with_back) rotate_stress_jaumann(pt.st.back, pt.st.w, dt);
      gp.solid->update_point(*gp.mc, d, dt, pt.st);
      double pw, pw0;
      sri_point_power(old, pt.st.sig, d, pw, pw0);
      de += pw * jm * dt;
      de0 += pw0 * jm * dt;
    }
    pt.store(s, gp);
    for (int c = 0; c < 6; ++c) mean[c] += pt.st.sig[c];
    eps += pt.st.eps_p;
    yielded = pt.st.yielded != 0.0 ? 1.0 : yielded;
    for (int h = 0; h < gp.history; ++h) hist[h] += pt.st.hist[h];
  }
  double fx[8] = {}, fy[8] = {}, fz[8] = {}, jp = 0;
  for (int g = 0; g < kSriPoints; ++g) {
    const std::size_t p = std::size_t(s.pt_first[std::size_t(e)] + g);
    const double jn = calc_hex_sri_point_gradients(x, y, z, g, b[0], b[1], b[2]);
    worst = std::min(worst, jn);
    jp += add_hex_sri_point_forces(&s.pt_sig[6 * p], b[0], b[1], b[2], jn, fx, fy, fz);
  }
  const double pq = jp / k.v[l] - k.q[l];  // the mean pressure and the bulk viscosity
  for (int j = 0; j < 8; ++j) {
    k.fx[j][l] = fx[j] + pq * k.dvdx[j][l];
    k.fy[j][l] = fy[j] + pq * k.dvdy[j][l];
    k.fz[j][l] = fz[j] + pq * k.dvdz[j][l];
  }
  constexpr double kInv = 1.0 / kSriPoints;
  for (int c = 0; c < 6; ++c) k.sig[c][l] = mean[c] * kInv;
  k.eps_p[l] = eps * kInv;
  k.yielded[l] = yielded;
  for (int h = 0; h < gp.history; ++h) k.hist[h][l] = hist[h] * kInv;
  k.de_ie[l] = de;
  k.de_old[l] = de0;
  if (!(worst > 0)) k.v[l] = worst;
}

// A block of fully integrated solids: the one-point element's kinematics and bulk viscosity
// (mean strain rate, dV/dx, step), the points lane by lane, no hourglass control.
void calc_forces_for_sri_block(State& s, const GroupPass& gp, const int* elems, const bool* active, HexBlock& k) {
  calc_hex_kinematics_and_viscosity_block(gp, k);
  IMPACT3D_FOR_LANES {
    k.de_ie[l] = k.de_old[l] = k.de_src[l] = k.de_hg[l] = k.hg_old[l] = k.hg_new[l] = 0;
    k.dt_hg[l] = DBL_MAX;
  }
  for (int l = 0; l < kLanes; ++l)
    if (active[l] && k.v[l] > 0 && k.vm[l] > 0) calc_forces_for_sri_lane(s, gp, k, l, elems[l]);
  calc_hex_time_step_block(k, gp.mc->c, gp.md->q1, gp.md->q2);
  limit_hex_time_step_block(k);
}

// Writes lane l's corner forces as zero (failed solids, padding).
void zero_corner_forces(HexBlock& k, int l) {
  for (int j = 0; j < 8; ++j) k.fx[j][l] = k.fy[j][l] = k.fz[j][l] = 0;
}

// Stores a computed block: element state, corner forces, books, and the block's result.
void store_hex_block(State& s, const GroupPass& gp, const int* elems, const bool* active, int block,
                     HexBlock& k) {
  BlockResult r;
  r.dt_min = std::numeric_limits<double>::infinity();
  const MaterialConstants& mc = *gp.mc;
  // a non-finite stress or force anywhere in the lane (summed across lanes at once: a chain
  // of 30 dependent additions per element is slow)
  alignas(64) Lanes check;
  IMPACT3D_FOR_LANES {
    double c = k.sig[0][l] + k.sig[1][l] + k.sig[2][l] + k.sig[3][l] + k.sig[4][l] + k.sig[5][l];
#pragma GCC unroll 16
    for (int j = 0; j < 8; ++j) c += k.fx[j][l] + k.fy[j][l] + k.fz[j][l];
    check[l] = c;
  }
  for (int l = 0; l < kLanes; ++l) {
    if (!active[l]) {
      zero_corner_forces(k, l);
      continue;
    }
    const int e = elems[l];
    const std::size_t E = std::size_t(e);
    if (!(k.v[l] > 0) || !(k.vm[l] > 0)) {  // the run stops: keep the lane's state as it was
      if (r.bad_volume_elem < 0) r.bad_volume_elem = e;
      s.dt_e[E] = 0;
      s.vol[E] = k.v[l];
      zero_corner_forces(k, l);
      continue;
    }
    double* sig = &s.sig[6 * E];
    if (gp.solid->plastic_strain) {
      s.eps_p[E] = k.eps_p[l];
      s.yielded[E] = k.yielded[l] != 0.0;
      if (gp.with_back)
        for (int c = 0; c < 6; ++c) s.back[6 * E + std::size_t(c)] = k.back[c][l];
    }
    const std::size_t hs = std::size_t(s.hist_stride);
    for (int h = 0; h < gp.history; ++h) s.hist[hs * E + std::size_t(h)] = k.hist[h][l];
    s.vol[E] = k.v[l];
    // contact's elastic step, from this pass's V and A_max (the same operations as
    // calc_hex_max_face_area: the same bits)
    if (gp.elastic_dt && mc.c > 0 && k.amax[l] > 0) {
      const double d = k.v[l] / k.amax[l] / mc.c;
      if (d < r.dt_elastic) r.dt_elastic = d;
    }
    // the first criterion met is the cause the run log names (State::failed, FailCause)
    FailCause cause = FailCause::none;
    if (mc.fail_strain > 0 && k.eps_p[l] >= mc.fail_strain) cause = FailCause::plastic_strain;
    else if (mc.tdel > 0 && k.dt[l] < mc.tdel) cause = FailCause::time_step;
    else if (mc.fail_history >= 0 && k.hist[mc.fail_history][l] >= 1.0) cause = FailCause::damage;
    else if (mc.vol_erode_hi > 0 && k.v[l] / s.vol0[E] > mc.vol_erode_hi) cause = FailCause::volume_high;
    else if (mc.vol_erode_lo > 0 && k.v[l] / s.vol0[E] < mc.vol_erode_lo) cause = FailCause::volume_low;
    bool fails = cause != FailCause::none;
    if (mc.erosion && !fails) {  // *MAT_ADD_EROSION
      const double sg[6] = {k.sig[0][l], k.sig[1][l], k.sig[2][l], k.sig[3][l], k.sig[4][l], k.sig[5][l]};
      double eps[3] = {0, 0, 0};
      if (mc.er_strain) {
        double X[8][3], x[8][3];
        for (int j = 0; j < 8; ++j) {
          const std::size_t n = std::size_t(s.conn[E][std::size_t(j)]);
          X[j][0] = gp.model->x[n], X[j][1] = gp.model->y[n], X[j][2] = gp.model->z[n];
          x[j][0] = s.x[n], x[j][1] = s.y[n], x[j][2] = s.z[n];
        }
        calc_hex_principal_strains(X, x, eps);
      }
      fails = erosion_criteria_met(mc, sg, k.v[l] / s.vol0[E], gp.time, eps);
      if (fails) cause = FailCause::erosion;
    }
    if (gp.dt > 0 && fails) {
      // Failure (plastic strain, the step below TDEL, damage, relative volume): the solid is deleted.  Its stress work up to now stays in the internal
      // energy, its mass on the nodes; the books as for a stress and viscosity that are zero
      // from now on (trapezoid with a zero end): only the old stress and q did work.
      s.failed[E] = std::uint8_t(cause);  // >= 2: failed in this pass (Engine lists it)
      ++r.failed_now;
      double pw0 = 0;
      for (int c = 0; c < 3; ++c) pw0 += 0.5 * k.old[c][l] * k.d[c][l];
      for (int c = 3; c < 6; ++c) pw0 += k.old[c][l] * k.d[c][l];
      const double die = gp.sri ? k.de_old[l] : pw0 * k.vm[l] * gp.dt;
      const double dbv = -0.5 * s.q[E] * k.trd[l] * k.vm[l] * gp.dt;
      for (int c = 0; c < 6; ++c) sig[c] = 0;
      s.q[E] = 0;
      zero_corner_forces(k, l);
      s.dt_e[E] = std::numeric_limits<double>::infinity();
      r.die += die;
      r.dbv += dbv;
      r.hg_old += k.hg_old[l];  // the last resultants acted over this cycle; none from now on
      if (gp.hg_state)
        for (int m = 0; m < 12; ++m) s.hgs[12 * E + std::size_t(m)] = 0;
      continue;
    }
    for (int c = 0; c < 6; ++c) sig[c] = k.sig[c][l];
    s.q[E] = k.q[l];
    if (gp.hg_state)
      for (int m = 0; m < 12; ++m) s.hgs[12 * E + std::size_t(m)] = k.hgs[m][l];
    s.dt_e[E] = k.dt[l];
    r.die += k.de_ie[l];
    r.dsrc += k.de_src[l];
    r.dhg += k.de_hg[l];
    r.hg_old += k.hg_old[l];
    r.hg_new += k.hg_new[l];
    r.dbv += k.de_bv[l];
    if (k.dt[l] < r.dt_min) {  // lanes in increasing element order: the lowest wins ties
      r.dt_min = k.dt[l];
      r.dt_elem = e;
    }
    if (!std::isfinite(check[l]) && r.non_finite_elem < 0) r.non_finite_elem = e;
  }
  // the block's corner forces, [corner][lane], in one piece
  const std::size_t base = std::size_t(block) * 8 * kLanes;
  for (int j = 0; j < 8; ++j) {
    IMPACT3D_FOR_LANES {
      s.cfx[base + std::size_t(j * kLanes + l)] = k.fx[j][l];
      s.cfy[base + std::size_t(j * kLanes + l)] = k.fy[j][l];
      s.cfz[base + std::size_t(j * kLanes + l)] = k.fz[j][l];
    }
  }
  s.block_results[std::size_t(block)] = r;
}

void process_hex_block(State& s, const GroupPass& gp, int block) {
  const int* elems = &s.slot_elem[std::size_t(block) * kLanes];
  bool active[kLanes];
  bool any = false;
  for (int l = 0; l < kLanes; ++l) {
    active[l] = elems[l] >= 0 && !s.failed[std::size_t(elems[l])];
    any = any || active[l];
  }
  if (!any) {  // every solid of the block has failed: nothing moves it any more
    BlockResult r;
    r.dt_min = std::numeric_limits<double>::infinity();
    s.block_results[std::size_t(block)] = r;
    return;
  }
  HexBlock k;
  gather_hex_block(s, gp, elems, k);
  if (gp.sri) calc_forces_for_sri_block(s, gp, elems, active, k);
  else calc_forces_for_hex_block(gp, k);
  store_hex_block(s, gp, elems, active, block, k);
}

// A shell or beam pass joins the solids' results: its elements are reported as element
// first + their index (the step, the first bad and the first non-finite element).
void merge_pass_results(int first, double dt_min, int dt_elem, int bad_elem, int non_finite_elem, double& dtmin, int& arg,
                        int& bad, int& nonfin) {
  if (dt_elem >= 0 && (dt_min < dtmin || arg < 0)) {
    dtmin = dt_min;
    arg = first + dt_elem;
  }
  if (bad < 0 && bad_elem >= 0) bad = first + bad_elem;
  if (nonfin < 0 && non_finite_elem >= 0) nonfin = first + non_finite_elem;
}

void merge_shell_results(const ShellPassResult& r, int ne, double& die, double& dhg, double& dtmin,
                         int& arg, int& bad, int& nonfin) {
  die += r.die;
  dhg += r.dhg;
  merge_pass_results(ne, r.dt_min, r.dt_shell, r.bad_shell, r.non_finite_shell, dtmin, arg, bad, nonfin);
}

// The beams join after the shells: a beam is reported as element ne + ns + its index.
void merge_beam_results(const BeamPassResult& r, int first, double& die, double& dtmin, int& arg, int& bad,
                        int& nonfin) {
  die += r.die;
  merge_pass_results(first, r.dt_min, r.dt_beam, r.bad_beam, r.non_finite_beam, dtmin, arg, bad, nonfin);
}

}  // namespace

ElementLoopResult calc_forces_for_elems(const Model& m, State& s, const ElementPassHooks& hooks) {
  ElementLoopResult out;
  for (const ElementGroup& g : s.groups) {
    if (g.kernel == HexKernel::rigid) {  // rigid solids: no internal forces, no step
      for (int b = g.first_block; b < g.first_block + g.num_blocks; ++b) {
        BlockResult r;
        r.dt_min = std::numeric_limits<double>::infinity();
        s.block_results[std::size_t(b)] = r;
      }
      continue;
    }
    GroupPass gp;
    gp.mc = &s.mats[std::size_t(g.material)];
    gp.md = &m.materials[std::size_t(g.material)];
    gp.kernel = g.kernel;
    gp.solid = g.solid;
    gp.history = g.history;
    gp.dt = s.dt_half;
    gp.dt_hg = s.dt_next > 0 ? s.dt_next : s.dt_half;
    gp.with_back = group_carries_back_stress(*g.solid, *gp.mc);
    gp.hg_state = group_carries_hourglass_state(*gp.md);
    gp.eos = gp.mc->eos_form != 0;
    gp.sri = g.formulation == 2;
    gp.time = s.time;
    gp.model = &m;
    gp.elastic_dt = s.elastic_dt_wanted;
    const int b0 = g.first_block, nb = g.num_blocks;
    if (hooks.owns_block) {
      const std::uint8_t* own = hooks.owns_block->data();
#pragma omp parallel for schedule(dynamic, kBlocksPerChunk) if (nb >= kMinBlocksForThreads)
      for (int b = b0; b < b0 + nb; ++b)
        if (own[b]) process_hex_block(s, gp, b);
      continue;
    }
#pragma omp parallel for schedule(dynamic, kBlocksPerChunk) if (nb >= kMinBlocksForThreads)
    for (int b = b0; b < b0 + nb; ++b) process_hex_block(s, gp, b);
  }
  // the shells and beams (the second and third families): computed here, booked after the
  // solids' reductions
  if (s.shells.ns > 0) compute_shell_forces(s, hooks.owns_shell_chunk);
  if (s.beams.nb > 0) compute_beam_forces(s, hooks.owns_beam_chunk);
  if (hooks.after_blocks) hooks.after_blocks(hooks.ctx, s);
  // Reductions group by group, blocks in order (same bits for any thread count and schedule).
  double die = 0, dhg = 0, dbv = 0, dsrc = 0;
  double dtmin = std::numeric_limits<double>::infinity();
  double dt_elastic = std::numeric_limits<double>::infinity();
  int arg = -1, bad = -1, nonfin = -1, failed = 0;
  for (std::size_t gi = 0; gi < s.groups.size(); ++gi) {
    const ElementGroup& g = s.groups[gi];
    double gie = 0, ghg = 0, gold = 0, gnew = 0;
    for (int b = g.first_block; b < g.first_block + g.num_blocks; ++b) {
      const BlockResult& r = s.block_results[std::size_t(b)];
      gie += r.die;
      ghg += r.dhg;
      gold += r.hg_old;
      gnew += r.hg_new;
      dsrc += r.dsrc;
      dbv += r.dbv;
      // smallest step, lowest element on ties (blocks go group by group, not in element order)
      if (r.dt_elem >= 0 && (r.dt_min < dtmin || (r.dt_min == dtmin && (arg < 0 || r.dt_elem < arg)))) {
        dtmin = r.dt_min;
        arg = r.dt_elem;
      }
      if (r.bad_volume_elem >= 0 && (bad < 0 || r.bad_volume_elem < bad)) bad = r.bad_volume_elem;
      if (r.non_finite_elem >= 0 && (nonfin < 0 || r.non_finite_elem < nonfin)) nonfin = r.non_finite_elem;
      failed += r.failed_now;
      if (r.dt_elastic < dt_elastic) dt_elastic = r.dt_elastic;
    }
    // the viscous resultants of the last pass: their work over the velocity step they acted in,
    // at the mean of the velocities before and after it (hexahedron.h)
    ghg += 0.5 * (s.hg_pending[gi] + gold) * s.dt_vel;
    s.hg_pending[gi] = gnew;
    s.mat_internal[std::size_t(g.material)] += gie;
    s.mat_hourglass[std::size_t(g.material)] += ghg;
    die += gie;
    dhg += ghg;
  }
  // the shells' books join after the solids'; a shell is reported as element s.ne + its index
  if (s.shells.ns > 0) merge_shell_results(book_shell_results(s), s.ne, die, dhg, dtmin, arg, bad, nonfin);
  if (s.beams.nb > 0)
    merge_beam_results(book_beam_results(s), s.ne + s.shells.ns, die, dtmin, arg, bad, nonfin);
  out.die = die;
  out.dhg = dhg;
  out.dbv = dbv;
  out.dsrc = dsrc;
  out.bad_volume_elem = bad;
  out.non_finite_elem = nonfin;
  out.dt_min = dtmin;
  out.dt_elem = arg;
  out.failed_now = failed;
  if (s.elastic_dt_wanted) {
    s.elastic_dt_solids = dt_elastic;
    s.elastic_dt_cycle = s.cycle;
  }
  return out;
}

}  // namespace impact3d
