#include "impact3d/solve/shell_processing.h"

#include <cmath>
#include <limits>

#include "impact3d/element/shell_fi.h"
#include "impact3d/solve/node_processing.h"
#include "impact3d/solve/rotational_corners.h"

namespace impact3d {

namespace {

constexpr int kMinShellsForThreads = 4096;

void zero_shell_corners(State& s, int k) {
  zero_rotational_corners(s, s.shells.corner_base + 4 * std::size_t(k), 4 * std::size_t(k), 4);
}

void gather_shell(const State& s, int k, double dt, ShellKernelIO& io) {
  const ShellState& sh = s.shells;
  gather_rotational_corners(s, sh.conn[std::size_t(k)], io.x, io.v, io.w);
  io.h = sh.thick[std::size_t(k)];
  io.dt = dt;
}

// A shell's points' state for the scalar kernels (ShellPointState: a shell's points together).
// A run of width 1 is that already (the pointers point into the State); a shell of a wider run
// (a block's shell going through the scalar kernel) is copied into pts, and put_shell_points
// copies it back after the kernel.
struct ShellPoints {
  double sig[5 * kMaxShellIntegrationPoints], back[6 * kMaxShellIntegrationPoints];
  double eps_p[kMaxShellIntegrationPoints];
  unsigned char yielded[kMaxShellIntegrationPoints];
};

ShellPointState shell_point_state(ShellState& sh, int k, bool plastic, bool back, ShellPoints& pts) {
  const std::size_t K = std::size_t(k);
  ShellPointState st{nullptr, nullptr, nullptr, nullptr, sh.hgq.empty() ? nullptr : &sh.hgq[5 * K], &sh.drill[4 * K]};
  if (sh.pt_width[K] == 1) {
    const std::size_t ip = std::size_t(sh.pt_base[K]);
    st.sig = &sh.sig[5 * ip];
    st.back = back ? &sh.back[6 * ip] : nullptr;
    st.eps_p = plastic ? &sh.eps_p[ip] : nullptr;
    st.yielded = plastic ? &sh.yielded[ip] : nullptr;
    return st;
  }
  const int nip = sh.nip[K];  // a run wider than 1: a group in blocks, ELFORM 2 (nip points)
  for (int p = 0; p < nip; ++p) {
    for (int c = 0; c < 5; ++c) pts.sig[5 * p + c] = sh.sig[shell_sig_at(sh, k, p, c)];
    if (back)
      for (int c = 0; c < 6; ++c) pts.back[6 * p + c] = sh.back[shell_back_at(sh, k, p, c)];
    if (plastic) {
      pts.eps_p[p] = sh.eps_p[shell_point_at(sh, k, p)];
      pts.yielded[p] = sh.yielded[shell_point_at(sh, k, p)];
    }
  }
  st.sig = pts.sig;
  st.back = back ? pts.back : nullptr;
  st.eps_p = plastic ? pts.eps_p : nullptr;
  st.yielded = plastic ? pts.yielded : nullptr;
  return st;
}

void put_shell_points(ShellState& sh, int k, bool plastic, bool back, const ShellPoints& pts) {
  const int nip = sh.nip[std::size_t(k)];
  for (int p = 0; p < nip; ++p) {
    for (int c = 0; c < 5; ++c) sh.sig[shell_sig_at(sh, k, p, c)] = pts.sig[5 * p + c];
    if (back)
      for (int c = 0; c < 6; ++c) sh.back[shell_back_at(sh, k, p, c)] = pts.back[6 * p + c];
    if (plastic) {
      sh.eps_p[shell_point_at(sh, k, p)] = pts.eps_p[p];
      sh.yielded[shell_point_at(sh, k, p)] = pts.yielded[p];
    }
  }
}

void process_shell(State& s, const ShellGroup& g, int k, double dt) {
  ShellState& sh = s.shells;
  if (sh.failed[std::size_t(k)]) {  // deleted: no forces, no step, no energy (its mass stays)
    zero_shell_corners(s, k);
    sh.dt_e[std::size_t(k)] = std::numeric_limits<double>::infinity();
    sh.de_ie[std::size_t(k)] = sh.de_hg[std::size_t(k)] = 0;
    sh.bad[std::size_t(k)] = 0;
    return;
  }
  ShellKernelIO io;
  gather_shell(s, k, dt, io);
  const bool plastic = shell_kernel_is_plastic(g.kernel);
  const bool back = shell_kernel_has_back(g.kernel);
  ShellPoints pts;
  ShellPointState st = shell_point_state(sh, k, plastic, back, pts);
  if (g.constants.elform == 16)
    calc_shell_fi_forces(g.constants, s.mats[std::size_t(g.material)], shell_material_kind(g.kernel), io, st);
  else
    calc_shell_bt_forces(g.constants, s.mats[std::size_t(g.material)], shell_material_kind(g.kernel), io, st);
  if (sh.pt_width[std::size_t(k)] != 1) put_shell_points(sh, k, plastic, back, pts);
  sh.bad[std::size_t(k)] = io.bad;
  if (io.bad) {
    zero_shell_corners(s, k);
    sh.dt_e[std::size_t(k)] = 0;
    sh.de_ie[std::size_t(k)] = sh.de_hg[std::size_t(k)] = 0;
    return;
  }
  sh.area[std::size_t(k)] = io.area;
  sh.dt_e[std::size_t(k)] = io.dt_e;
  sh.de_ie[std::size_t(k)] = io.de_ie;
  sh.de_hg[std::size_t(k)] = io.de_hg;
  store_rotational_corners(s, sh.corner_base + 4 * std::size_t(k), 4 * std::size_t(k), io.f, io.m);
  // failure (type 3 FS, type 24 FAIL): when every point through the thickness has reached it, the shell is
  // deleted; this pass's forces still act, from the next pass on it carries none.  Type 24 TDEL:
  // likewise when the shell's step falls below it.
  const MaterialConstants& mc = s.mats[std::size_t(g.material)];
  const double fs = mc.fail_strain;
  if (plastic && fs > 0 && dt > 0) {
    bool all = true;
    for (int i = 0; i < sh.nip[std::size_t(k)] && all; ++i) all = sh.eps_p[shell_point_at(sh, k, i)] >= fs;
    if (all) sh.failed[std::size_t(k)] = 2;  // 2: in this pass (the books count it)
  }
  if (mc.shell_tdel > 0 && dt > 0 && io.dt_e < mc.shell_tdel) sh.failed[std::size_t(k)] = 2;
}

// Raw views of the arrays a block reads and writes, and what the group carries, taken once per
// group pass (so that the compiler need not reload the vectors' data pointers after every store
// into the block).
struct ShellBlockArrays {
  const double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *thick;
  const std::array<int, 4>* conn;
  const int *order, *block_nodes, *node_rot, *pt_base;
  const std::uint8_t* pt_width;
  double *sig, *back, *eps_p, *hgq, *drill;
  std::uint8_t* yielded;
  double *cfx, *cfy, *cfz, *cmx, *cmy, *cmz, *area, *dt_e, *de_ie, *de_hg;
  std::uint8_t *bad, *failed;
  std::size_t corner_base;
  int nip;
  bool plastic, back_stress, hourglass_state, drilling;  // which point and shell state the group has
  double fail_strain, shell_tdel;
};

ShellBlockArrays shell_block_arrays(State& s, const ShellGroup& g, const ShellBlockMaterial& mat) {
  ShellState& sh = s.shells;
  ShellBlockArrays a;
  a.x = s.x.data(), a.y = s.y.data(), a.z = s.z.data();
  a.vx = s.vx.data(), a.vy = s.vy.data(), a.vz = s.vz.data();
  a.wx = sh.wx.data(), a.wy = sh.wy.data(), a.wz = sh.wz.data();
  a.thick = sh.thick.data();
  a.conn = sh.conn.data();
  a.order = sh.order.data(), a.block_nodes = sh.block_nodes.data();
  a.node_rot = sh.node_rot.data(), a.pt_base = sh.pt_base.data(), a.pt_width = sh.pt_width.data();
  a.sig = sh.sig.data(), a.back = sh.back.data(), a.eps_p = sh.eps_p.data(), a.hgq = sh.hgq.data();
  a.drill = sh.drill.data(), a.yielded = sh.yielded.data();
  a.cfx = s.cfx.data(), a.cfy = s.cfy.data(), a.cfz = s.cfz.data();
  a.cmx = sh.cmx.data(), a.cmy = sh.cmy.data(), a.cmz = sh.cmz.data();
  a.area = sh.area.data(), a.dt_e = sh.dt_e.data(), a.de_ie = sh.de_ie.data(), a.de_hg = sh.de_hg.data();
  a.bad = sh.bad.data(), a.failed = sh.failed.data();
  a.corner_base = sh.corner_base;
  a.nip = g.constants.nip;
  a.plastic = shell_kernel_is_plastic(g.kernel);
  a.back_stress = mat.has_back;
  a.hourglass_state = mat.has_hgq && g.constants.hourglass_coef > 0;
  a.drilling = g.constants.drill_coef > 0;
  a.fail_strain = s.mats[std::size_t(g.material)].fail_strain;
  a.shell_tdel = s.mats[std::size_t(g.material)].shell_tdel;
  return a;
}

// A block of kLanes shells ord[0..kLanes) into b: nodal data (as gather_shell), thickness, the
// points' state, the hourglass resultants and drilling moments (where the kernel reads them).
void gather_shell_block(const ShellBlockArrays& a, const int* ord, ShellBlock& b) {
  const int* bn = a.block_nodes + 4 * (ord - a.order);  // the block's corner nodes, lane after lane
  for (int j = 0; j < 4; ++j) {
    IMPACT3D_FOR_LANES {
      const int n = bn[kLanes * j + l];
      b.x[j][0][l] = a.x[n];
      b.x[j][1][l] = a.y[n];
      b.x[j][2][l] = a.z[n];
      b.v[j][0][l] = a.vx[n];
      b.v[j][1][l] = a.vy[n];
      b.v[j][2][l] = a.vz[n];
      const int r = a.node_rot[n];
      b.w[j][0][l] = r >= 0 ? a.wx[r] : 0.0;
      b.w[j][1][l] = r >= 0 ? a.wy[r] : 0.0;
      b.w[j][2][l] = r >= 0 ? a.wz[r] : 0.0;
    }
  }
  for (int l = 0; l < kLanes; ++l) {
    const std::size_t k = std::size_t(ord[l]);
    if (a.drilling)
      for (int j = 0; j < 4; ++j) b.drill[j][l] = a.drill[4 * k + std::size_t(j)];
    b.h[l] = a.thick[k];
    if (a.hourglass_state)
      for (int j = 0; j < 5; ++j) b.hgq[j][l] = a.hgq[5 * k + std::size_t(j)];
  }
  // the points' state: the block's run (shell_state.h) is laid out as ShellBlock holds it
  const std::size_t ip = std::size_t(a.pt_base[ord[0]]);
  const double* sig = a.sig + 5 * ip;
  for (int p = 0; p < a.nip; ++p)
    for (int c = 0; c < 5; ++c) IMPACT3D_FOR_LANES b.sig[p][c][l] = sig[(5 * p + c) * kLanes + l];
  if (a.back_stress) {
    const double* back = a.back + 6 * ip;
    for (int p = 0; p < a.nip; ++p)
      for (int c = 0; c < 6; ++c) IMPACT3D_FOR_LANES b.back[p][c][l] = back[(6 * p + c) * kLanes + l];
  }
  if (a.plastic) {
    const double* eps_p = a.eps_p + ip;
    const std::uint8_t* yielded = a.yielded + ip;
    for (int p = 0; p < a.nip; ++p) {
      IMPACT3D_FOR_LANES b.eps_p[p][l] = eps_p[p * kLanes + l];
      IMPACT3D_FOR_LANES b.yielded[p][l] = yielded[p * kLanes + l];
    }
  }
}

// The block's results back, shell by shell (as process_shell stores them), and the failure and
// TDEL checks.
void store_shell_block(const ShellBlockArrays& a, const int* ord, double dt, const ShellBlock& b) {
  for (int l = 0; l < kLanes; ++l) {
    const std::size_t k = std::size_t(ord[l]);
    a.bad[k] = 0;
    a.area[k] = b.area[l];
    a.dt_e[k] = b.dt_e[l];
    a.de_ie[k] = b.de_ie[l];
    a.de_hg[k] = b.de_hg[l];
    for (int j = 0; j < 4; ++j) {
      const std::size_t c = a.corner_base + 4 * k + std::size_t(j);
      a.cfx[c] = b.f[j][0][l];
      a.cfy[c] = b.f[j][1][l];
      a.cfz[c] = b.f[j][2][l];
      const std::size_t q = 4 * k + std::size_t(j);
      a.cmx[q] = b.m[j][0][l];
      a.cmy[q] = b.m[j][1][l];
      a.cmz[q] = b.m[j][2][l];
    }
    if (a.drilling)
      for (int j = 0; j < 4; ++j) a.drill[4 * k + std::size_t(j)] = b.drill[j][l];
    if (a.plastic) {
      bool all_failed = a.fail_strain > 0 && dt > 0;
      for (int p = 0; p < a.nip; ++p) all_failed = all_failed && b.eps_p[p][l] >= a.fail_strain;
      // failure as process_shell: this pass's forces still act, from the next pass on none
      if (all_failed) a.failed[k] = 2;
    }
    if (a.hourglass_state)
      for (int j = 0; j < 5; ++j) a.hgq[5 * k + std::size_t(j)] = b.hgq[j][l];
    // type 24 TDEL as process_shell: deleted when the shell's step falls below it
    if (a.shell_tdel > 0 && dt > 0 && b.dt_e[l] < a.shell_tdel) a.failed[k] = 2;
  }
  // the points' state back into the block's run (as gather_shell_block reads it)
  const std::size_t ip = std::size_t(a.pt_base[ord[0]]);
  double* sig = a.sig + 5 * ip;
  for (int p = 0; p < a.nip; ++p)
    for (int c = 0; c < 5; ++c) IMPACT3D_FOR_LANES sig[(5 * p + c) * kLanes + l] = b.sig[p][c][l];
  if (a.back_stress) {
    double* back = a.back + 6 * ip;
    for (int p = 0; p < a.nip; ++p)
      for (int c = 0; c < 6; ++c) IMPACT3D_FOR_LANES back[(6 * p + c) * kLanes + l] = b.back[p][c][l];
  }
  if (a.plastic) {
    double* eps_p = a.eps_p + ip;
    std::uint8_t* yielded = a.yielded + ip;
    for (int p = 0; p < a.nip; ++p) {
      IMPACT3D_FOR_LANES eps_p[p * kLanes + l] = b.eps_p[p][l];
      IMPACT3D_FOR_LANES yielded[p * kLanes + l] = b.yielded[p][l] != 0.0;
    }
  }
}

// kLanes shells ord[0..kLanes) through the block kernel; a block with a deleted shell or a bad
// one (non-positive area: the block's results are dropped before they are stored) goes through
// process_shell shell by shell instead (the same bits; the scalar kernel's handling of both).
void process_shell_block(State& s, const ShellGroup& g, const ShellBlockMaterial& mat, const ShellBlockArrays& a,
                         const int* ord, double dt, ShellBlock& b) {
  bool scalar = a.pt_width[ord[0]] != kLanes;  // (never: lay_out_shell_points makes each block one run)
  for (int l = 0; l < kLanes; ++l) scalar = scalar || a.failed[ord[l]] != 0;
  if (!scalar) {
    gather_shell_block(a, ord, b);
    calc_shell_bt_forces_block(g.constants, mat, dt, b);
    for (int l = 0; l < kLanes; ++l) scalar = scalar || b.bad[l] != 0.0;
  }
  if (!scalar) {
    store_shell_block(a, ord, dt, b);
    return;
  }
  for (int l = 0; l < kLanes; ++l) process_shell(s, g, ord[l], dt);
}

// A group's shells: whole blocks through the block kernel (groups with g.blocks), the rest
// (the last n mod kLanes, or every shell of the other groups) through process_shell.
// own: the group's chunks' marks (null: every shell).
void process_shells_of_group(State& s, const ShellGroup& g, const int* ord, int n, double dt, const std::uint8_t* own) {
  int scalar_from = 0;
  if (g.blocks) {
    const ShellBlockMaterial mat{&s.mats[std::size_t(g.material)], shell_material_kind(g.kernel), g.update_block,
                                 shell_kernel_has_back(g.kernel), !s.shells.hgq.empty()};
    const ShellBlockArrays a = shell_block_arrays(s, g, mat);
    const int nb = n / kLanes;
#pragma omp parallel if (n >= kMinShellsForThreads)
    {
      ShellBlock b{};  // one per thread: about 40 KB on its stack, reused block after block
#pragma omp for schedule(static)
      for (int q = 0; q < nb; ++q)
        if (!own || own[q]) process_shell_block(s, g, mat, a, ord + q * kLanes, dt, b);
    }
    scalar_from = nb * kLanes;
  }
#pragma omp parallel for schedule(static) if (n - scalar_from >= kMinShellsForThreads)
  for (int q = scalar_from; q < n; ++q)
    if (!own || own[q / kLanes]) process_shell(s, g, ord[q], dt);
}

bool shell_forces_finite(const State& s, int k) {
  return rotational_corners_finite(s, s.shells.corner_base + 4 * std::size_t(k), 4 * std::size_t(k), 4);
}

}  // namespace

int num_shell_chunks(const ShellState& sh) { return count_group_chunks(sh.groups, kLanes); }

std::vector<int> shell_chunk_of_shells(const ShellState& sh) {
  return chunk_of_group_elements(sh.groups, sh.order, sh.ns, kLanes);
}

void compute_shell_forces(State& s, const std::vector<std::uint8_t>* owns_chunk) {
  const double dt = s.dt_half;
  auto group = [&](const ShellGroup& g, const int* ord, const std::uint8_t* own) {
    if (g.kernel == ShellKernel::rigid) {
      for (int q = 0; q < g.count; ++q) zero_shell_corners(s, ord[q]);
      return;
    }
    process_shells_of_group(s, g, ord, g.count, dt, own);
  };
  for_each_group_with_chunks(s.shells.groups, s.shells.order, kLanes, owns_chunk, group);
}

ShellPassResult book_shell_results(State& s) {
  ShellPassResult out;
  out.dt_min = std::numeric_limits<double>::infinity();
  ShellState& sh = s.shells;
  for (const ShellGroup& g : sh.groups) {
    if (g.kernel == ShellKernel::rigid) continue;
    const int* ord = &sh.order[std::size_t(g.first)];
    const int n = g.count;
    // books in group order (the same bits for any thread count)
    double gie = 0, ghg = 0;
    for (int q = 0; q < n; ++q) {
      const int k = ord[q];
      const std::size_t K = std::size_t(k);
      if (sh.bad[K]) {
        if (out.bad_shell < 0 || k < out.bad_shell) out.bad_shell = k;
        continue;
      }
      if (sh.failed[K] == 2) {
        sh.failed[K] = 1;
        ++out.failed_now;
      }
      gie += sh.de_ie[K];
      sh.energy[K] += sh.de_ie[K];
      ghg += sh.de_hg[K];
      if (sh.failed[K] == 1 && sh.dt_e[K] == std::numeric_limits<double>::infinity()) continue;
      if (sh.dt_e[K] < out.dt_min || (sh.dt_e[K] == out.dt_min && k < out.dt_shell)) {
        out.dt_min = sh.dt_e[K];
        out.dt_shell = k;
      }
      if (!shell_forces_finite(s, k) && (out.non_finite_shell < 0 || k < out.non_finite_shell))
        out.non_finite_shell = k;
    }
    s.mat_internal[std::size_t(g.material)] += gie;
    s.mat_hourglass[std::size_t(g.material)] += ghg;
    out.die += gie;
    out.dhg += ghg;
  }
  return out;
}

ShellPassResult calc_forces_for_shells(const Model& m, State& s) {
  (void)m;
  compute_shell_forces(s);
  return book_shell_results(s);
}

void update_rotational_velocities_for_nodes(State& s, double dt_n) {
  ShellState& sh = s.shells;
  if (sh.nr == 0) return;
  const int* cs = sh.rot_corner_start.data();
  const int* cl = sh.rot_corner_list.data();
  // the time-centred book's product w^{n-1/2} . w*, w* = w^{n-1/2} + r (w^{n+1/2} - w^{n-1/2}) with
  // r = dt^{n-1/2} / dt^n: the increment as a step equal to the last would have made it (r = 1 but
  // where the step changes: the last step landing on the end time; run_cycle.h)
  const double r_step = s.dt_half > 0 ? s.dt_half / dt_n : 1.0;
  double ke_centred = 0;
  for (int r = 0; r < sh.nr; ++r) {
    const std::size_t R = std::size_t(r);
    const int node = sh.rot_node[R];
    const int rb = s.rigid_of_node[std::size_t(node)];
    const double w0x = sh.wx[R], w0y = sh.wy[R], w0z = sh.wz[R];
    if (rb >= 0) {  // a node of a rigid body turns with it
      const auto& w = s.rigid[std::size_t(rb)].omega;
      sh.wx[R] = w[0];
      sh.wy[R] = w[1];
      sh.wz[R] = w[2];
      ke_centred += 0.5 * sh.inertia[R] * time_centred_product(w0x, w0y, w0z, w[0], w[1], w[2], r_step);
      continue;
    }
    double mx = 0, my = 0, mz = 0;
    for (int c = cs[r]; c < cs[r + 1]; ++c) {
      const std::size_t q = std::size_t(cl[c]);
      mx += sh.cmx[q];
      my += sh.cmy[q];
      mz += sh.cmz[q];
    }
    const double inv = sh.inertia[R] > 0 ? 1.0 / sh.inertia[R] : 0.0;
    const std::uint8_t f = sh.rot_fix[R];
    if (!(f & 1)) sh.wx[R] -= dt_n * mx * inv;
    if (!(f & 2)) sh.wy[R] -= dt_n * my * inv;
    if (!(f & 4)) sh.wz[R] -= dt_n * mz * inv;
    ke_centred += 0.5 * sh.inertia[R] * time_centred_product(w0x, w0y, w0z, sh.wx[R], sh.wy[R], sh.wz[R], r_step);
  }
  sh.rot_kinetic_centred = ke_centred;
  sh.rot_kinetic = calc_rotational_kinetic_energy(s);
  s.kinetic += sh.rot_kinetic;
}

double calc_rotational_kinetic_energy(const State& s) {
  const ShellState& sh = s.shells;
  double ke = 0;
  for (int r = 0; r < sh.nr; ++r) {
    const std::size_t R = std::size_t(r);
    ke += 0.5 * sh.inertia[R] * (sh.wx[R] * sh.wx[R] + sh.wy[R] * sh.wy[R] + sh.wz[R] * sh.wz[R]);
  }
  return ke;
}

}  // namespace impact3d
