#include "impact3d/solve/beam_processing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "impact3d/material/material_types.h"
#include "impact3d/solve/rotational_corners.h"

namespace impact3d {

namespace {

constexpr int kMinBeamsForThreads = 4096;

void zero_beam_ends(State& s, int b) {
  const BeamState& bm = s.beams;
  zero_rotational_corners(s, bm.corner_base + 2 * std::size_t(b), bm.moment_base + 2 * std::size_t(b), 2);
}

void gather_beam(const State& s, int b, double dt, BeamKernelIO& io) {
  const BeamState& bm = s.beams;
  gather_rotational_corners(s, bm.conn[std::size_t(b)], io.x, io.v, io.w);
  for (int a = 0; a < 3; ++a) io.e2[a] = bm.e2[3 * std::size_t(b) + std::size_t(a)];
  io.dt = dt;
}

void process_beam(State& s, const BeamGroup& g, int b, double dt) {
  BeamState& bm = s.beams;
  const std::size_t B = std::size_t(b);
  if (bm.failed[B]) {  // deleted: no forces, no step
    zero_beam_ends(s, b);
    bm.bad[B] = 0;
    bm.dt_e[B] = std::numeric_limits<double>::infinity();
    bm.de_ie[B] = 0;
    return;
  }
  BeamKernelIO io;
  gather_beam(s, b, dt, io);
  const std::size_t ip = std::size_t(bm.ip_start[B]);
  const bool plastic = g.material_kind != BeamMaterialKind::elastic;
  BeamPointState st{bm.sig.data() + 3 * ip, bm.eps_rr.data() + ip, g.material_kind == BeamMaterialKind::plastic_kinematic ? &bm.back[6 * ip] : nullptr,
                    plastic ? &bm.eps_p[ip] : nullptr, plastic ? &bm.yielded[ip] : nullptr};
  const MaterialConstants& mc = s.mats[std::size_t(g.material)];
  if (g.kernel == BeamKernel::truss) calc_truss_forces(bm.area[B], mc, g.material_kind, io, st);
  else if (g.kernel == BeamKernel::resultant) calc_beam_bs_forces(bm.rsec[B], mc, io, &bm.bs[6 * B]);
  else calc_beam_hl_forces(bm.size[B], g.rule, g.shrf, mc, g.material_kind, io, st);
  bm.bad[B] = io.bad;
  if (io.bad) {
    zero_beam_ends(s, b);
    bm.dt_e[B] = 0;
    bm.de_ie[B] = 0;
    return;
  }
  bm.length[B] = io.length;
  bm.dt_e[B] = beam_time_step(io.length, mc) / bm.step_scale[B];
  bm.de_ie[B] = io.de_ie;
  for (int a = 0; a < 3; ++a) bm.e2[3 * B + std::size_t(a)] = io.e2[a];
  for (int k = 0; k < 6; ++k) bm.res[6 * B + std::size_t(k)] = io.res[k];
  store_rotational_corners(s, bm.corner_base + 2 * B, bm.moment_base + 2 * B, io.f, io.m);
}

bool beam_forces_finite(const State& s, int b) {
  const BeamState& bm = s.beams;
  return rotational_corners_finite(s, bm.corner_base + 2 * std::size_t(b), bm.moment_base + 2 * std::size_t(b), 2);
}

}  // namespace

bool spot_weld_beam_fails(const MaterialConstants& mc, const double res[6], const double* eps_p, int points, double time) {
  const double tfail = mc.k[kSpotWeldTFAIL];
  if (tfail > 0 && time >= tfail) return true;
  // the failure resultants in the order of BeamState::res (N, Q_s, Q_t, T, M_s, M_t): NRR, NRS,
  // NRT, MRR, MSS, MTT
  const double* cap = &mc.k[kSpotWeldNRR];
  bool any = false;
  double f = 0;
  for (int i = 0; i < 6; ++i) {
    const double c = cap[i];
    if (!(c > 0)) continue;
    any = true;
    const double r = i == 0 ? std::max(res[0], 0.0) : res[i];  // the axial force in tension only
    f += (r / c) * (r / c);
  }
  if (any) return f >= 1;
  if (mc.fail_strain > 0 && eps_p && points > 0) {
    for (int p = 0; p < points; ++p)
      if (eps_p[p] < mc.fail_strain) return false;
    return true;
  }
  return false;
}

double beam_time_step(double length, const MaterialConstants& mc) {
  const double c = mc.rho > 0 ? std::sqrt(mc.E / mc.rho) : 0.0;
  return c > 0 ? length / c : std::numeric_limits<double>::infinity();
}

const double* filtered_weld_resultants(BeamState& bm, int b, double mean[6]) {
  const std::size_t B = std::size_t(b);
  const double* res = &bm.res[6 * B];
  if (bm.weld_res_start.empty()) return res;
  const int first = bm.weld_res_start[B], nf = (bm.weld_res_start[B + 1] - first) / 6;
  if (nf == 0) return res;
  double* ring = &bm.weld_res[std::size_t(first)];
  int& count = bm.weld_res_count[B];
  for (int i = 0; i < 6; ++i) ring[6 * (count % nf) + i] = res[i];
  ++count;
  const int stored = std::min(count, nf);
  for (int i = 0; i < 6; ++i) {
    double sum = 0;
    for (int k = 0; k < stored; ++k) sum += ring[6 * k + i];  // slot order: the same bits on a restart
    mean[i] = sum / stored;
  }
  return mean;
}

int num_beam_chunks(const BeamState& bm) { return count_group_chunks(bm.groups, kLanes); }

std::vector<int> beam_chunk_of_beams(const BeamState& bm) {
  return chunk_of_group_elements(bm.groups, bm.order, bm.nb, kLanes);
}

void compute_beam_forces(State& s, const std::vector<std::uint8_t>* owns_chunk) {
  const double dt = s.dt_half;
  auto group = [&](const BeamGroup& g, const int* ord, const std::uint8_t* own) {
    const int n = g.count;
    if (g.kernel == BeamKernel::rigid) {
      for (int q = 0; q < n; ++q) zero_beam_ends(s, ord[q]);
      return;
    }
#pragma omp parallel for schedule(static) if (n >= kMinBeamsForThreads)
    for (int q = 0; q < n; ++q)
      if (!own || own[q / kLanes]) process_beam(s, g, ord[q], dt);
  };
  for_each_group_with_chunks(s.beams.groups, s.beams.order, kLanes, owns_chunk, group);
}

BeamPassResult book_beam_results(State& s) {
  BeamPassResult out;
  out.dt_min = std::numeric_limits<double>::infinity();
  BeamState& bm = s.beams;
  const double dt = s.dt_half;
  bm.newly_failed.clear();
  for (const BeamGroup& g : bm.groups) {
    if (g.kernel == BeamKernel::rigid) continue;
    const int* ord = &bm.order[std::size_t(g.first)];
    const int n = g.count;
    // books in group order (the same bits for any thread count)
    double gie = 0;
    for (int q = 0; q < n; ++q) {
      const int b = ord[q];
      const std::size_t B = std::size_t(b);
      if (bm.failed[B]) continue;
      if (bm.bad[B]) {
        if (out.bad_beam < 0 || b < out.bad_beam) out.bad_beam = b;
        continue;
      }
      gie += bm.de_ie[B];
      bm.energy[B] += bm.de_ie[B];
      if (bm.dt_e[B] < out.dt_min || (bm.dt_e[B] == out.dt_min && b < out.dt_beam)) {
        out.dt_min = bm.dt_e[B];
        out.dt_beam = b;
      }
      if (!beam_forces_finite(s, b) && (out.non_finite_beam < 0 || b < out.non_finite_beam)) out.non_finite_beam = b;
      // *MAT_SPOTWELD: its failure rule on this pass's resultants (at x^{n+1}); this pass's
      // forces still act, from the next pass on the beam carries none
      if (g.spot_weld && dt > 0) {
        const std::size_t ip = std::size_t(bm.ip_start[B]);
        const int points = bm.ip_start[B + 1] - bm.ip_start[B];
        double mean[6];
        const double* res = filtered_weld_resultants(bm, b, mean);
        if (spot_weld_beam_fails(s.mats[std::size_t(g.material)], res, bm.eps_p.empty() ? nullptr : &bm.eps_p[ip], points,
                                 s.time)) {
          bm.failed[B] = 1;
          bm.newly_failed.push_back(b);
        }
      }
    }
    s.mat_internal[std::size_t(g.material)] += gie;
    out.die += gie;
  }
  return out;
}

BeamPassResult calc_forces_for_beams(const Model& m, State& s) {
  (void)m;
  compute_beam_forces(s);
  return book_beam_results(s);
}

}  // namespace impact3d
