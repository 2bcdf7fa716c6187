// The distributed cycle (distributed_cycle.h).
#include "impact3d/parallel/distributed_cycle.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "common/messages.h"
#include "impact3d/element/shell_fi.h"
#include "impact3d/material/material_types.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/parallel/comm.h"
#include "impact3d/solve/engine.h"
#include "impact3d/solve/beam_processing.h"
#include "impact3d/solve/shell_processing.h"

namespace impact3d::parallel {

namespace {

constexpr int kTagCorners = 1, kTagKinematics = 2;
constexpr std::size_t kBlockCorners = 8 * kLanes;

// Every value of node k that the outputs or a restart dump read, in a fixed order (the external
// forces: their owner's are one process's, a restart dump holds them).
template <class F>
void visit_node(State& s, std::size_t k, F&& f) {
  for (std::vector<double>* v : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.ax, &s.ay, &s.az, &s.vx_old, &s.vy_old,
                                 &s.vz_old, &s.fext_x, &s.fext_y, &s.fext_z})
    if (!v->empty()) f((*v)[k]);
}

// Every value of solid e that changes in the cycle (State::visit_dynamic_fields' solid part).
template <class F>
void visit_solid(State& s, std::size_t e, F&& f) {
  f(s.vol[e]);
  f(s.q[e]);
  f(s.dt_e[e]);
  f(s.failed[e]);
  if (!s.eps_p.empty()) f(s.eps_p[e]);
  if (!s.yielded.empty()) f(s.yielded[e]);
  for (std::size_t c = 0; c < 6; ++c) f(s.sig[6 * e + c]);
  if (!s.back.empty())
    for (std::size_t c = 0; c < 6; ++c) f(s.back[6 * e + c]);
  if (!s.hgs.empty())
    for (std::size_t c = 0; c < 12; ++c) f(s.hgs[12 * e + c]);
  const std::size_t hs = std::size_t(s.hist_stride);
  if (!s.hist.empty())
    for (std::size_t h = 0; h < hs; ++h) f(s.hist[hs * e + h]);
  if (s.pt_first.empty() || s.pt_first[e] < 0) return;
  for (std::size_t g = 0; g < 8; ++g) {  // a fully integrated solid's points
    const std::size_t p = std::size_t(s.pt_first[e]) + g;
    for (std::size_t c = 0; c < 6; ++c) f(s.pt_sig[6 * p + c]);
    if (!s.pt_back.empty())
      for (std::size_t c = 0; c < 6; ++c) f(s.pt_back[6 * p + c]);
    f(s.pt_eps_p[p]);
    f(s.pt_yielded[p]);
    if (!s.pt_hist.empty())
      for (std::size_t h = 0; h < hs; ++h) f(s.pt_hist[hs * p + h]);
  }
}

// Every value of shell k that changes in the cycle and is not among the shell results that go
// to every rank each cycle (ShellRecord): State::visit_dynamic_fields' shell part.  `points`:
// the shell's integration points, all of them (ELFORM 16: 5 x NIP, shell_fi.h; the outputs read
// the first NIP, a restart dump all).
template <class F>
void visit_shell(State& s, std::size_t k, int points, F&& f) {
  ShellState& sh = s.shells;
  f(sh.area[k]);
  const int K = int(k);
  for (int p = 0; p < points; ++p) {
    for (int c = 0; c < 5; ++c) f(sh.sig[shell_sig_at(sh, K, p, c)]);
    if (!sh.back.empty())
      for (int c = 0; c < 6; ++c) f(sh.back[shell_back_at(sh, K, p, c)]);
    if (!sh.eps_p.empty()) f(sh.eps_p[shell_point_at(sh, K, p)]);
    if (!sh.yielded.empty()) f(sh.yielded[shell_point_at(sh, K, p)]);
  }
  if (!sh.hgq.empty())
    for (std::size_t c = 0; c < 5; ++c) f(sh.hgq[5 * k + c]);
  for (std::size_t c = 0; c < 4; ++c) f(sh.drill[4 * k + c]);
}

// What every rank needs of shell k after the element pass: the books' inputs (this pass's
// energy increments, step, bad and failure marks) and its corner forces and moments (the
// node pass of the owners of its nodes, the rotational update that every rank makes).
template <class F>
void visit_shell_record(State& s, std::size_t k, F&& f) {
  ShellState& sh = s.shells;
  f(sh.de_ie[k]);
  f(sh.de_hg[k]);
  f(sh.dt_e[k]);
  f(sh.bad[k]);
  f(sh.failed[k]);
  for (std::size_t j = 0; j < 4; ++j) {
    const std::size_t c = sh.corner_base + 4 * k + j, q = 4 * k + j;
    f(s.cfx[c]), f(s.cfy[c]), f(s.cfz[c]);
    f(sh.cmx[q]), f(sh.cmy[q]), f(sh.cmz[q]);
  }
}
constexpr std::size_t kShellRecord = 5 + 4 * 6;

// Every value of beam b that changes in the cycle and is not in its BeamRecord (State::
// visit_dynamic_fields' beam part; the spot welds' rings are refused).
template <class F>
void visit_beam(State& s, std::size_t b, F&& f) {
  BeamState& bm = s.beams;
  f(bm.length[b]);
  for (std::size_t a = 0; a < 3; ++a) f(bm.e2[3 * b + a]);
  for (std::size_t p = std::size_t(bm.ip_start[b]); p < std::size_t(bm.ip_start[b + 1]); ++p) {
    for (std::size_t c = 0; c < 3; ++c) f(bm.sig[3 * p + c]);
    f(bm.eps_rr[p]);
    if (!bm.back.empty())
      for (std::size_t c = 0; c < 6; ++c) f(bm.back[6 * p + c]);
    if (!bm.eps_p.empty()) f(bm.eps_p[p]);
    if (!bm.yielded.empty()) f(bm.yielded[p]);
  }
  for (std::size_t c = 0; c < 6; ++c) f(bm.res[6 * b + c]);
  if (!bm.bs.empty())
    for (std::size_t c = 0; c < 6; ++c) f(bm.bs[6 * b + c]);
}

// What every rank needs of beam b after the element pass (as a shell's record).
template <class F>
void visit_beam_record(State& s, std::size_t b, F&& f) {
  BeamState& bm = s.beams;
  ShellState& sh = s.shells;
  f(bm.de_ie[b]);
  f(bm.dt_e[b]);
  f(bm.bad[b]);
  f(bm.failed[b]);
  for (std::size_t j = 0; j < 2; ++j) {
    const std::size_t c = bm.corner_base + 2 * b + j, q = bm.moment_base + 2 * b + j;
    f(s.cfx[c]), f(s.cfy[c]), f(s.cfz[c]);
    f(sh.cmx[q]), f(sh.cmy[q]), f(sh.cmz[q]);
  }
}
constexpr std::size_t kBeamRecord = 4 + 2 * 6;

// A block's corner forces and its solids.
template <class F>
void visit_block(State& s, std::size_t b, F&& f) {
  for (std::vector<double>* v : {&s.cfx, &s.cfy, &s.cfz})
    for (std::size_t c = 0; c < kBlockCorners; ++c) f((*v)[b * kBlockCorners + c]);
  for (std::size_t l = 0; l < std::size_t(kLanes); ++l)
    if (const int e = s.slot_elem[b * kLanes + l]; e >= 0) visit_solid(s, std::size_t(e), f);
}

// Values written to or read from a buffer of doubles (bytes as 0-255, exact).
struct Packer {
  double* out;
  std::size_t n = 0;
  void operator()(double& v) { out[n++] = v; }
  void operator()(std::uint8_t& v) { out[n++] = v; }
};
struct Unpacker {
  const double* in;
  std::size_t n = 0;
  void operator()(double& v) { v = in[n++]; }
  void operator()(std::uint8_t& v) { v = std::uint8_t(in[n++]); }
};
struct Counter {
  std::size_t n = 0;
  void operator()(double&) { ++n; }
  void operator()(std::uint8_t&) { ++n; }
};

// Adds the wall-clock time of a scope to a total.
struct Timer {
  double& total;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  explicit Timer(double& t) : total(t) {}
  ~Timer() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
};

struct Command {
  int op = 0, code = 0;
  double land_time = -1;
};

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> d(counts.size(), 0);
  for (std::size_t q = 1; q < counts.size(); ++q) d[q] = d[q - 1] + counts[q - 1];
  return d;
}

}  // namespace

std::string distributed_refusal(const Model& m, int nranks) {
  std::vector<std::string> what;
  if (!m.interfaces.empty()) what.push_back("sliding interfaces");
  if (!m.force_transducers.empty()) what.push_back("force transducers");
  if (!m.tied_contacts.empty()) what.push_back("tied contacts");
  bool rigid = !m.spot_welds.empty(), failure = m.control.erode_small_steps, shell_failure = false,
       weld_beams = false;
  for (const MaterialData& md : m.materials) {
    if (material_type(md.type).rigid) rigid = true;
    if (md.beam) {
      weld_beams = weld_beams || md.type == 100;  // *MAT_SPOTWELD: its failure rule deletes beams
      continue;
    }
    const MaterialConstants mc = derive_constants(md, m);
    if (md.shell) {
      if (mc.fail_strain > 0 || mc.shell_tdel > 0) shell_failure = true;
      continue;
    }
    if (mc.fail_strain > 0 || mc.tdel > 0 || mc.fail_history >= 0 || mc.vol_erode_hi > 0 || mc.vol_erode_lo > 0 ||
        mc.erosion)
      failure = true;
  }
  if (rigid) what.push_back("rigid bodies");
  if (failure) what.push_back("solid failure or erosion");
  if (shell_failure) what.push_back("shell failure (FS, FAIL, TDEL)");
  if (weld_beams) what.push_back("spot-weld beams (*MAT_SPOTWELD)");
  const std::size_t fixed = fixed_walls_for_node_pass(m).size();
  if (!m.walls.empty() && (fixed != m.walls.size() || fixed > kMaxFusedWalls))
    what.push_back("moving stonewalls or stonewalls on node lists");
  // one block of kLanes solids, shells or beams of one material at least per rank
  std::vector<int> solids(m.materials.size(), 0), shells(m.materials.size(), 0), beams(m.materials.size(), 0);
  for (int mat : m.hex_material) ++solids[std::size_t(mat)];
  for (int mat : m.shell_material) ++shells[std::size_t(mat)];
  for (int mat : m.beam_material) ++beams[std::size_t(mat)];
  long blocks = 0;
  for (std::size_t i = 0; i < m.materials.size(); ++i)
    blocks += (solids[i] + kLanes - 1) / kLanes + (shells[i] + kLanes - 1) / kLanes + (beams[i] + kLanes - 1) / kLanes;
  if (blocks < nranks)
    what.push_back(std::to_string(blocks) + " blocks of solids, shells and beams for " + std::to_string(nranks) +
                   " ranks (one block of 8 elements per rank at least)");
  std::string out;
  for (const std::string& w : what) out += (out.empty() ? "" : ", ") + w;
  return out;
}

DistributedCycle::DistributedCycle() : rank_(rank()), nranks_(size()) {}

void DistributedCycle::setup(const State& s, const Model& m, const LoadSet& loads) {
  model_ = &m;
  loads_ = &loads;
  load_terms_ = loads.has_loads || loads.has_motions;
  const std::size_t nb = s.slot_elem.size() / kLanes, nsc = std::size_t(num_shell_chunks(s.shells)),
                    nu = nb + nsc + std::size_t(num_beam_chunks(s.beams));
  // the partition: rank 0 computes it, every rank gets it (one partition, whatever METIS does)
  std::vector<int> block_rank(nu, 0);
  int ok = 1;
  BlockGraph g;
  if (leads()) {
    g = block_graph(s);
    try {
      block_rank = partition_blocks(g, nranks_);
    } catch (const std::exception&) {
      ok = 0;
    }
  }
  broadcast(&ok, sizeof ok);
  if (!ok) throw std::runtime_error("the partition failed (METIS)");
  broadcast(block_rank.data(), nu * sizeof(int));
  std::vector<std::vector<int>> faces;  // a pressure face's corners: its force needs all four
  for (const PressureLoad& l : m.pressure_loads) faces.emplace_back(l.nodes.begin(), l.nodes.end());
  dom_ = build_domain(s, block_rank, nranks_, rank_, faces);
  if (leads()) report_ = partition_report(summarize_partition(s, g, block_rank, nranks_));

  rank_blocks_.assign(std::size_t(nranks_), {});
  for (std::size_t b = 0; b < nb; ++b) rank_blocks_[std::size_t(block_rank[b])].push_back(int(b));  // solids' blocks
  block_bytes_.assign(std::size_t(nranks_), 0);
  for (int q = 0; q < nranks_; ++q)
    block_bytes_[std::size_t(q)] = int(rank_blocks_[std::size_t(q)].size() * sizeof(BlockResult));
  block_displs_ = displacements(block_bytes_);
  block_buf_.resize(nb);
  if (m.control.mass_scaling_dt != 0) {  // every solid's step to every rank (mass_scaling.h)
    step_bytes_.assign(std::size_t(nranks_), 0);
    for (int q = 0; q < nranks_; ++q)
      step_bytes_[std::size_t(q)] = int(rank_blocks_[std::size_t(q)].size() * kLanes * sizeof(double));
    step_displs_ = displacements(step_bytes_);
    step_buf_.assign(nb * kLanes, 0.0);
  }
  // the shells' and beams' records: every rank's shells, then its beams, chunk after chunk
  rank_shells_.assign(std::size_t(nranks_), {});
  rank_beams_.assign(std::size_t(nranks_), {});
  const std::vector<int> shell_chunk = shell_chunk_of_shells(s.shells), beam_chunk = beam_chunk_of_beams(s.beams);
  // (a group's order runs chunk after chunk, increasing in a chunk: partition.h's owned lists)
  for (int k : s.shells.order) rank_shells_[std::size_t(block_rank[nb + std::size_t(shell_chunk[std::size_t(k)])])].push_back(k);
  for (int b : s.beams.order)
    rank_beams_[std::size_t(block_rank[nb + nsc + std::size_t(beam_chunk[std::size_t(b)])])].push_back(b);
  shell_bytes_.assign(std::size_t(nranks_), 0);
  for (int q = 0; q < nranks_; ++q)
    shell_bytes_[std::size_t(q)] = int((rank_shells_[std::size_t(q)].size() * kShellRecord +
                                        rank_beams_[std::size_t(q)].size() * kBeamRecord) * sizeof(double));
  shell_displs_ = displacements(shell_bytes_);
  shell_buf_.assign(std::size_t(s.shells.ns) * kShellRecord + std::size_t(s.beams.nb) * kBeamRecord, 0.0);
  rank_nodes_.assign(std::size_t(nranks_), {});
  if (leads())
    for (std::size_t n = 0; n < std::size_t(s.nn); ++n) rank_nodes_[std::size_t(dom_.node_rank[n])].push_back(int(n));
  // the load terms: each slot on the rank that owns its node (a rigid body's: rank 0)
  const std::vector<int> slot_node = load_term_nodes(m);
  rank_slots_.assign(std::size_t(nranks_), {});
  for (std::size_t j = 0; j < slot_node.size(); ++j)
    rank_slots_[slot_node[j] < 0 ? 0 : std::size_t(dom_.node_rank[std::size_t(slot_node[j])])].push_back(int(j));
  terms_.assign(slot_node.size(), 0.0);
  all_terms_.assign(leads() ? slot_node.size() : 0, 0.0);
  records_.clear();
  setup_exchanges();
  setup_gathers(s, m);
}

// The neighbour exchanges' buffers: per peer its corners (3 values each), then its nodes (6).
void DistributedCycle::setup_exchanges() {
  std::size_t ns = 0, nr = 0;
  for (const Peer& p : dom_.peers) {
    ns += 3 * p.send_corners.size() + 6 * p.send_nodes.size();
    nr += 3 * p.recv_corners.size() + 6 * p.recv_nodes.size();
  }
  send_buf_.assign(ns, 0.0);
  recv_buf_.assign(nr, 0.0);
  corner_ex_.clear();
  node_ex_.clear();
  double* sp = send_buf_.data();
  double* rp = recv_buf_.data();
  for (const Peer& p : dom_.peers) {
    Exchange c{p.rank, sp, int(3 * p.send_corners.size()), rp, int(3 * p.recv_corners.size())};
    sp += c.send_count, rp += c.recv_count;
    Exchange k{p.rank, sp, int(6 * p.send_nodes.size()), rp, int(6 * p.recv_nodes.size())};
    sp += k.send_count, rp += k.recv_count;
    corner_ex_.push_back(c);
    node_ex_.push_back(k);
  }
}

// The output gather's sizes (each rank's own nodes, blocks, shells, beams and the angles of its
// nodes' prescribed motions) and the velocities' gather (6 values a node).
void DistributedCycle::setup_gathers(const State& s, const Model& m) {
  State& sm = const_cast<State&>(s);  // (the counter only counts)
  Counter cnt;
  for (int n : dom_.owned_nodes) visit_node(sm, std::size_t(n), cnt);
  for (int b : dom_.owned_blocks) visit_block(sm, std::size_t(b), cnt);
  shell_points_.assign(std::size_t(s.shells.ns), 0);
  for (const ShellGroup& g : s.shells.groups)
    for (int i = g.first; i < g.first + g.count; ++i) {
      const std::size_t k = std::size_t(s.shells.order[std::size_t(i)]);
      shell_points_[k] = shell_points_per_shell(g.constants.elform, s.shells.nip[k]);
    }
  for (int k : dom_.owned_shells) visit_shell(sm, std::size_t(k), shell_points_[std::size_t(k)], cnt);
  for (int b : dom_.owned_beams) visit_beam(sm, std::size_t(b), cnt);
  // the prescribed motions of nodes: each on the rank that owns its node (their angles)
  rank_motions_.assign(std::size_t(nranks_), {});
  for (std::size_t j = 0; j < m.prescribed_motions.size(); ++j)
    if (const int n = m.prescribed_motions[j].node; n >= 0)
      rank_motions_[std::size_t(dom_.node_rank[std::size_t(n)])].push_back(int(j));
  cnt.n += rank_motions_[std::size_t(rank_)].size();
  state_buf_.assign(cnt.n, 0.0);
  const int mine = int(cnt.n * sizeof(double));
  state_bytes_.assign(std::size_t(nranks_), 0);
  std::vector<int> one(std::size_t(nranks_), int(sizeof(int)));
  gather(&mine, int(sizeof(int)), state_bytes_.data(), one.data(), displacements(one).data());
  state_displs_ = displacements(state_bytes_);
  if (leads()) state_all_.assign(std::size_t(state_displs_.back() + state_bytes_.back()) / sizeof(double), 0.0);
  // the velocities' gather: each rank's own nodes, 6 values each
  vel_buf_.assign(6 * dom_.owned_nodes.size(), 0.0);
  vel_bytes_.assign(std::size_t(nranks_), 0);
  for (int q = 0; q < nranks_; ++q)
    vel_bytes_[std::size_t(q)] = leads() ? int(6 * rank_nodes_[std::size_t(q)].size() * sizeof(double)) : 0;
  vel_displs_ = displacements(vel_bytes_);
  if (leads()) vel_all_.assign(6 * std::size_t(s.nn), 0.0);
}

ElementPassHooks DistributedCycle::element_hooks() {
  ElementPassHooks h;
  h.owns_block = &dom_.owns_block;
  h.owns_shell_chunk = &dom_.owns_chunk;
  h.owns_beam_chunk = &dom_.owns_beam_chunk;
  h.after_blocks = &DistributedCycle::after_blocks;
  h.ctx = this;
  return h;
}

void DistributedCycle::after_blocks(void* self, State& s) {
  auto* d = static_cast<DistributedCycle*>(self);
  const Timer t(d->comm_s_);
  d->share_block_results(s);
  if (!d->step_buf_.empty()) d->share_solid_steps(s);
  if (s.shells.ns > 0 || s.beams.nb > 0) d->share_shell_results(s);
  d->send_corner_forces(s);
}

void DistributedCycle::share_block_results(State& s) {
  const std::vector<int>& mine = rank_blocks_[std::size_t(rank_)];
  BlockResult* own = block_buf_.data() + block_displs_[std::size_t(rank_)] / int(sizeof(BlockResult));
  for (std::size_t i = 0; i < mine.size(); ++i) own[i] = s.block_results[std::size_t(mine[i])];
  allgather(own, block_bytes_[std::size_t(rank_)], block_buf_.data(), block_bytes_.data(), block_displs_.data());
  for (int q = 0; q < nranks_; ++q) {
    const BlockResult* from = block_buf_.data() + block_displs_[std::size_t(q)] / int(sizeof(BlockResult));
    const std::vector<int>& theirs = rank_blocks_[std::size_t(q)];
    for (std::size_t i = 0; i < theirs.size(); ++i) s.block_results[std::size_t(theirs[i])] = from[i];
  }
}

void DistributedCycle::share_solid_steps(State& s) {
  double* own = step_buf_.data() + step_displs_[std::size_t(rank_)] / int(sizeof(double));
  for (int b : rank_blocks_[std::size_t(rank_)])
    for (std::size_t l = 0; l < std::size_t(kLanes); ++l) {
      const int e = s.slot_elem[std::size_t(b) * kLanes + l];
      *own++ = e >= 0 ? s.dt_e[std::size_t(e)] : 0.0;
    }
  own = step_buf_.data() + step_displs_[std::size_t(rank_)] / int(sizeof(double));
  allgather(own, step_bytes_[std::size_t(rank_)], step_buf_.data(), step_bytes_.data(), step_displs_.data());
  for (int q = 0; q < nranks_; ++q) {
    if (q == rank_) continue;
    const double* in = step_buf_.data() + step_displs_[std::size_t(q)] / int(sizeof(double));
    for (int b : rank_blocks_[std::size_t(q)])
      for (std::size_t l = 0; l < std::size_t(kLanes); ++l, ++in)
        if (const int e = s.slot_elem[std::size_t(b) * kLanes + l]; e >= 0) s.dt_e[std::size_t(e)] = *in;
  }
}

void DistributedCycle::before_adding_mass(void* self, State& s) {
  static_cast<DistributedCycle*>(self)->gather_velocities(s);
}

void DistributedCycle::share_shell_results(State& s) {
  double* own = shell_buf_.data() + shell_displs_[std::size_t(rank_)] / int(sizeof(double));
  Packer pk{own};
  for (int k : rank_shells_[std::size_t(rank_)]) visit_shell_record(s, std::size_t(k), pk);
  for (int b : rank_beams_[std::size_t(rank_)]) visit_beam_record(s, std::size_t(b), pk);
  allgather(own, shell_bytes_[std::size_t(rank_)], shell_buf_.data(), shell_bytes_.data(), shell_displs_.data());
  for (int q = 0; q < nranks_; ++q) {
    if (q == rank_) continue;
    Unpacker up{shell_buf_.data() + shell_displs_[std::size_t(q)] / int(sizeof(double))};
    for (int k : rank_shells_[std::size_t(q)]) visit_shell_record(s, std::size_t(k), up);
    for (int b : rank_beams_[std::size_t(q)]) visit_beam_record(s, std::size_t(b), up);
  }
}

void DistributedCycle::send_corner_forces(State& s) {
  for (std::size_t i = 0; i < dom_.peers.size(); ++i) {
    double* out = const_cast<double*>(corner_ex_[i].send);
    for (int c : dom_.peers[i].send_corners) {
      *out++ = s.cfx[std::size_t(c)];
      *out++ = s.cfy[std::size_t(c)];
      *out++ = s.cfz[std::size_t(c)];
    }
  }
  exchange(corner_ex_, kTagCorners);
  for (std::size_t i = 0; i < dom_.peers.size(); ++i) {
    const double* in = corner_ex_[i].recv;
    for (int c : dom_.peers[i].recv_corners) {
      s.cfx[std::size_t(c)] = *in++;
      s.cfy[std::size_t(c)] = *in++;
      s.cfz[std::size_t(c)] = *in++;
    }
  }
}

void DistributedCycle::send_ghost_kinematics(State& s) {
  for (std::size_t i = 0; i < dom_.peers.size(); ++i) {
    double* out = const_cast<double*>(node_ex_[i].send);
    for (int n : dom_.peers[i].send_nodes) {
      const std::size_t k = std::size_t(n);
      *out++ = s.x[k], *out++ = s.y[k], *out++ = s.z[k];
      *out++ = s.vx[k], *out++ = s.vy[k], *out++ = s.vz[k];
    }
  }
  exchange(node_ex_, kTagKinematics);
  for (std::size_t i = 0; i < dom_.peers.size(); ++i) {
    const double* in = node_ex_[i].recv;
    for (int n : dom_.peers[i].recv_nodes) {
      const std::size_t k = std::size_t(n);
      s.x[k] = *in++, s.y[k] = *in++, s.z[k] = *in++;
      s.vx[k] = *in++, s.vy[k] = *in++, s.vz[k] = *in++;
    }
  }
}

void DistributedCycle::size_node_records(const State& s, const NodePass& p) {
  const std::size_t nodes = dom_.owned_nodes.size(), mine = rank_slots_[std::size_t(rank_)].size();
  terms_offset_ = std::size_t(node_record_size(p));
  stride_ = terms_offset_ + std::size_t(load_terms_ ? node_power_term_count(*model_) : 0);
  const std::size_t slots = load_terms_ ? mine : 0;
  if (records_.size() == stride_ * nodes + slots) return;  // sized once, at the first cycle
  records_.assign(stride_ * nodes + slots, 0.0);
  record_counts_.assign(std::size_t(nranks_), 0);
  for (int q = 0; q < nranks_; ++q) {
    const std::size_t qs = load_terms_ ? rank_slots_[std::size_t(q)].size() : 0;
    record_counts_[std::size_t(q)] =
        leads() ? int((stride_ * rank_nodes_[std::size_t(q)].size() + qs) * sizeof(double)) : 0;
  }
  record_displs_ = displacements(record_counts_);
  if (leads()) {
    gathered_records_.assign(std::size_t(record_displs_.back() + record_counts_.back()) / sizeof(double), 0.0);
    all_records_.assign(stride_ * std::size_t(s.nn), 0.0);
  }
}

void DistributedCycle::node_pass(State& s, const NodePass& p) {
  size_node_records(s, p);
  update_velocities_for_listed_nodes(s, p, dom_.owned_nodes, records_.data(), stride_);
  if (p.update_positions) share_node_books(s, p);
}

void DistributedCycle::apply_walls(State& s, const NodePass& p) {
  apply_walls_to_listed_nodes(s, p, dom_.owned_nodes, records_.data(), stride_);
}

void DistributedCycle::finish_node_pass(State& s, const NodePass& p) {
  if (p.update_positions) throw std::logic_error("distributed node pass: the nodes moved already");
  update_positions_for_listed_nodes(s, p.dt_next, dom_.owned_nodes, records_.data(), stride_);
  share_node_books(s, p);
}

// The books of this rank's nodes (kinetic energy, walls, the external work's node terms) and
// its load terms to rank 0, which books them in the one-process order; then the ghosts.
void DistributedCycle::share_node_books(State& s, const NodePass& p) {
  const std::size_t nodes = dom_.owned_nodes.size();
  const std::vector<int>& my_slots = rank_slots_[std::size_t(rank_)];
  if (load_terms_) {
    if (stride_ > terms_offset_)
      for (std::size_t a = 0; a < nodes; ++a)
        compute_node_power_terms(*model_, s, *loads_, std::size_t(dom_.owned_nodes[a]),
                                 &records_[stride_ * a + terms_offset_]);
    compute_load_terms(*model_, s, *loads_, p.dt_n, &dom_.owns_node, terms_.data());
    double* out = records_.data() + stride_ * nodes;
    for (int j : my_slots) *out++ = terms_[std::size_t(j)];
  }
  const Timer t(comm_s_);
  gather(records_.data(), int(records_.size() * sizeof(double)), gathered_records_.data(), record_counts_.data(),
         record_displs_.data());
  if (leads()) {  // into node and slot order, then the one-process sums
    const double* in = gathered_records_.data();
    for (int q = 0; q < nranks_; ++q) {
      for (int n : rank_nodes_[std::size_t(q)]) {
        std::memcpy(&all_records_[stride_ * std::size_t(n)], in, stride_ * sizeof(double));
        in += stride_;
      }
      if (load_terms_)
        for (int j : rank_slots_[std::size_t(q)]) all_terms_[std::size_t(j)] = *in++;
    }
    book_node_records(s, p, all_records_.data(), stride_);
  }
  send_ghost_kinematics(s);
}

void DistributedCycle::book_external_work(State& s, double dt_n) {
  if (!leads()) return;
  book_external_work_from_terms(*model_, s, *loads_, dt_n, all_terms_.data(), all_records_.data() + terms_offset_,
                                stride_);
}

void DistributedCycle::gather_state(State& s) {
  const Timer t(gather_s_);
  Packer pk{state_buf_.data()};
  for (int n : dom_.owned_nodes) visit_node(s, std::size_t(n), pk);
  for (int b : dom_.owned_blocks) visit_block(s, std::size_t(b), pk);
  for (int k : dom_.owned_shells) visit_shell(s, std::size_t(k), shell_points_[std::size_t(k)], pk);
  for (int b : dom_.owned_beams) visit_beam(s, std::size_t(b), pk);
  for (int j : rank_motions_[std::size_t(rank_)]) pk(s.motion_angle[std::size_t(j)]);
  gather(state_buf_.data(), int(state_buf_.size() * sizeof(double)), state_all_.data(), state_bytes_.data(),
         state_displs_.data());
  if (!leads()) return;
  for (int q = 1; q < nranks_; ++q)
    unpack_rank_state(s, q, state_all_.data() + state_displs_[std::size_t(q)] / int(sizeof(double)));
}

void DistributedCycle::gather_velocities(State& s) {
  const Timer t(gather_s_);
  double* out = vel_buf_.data();
  for (int n : dom_.owned_nodes) {
    const std::size_t k = std::size_t(n);
    *out++ = s.vx_old[k], *out++ = s.vy_old[k], *out++ = s.vz_old[k];
    *out++ = s.vx[k], *out++ = s.vy[k], *out++ = s.vz[k];
  }
  gather(vel_buf_.data(), int(vel_buf_.size() * sizeof(double)), vel_all_.data(), vel_bytes_.data(),
         vel_displs_.data());
  if (!leads()) return;
  const double* in = vel_all_.data();
  for (int q = 0; q < nranks_; ++q)
    for (int n : rank_nodes_[std::size_t(q)]) {
      const std::size_t k = std::size_t(n);
      s.vx_old[k] = *in++, s.vy_old[k] = *in++, s.vz_old[k] = *in++;
      s.vx[k] = *in++, s.vy[k] = *in++, s.vz[k] = *in++;
    }
}

void DistributedCycle::unpack_rank_state(State& s, int q, const double* from) {
  Unpacker up{from};
  for (int n : rank_nodes_[std::size_t(q)]) visit_node(s, std::size_t(n), up);
  for (int b : rank_blocks_[std::size_t(q)]) visit_block(s, std::size_t(b), up);
  for (int k : rank_shells_[std::size_t(q)]) visit_shell(s, std::size_t(k), shell_points_[std::size_t(k)], up);
  for (int b : rank_beams_[std::size_t(q)]) visit_beam(s, std::size_t(b), up);
  for (int j : rank_motions_[std::size_t(q)]) up(s.motion_angle[std::size_t(j)]);
}

void DistributedCycle::resume(Engine& engine) {
  try {
    SlidingInterfaces::RestartData cd;
    read_restart_dump_state(restart_path_, engine.state(), cd);
    engine.contact().restore(cd);
  } catch (const std::exception& ex) {  // rank 0 read it: a file that changed under the run
    std::fprintf(stderr, "impact3d: rank %d: restart dump %s: %s\n", rank_, restart_path_.c_str(), ex.what());
    abort(exit_code::file_error);
  }
}

void DistributedCycle::announce(Op op, double land_time, int code) {
  Command c;
  c.op = int(op);
  c.code = code;
  c.land_time = land_time;
  const Timer t(comm_s_);
  broadcast(&c, sizeof c);
}

int DistributedCycle::follow(Engine& engine) {
  for (;;) {
    Command c;
    broadcast(&c, sizeof c);
    switch (Op(c.op)) {
      case Op::initialize:
        engine.initialize();
        break;
      case Op::step:
        engine.land_on(c.land_time);
        engine.step();
        break;
      case Op::gather:
        engine.gather_for_output();
        break;
      case Op::gather_velocities:
        engine.gather_velocities();
        break;
      case Op::resume:
        resume(engine);
        break;
      case Op::finish:
        return c.code;
      default:
        throw std::logic_error("distributed run: unknown command from rank 0");
    }
  }
}

}  // namespace impact3d::parallel
