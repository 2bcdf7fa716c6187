// The partition over MPI ranks and the ranks' domains (partition.h).
#include "impact3d/parallel/partition.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "impact3d/solve/beam_processing.h"
#include "impact3d/solve/shell_processing.h"

#if IMPACT3D_HAVE_MPI
#include <metis.h>
#endif

namespace impact3d::parallel {

namespace {

constexpr std::size_t kBlockCorners = 8 * kLanes;  // cfx entries of one block

std::size_t num_blocks(const State& s) { return s.slot_elem.size() / kLanes; }

// The units of work (partition.h): the solids' blocks, the shells' chunks, the beams' chunks.
std::size_t num_shell_units(const State& s) { return std::size_t(num_shell_chunks(s.shells)); }
std::size_t num_units(const State& s) {
  return num_blocks(s) + num_shell_units(s) + std::size_t(num_beam_chunks(s.beams));
}

// Corner c's unit: a solid corner's block, a shell corner's chunk (after the blocks), a beam
// end's chunk (after the shells').
struct CornerUnits {
  std::size_t solid_corners = 0, shell_base = 0, shell_end = 0, beam_base = 0, beam_end = 0, nb = 0, nsc = 0;
  std::vector<int> shell_chunk, beam_chunk;
  explicit CornerUnits(const State& s)
      : solid_corners(kBlockCorners * num_blocks(s)), shell_base(s.shells.corner_base),
        shell_end(s.shells.corner_base + 4 * std::size_t(s.shells.ns)), beam_base(s.beams.corner_base),
        beam_end(s.beams.corner_base + 2 * std::size_t(s.beams.nb)), nb(num_blocks(s)), nsc(num_shell_units(s)),
        shell_chunk(shell_chunk_of_shells(s.shells)), beam_chunk(beam_chunk_of_beams(s.beams)) {}
  int operator()(std::size_t c) const {
    if (c < solid_corners) return int(c / kBlockCorners);
    if (c >= shell_base && c < shell_end) return int(nb) + shell_chunk[(c - shell_base) / 4];
    if (c >= beam_base && c < beam_end) return int(nb + nsc) + beam_chunk[(c - beam_base) / 2];
    return -1;
  }
};

// The units around node n, increasing, into out.
void node_units(const State& s, const CornerUnits& cu, std::size_t n, std::vector<int>& out) {
  out.clear();
  for (int c = s.corner_start[n]; c < s.corner_start[n + 1]; ++c)
    if (const int u = cu(std::size_t(s.corner_list[std::size_t(c)])); u >= 0) out.push_back(u);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// The ranks of the units around node n, increasing, into out.
void node_ranks(const State& s, const CornerUnits& cu, const std::vector<int>& unit_rank, std::size_t n,
                std::vector<int>& out) {
  node_units(s, cu, n, out);
  for (int& u : out) u = unit_rank[std::size_t(u)];
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// The solids' corners around node n (its corner list without shell or beam corners): the
// corners whose forces the neighbour exchange carries (the shells' go to every rank).
template <class F>
void for_solid_corners(const State& s, std::size_t n, F&& f) {
  const std::size_t solid_corners = kBlockCorners * num_blocks(s);
  for (int c = s.corner_start[n]; c < s.corner_start[n + 1]; ++c) {
    const std::size_t cc = std::size_t(s.corner_list[std::size_t(c)]);
    if (cc < solid_corners) f(cc);
  }
}

// Each node's units, increasing (CSR).
void node_unit_lists(const State& s, std::vector<int>& start, std::vector<int>& list) {
  const CornerUnits cu(s);
  start.assign(std::size_t(s.nn) + 1, 0);
  list.clear();
  std::vector<int> mine;
  for (std::size_t n = 0; n < std::size_t(s.nn); ++n) {
    node_units(s, cu, n, mine);
    list.insert(list.end(), mine.begin(), mine.end());
    start[n + 1] = int(list.size());
  }
}

// The elements of each chunk, from each element's chunk.
std::vector<std::vector<int>> by_chunk(const std::vector<int>& chunk_of, int nchunks) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(nchunks));
  for (std::size_t k = 0; k < chunk_of.size(); ++k) out[std::size_t(chunk_of[k])].push_back(int(k));
  return out;
}
std::vector<std::vector<int>> shells_by_chunk(const State& s) {
  return by_chunk(shell_chunk_of_shells(s.shells), num_shell_chunks(s.shells));
}
std::vector<std::vector<int>> beams_by_chunk(const State& s) {
  return by_chunk(beam_chunk_of_beams(s.beams), num_beam_chunks(s.beams));
}

// The nodes of unit u (with repeats; a beam's two ends, not its orientation node).
template <class F>
void for_unit_nodes(const State& s, const std::vector<std::vector<int>>& chunk_shells,
                    const std::vector<std::vector<int>>& chunk_beams, std::size_t u, F&& f) {
  const std::size_t nb = num_blocks(s), nsc = chunk_shells.size();
  if (u < nb) {
    for (int l = 0; l < kLanes; ++l)
      if (const int e = s.slot_elem[u * kLanes + std::size_t(l)]; e >= 0)
        for (int n : s.conn[std::size_t(e)]) f(n);
    return;
  }
  if (u < nb + nsc) {
    for (int k : chunk_shells[u - nb])
      for (int n : s.shells.conn[std::size_t(k)]) f(n);
    return;
  }
  for (int b : chunk_beams[u - nb - nsc])
    for (int j = 0; j < 2; ++j) f(s.beams.conn[std::size_t(b)][std::size_t(j)]);
}

}  // namespace

int group_cost_per_solid(const ElementGroup& g) { return g.formulation == 2 ? 6 : 1; }

BlockGraph block_graph(const State& s) {
  const std::size_t nb = num_blocks(s), nu = num_units(s);
  std::vector<int> nstart, nlist;
  node_unit_lists(s, nstart, nlist);
  const std::vector<std::vector<int>> chunk_shells = shells_by_chunk(s), chunk_beams = beams_by_chunk(s);
  BlockGraph g;
  g.xadj.assign(nu + 1, 0);
  g.vwgt.assign(nu, 0);
  for (const ElementGroup& grp : s.groups)
    for (int b = grp.first_block; b < grp.first_block + grp.num_blocks; ++b)
      for (int l = 0; l < kLanes; ++l)
        if (s.slot_elem[std::size_t(b) * kLanes + std::size_t(l)] >= 0) g.vwgt[std::size_t(b)] += group_cost_per_solid(grp);
  for (std::size_t c = 0; c < chunk_shells.size(); ++c) g.vwgt[nb + c] = kShellCost * int(chunk_shells[c].size());
  for (std::size_t c = 0; c < chunk_beams.size(); ++c)
    g.vwgt[nb + chunk_shells.size() + c] = kBeamCost * int(chunk_beams[c].size());
  std::vector<int> shared(nu, 0), node_seen(std::size_t(s.nn), -1), touched;
  for (std::size_t u = 0; u < nu; ++u) {
    touched.clear();
    for_unit_nodes(s, chunk_shells, chunk_beams, u, [&](int n) {
      if (node_seen[std::size_t(n)] == int(u)) return;  // each node once per unit
      node_seen[std::size_t(n)] = int(u);
      for (int k = nstart[std::size_t(n)]; k < nstart[std::size_t(n) + 1]; ++k) {
        const int u2 = nlist[std::size_t(k)];
        if (u2 == int(u)) continue;
        if (shared[std::size_t(u2)]++ == 0) touched.push_back(u2);
      }
    });
    std::sort(touched.begin(), touched.end());
    for (int u2 : touched) {
      g.adjncy.push_back(u2);
      g.adjwgt.push_back(shared[std::size_t(u2)]);
      shared[std::size_t(u2)] = 0;
    }
    g.xadj[u + 1] = int(g.adjncy.size());
  }
  return g;
}

std::vector<int> partition_blocks(const BlockGraph& g, int nparts) {
  const int nv = int(g.vwgt.size());
  if (nparts < 1) throw std::runtime_error("partition: the number of parts must be at least 1");
  if (nparts == 1) return std::vector<int>(std::size_t(nv), 0);
  if (nv < nparts)
    throw std::runtime_error("partition: " + std::to_string(nv) + " blocks of solids, shells and beams cannot fill " +
                             std::to_string(nparts) + " ranks");
#if IMPACT3D_HAVE_MPI
  static_assert(sizeof(idx_t) == sizeof(int), "METIS built with 64-bit indices");
  std::vector<int> part(std::size_t(nv), 0);
  idx_t n = nv, ncon = 1, np = nparts, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_NUMBERING] = 0;
  const int rc = METIS_PartGraphKway(&n, &ncon, const_cast<int*>(g.xadj.data()), const_cast<int*>(g.adjncy.data()),
                                     const_cast<int*>(g.vwgt.data()), nullptr, const_cast<int*>(g.adjwgt.data()), &np,
                                     nullptr, nullptr, options, &cut, part.data());
  if (rc != METIS_OK) throw std::runtime_error("partition: METIS_PartGraphKway failed (" + std::to_string(rc) + ")");
  return part;
#else
  throw std::runtime_error("partition: this build has no METIS (CMake option IMPACT3D_MPI)");
#endif
}

Domain build_domain(const State& s, const std::vector<int>& block_rank, int nranks, int rank,
                    const std::vector<std::vector<int>>& together) {
  const std::size_t nb = num_blocks(s), nsc = num_shell_units(s), nu = num_units(s);
  if (block_rank.size() != nu) throw std::logic_error("build_domain: one rank per block and chunk expected");
  Domain d;
  d.rank = rank;
  d.nranks = nranks;
  d.block_rank = block_rank;
  d.owns_block.assign(nb, 0);
  d.owns_chunk.assign(nsc, 0);
  d.owns_beam_chunk.assign(nu - nb - nsc, 0);
  for (std::size_t b = 0; b < nb; ++b)
    if (block_rank[b] == rank) {
      d.owns_block[b] = 1;
      d.owned_blocks.push_back(int(b));
      for (int l = 0; l < kLanes; ++l)
        if (const int e = s.slot_elem[b * kLanes + std::size_t(l)]; e >= 0) d.owned_elems.push_back(e);
    }
  std::sort(d.owned_elems.begin(), d.owned_elems.end());
  const std::vector<std::vector<int>> chunk_shells = shells_by_chunk(s);
  for (std::size_t c = 0; c < nsc; ++c)
    if (block_rank[nb + c] == rank) {
      d.owns_chunk[c] = 1;
      d.owned_chunks.push_back(int(c));
      d.owned_shells.insert(d.owned_shells.end(), chunk_shells[c].begin(), chunk_shells[c].end());
    }
  const std::vector<std::vector<int>> chunk_beams = beams_by_chunk(s);
  for (std::size_t c = 0; c < nu - nb - nsc; ++c)
    if (block_rank[nb + nsc + c] == rank) {
      d.owns_beam_chunk[c] = 1;
      d.owned_beams.insert(d.owned_beams.end(), chunk_beams[c].begin(), chunk_beams[c].end());
    }
  const CornerUnits cu(s);
  d.node_rank.assign(std::size_t(s.nn), 0);
  d.owns_node.assign(std::size_t(s.nn), 0);
  std::vector<int> ranks_here;
  for (std::size_t n = 0; n < std::size_t(s.nn); ++n) {  // the owners: the lowest rank of the elements around
    node_ranks(s, cu, block_rank, n, ranks_here);
    d.node_rank[n] = ranks_here.empty() ? 0 : ranks_here.front();
  }
  std::vector<std::vector<int>> also(together.empty() ? 0 : std::size_t(s.nn));  // ranks that need a node
  for (const std::vector<int>& g : together)
    for (int n : g)
      for (int n2 : g) also[std::size_t(n2)].push_back(d.node_rank[std::size_t(n)]);
  std::vector<Peer> by_rank(static_cast<std::size_t>(nranks));
  for (std::size_t n = 0; n < std::size_t(s.nn); ++n) {
    node_ranks(s, cu, block_rank, n, ranks_here);
    const int owner = d.node_rank[n];
    if (!also.empty() && !also[n].empty()) {
      ranks_here.insert(ranks_here.end(), also[n].begin(), also[n].end());
      std::sort(ranks_here.begin(), ranks_here.end());
      ranks_here.erase(std::unique(ranks_here.begin(), ranks_here.end()), ranks_here.end());
    }
    const bool touched_here = std::binary_search(ranks_here.begin(), ranks_here.end(), rank);
    if (owner == rank) {
      d.owned_nodes.push_back(int(n));
      d.owns_node[n] = 1;
      for (int q : ranks_here)
        if (q != rank) by_rank[std::size_t(q)].send_nodes.push_back(int(n));
      for_solid_corners(s, n, [&](std::size_t c) {
        const int q = block_rank[c / kBlockCorners];
        if (q != rank) by_rank[std::size_t(q)].recv_corners.push_back(int(c));
      });
    } else if (touched_here) {
      d.ghost_nodes.push_back(int(n));
      by_rank[std::size_t(owner)].recv_nodes.push_back(int(n));
      for_solid_corners(s, n, [&](std::size_t c) {
        if (block_rank[c / kBlockCorners] == rank) by_rank[std::size_t(owner)].send_corners.push_back(int(c));
      });
    }
  }
  for (int q = 0; q < nranks; ++q) {
    Peer& p = by_rank[std::size_t(q)];
    if (p.send_corners.empty() && p.recv_corners.empty() && p.send_nodes.empty() && p.recv_nodes.empty()) continue;
    p.rank = q;
    std::sort(p.send_corners.begin(), p.send_corners.end());
    std::sort(p.recv_corners.begin(), p.recv_corners.end());
    d.peers.push_back(std::move(p));
  }
  return d;
}

PartitionSummary summarize_partition(const State& s, const BlockGraph& g, const std::vector<int>& block_rank,
                                     int nranks) {
  PartitionSummary p;
  const std::size_t R = std::size_t(nranks), nb = num_blocks(s);
  p.solids.assign(R, 0);
  p.shells.assign(R, 0);
  p.beams.assign(R, 0);
  p.blocks.assign(R, 0);
  p.owned_nodes.assign(R, 0);
  p.shared_nodes.assign(R, 0);
  p.weight.assign(R, 0);
  const std::vector<std::vector<int>> chunk_shells = shells_by_chunk(s), chunk_beams = beams_by_chunk(s);
  const std::size_t nsc = chunk_shells.size();
  for (std::size_t b = 0; b < block_rank.size(); ++b) {
    const std::size_t r = std::size_t(block_rank[b]);
    ++p.blocks[r];
    p.weight[r] += g.vwgt[b];
    if (b >= nb + nsc) {
      p.beams[r] += int(chunk_beams[b - nb - nsc].size());
      continue;
    }
    if (b >= nb) {
      p.shells[r] += int(chunk_shells[b - nb].size());
      continue;
    }
    for (int l = 0; l < kLanes; ++l)
      if (s.slot_elem[b * kLanes + std::size_t(l)] >= 0) ++p.solids[r];
  }
  const CornerUnits cu(s);
  std::vector<int> ranks_here;
  for (std::size_t n = 0; n < std::size_t(s.nn); ++n) {
    node_ranks(s, cu, block_rank, n, ranks_here);
    ++p.owned_nodes[ranks_here.empty() ? 0 : std::size_t(ranks_here.front())];
    if (ranks_here.size() > 1)
      for (int q : ranks_here) ++p.shared_nodes[std::size_t(q)];
  }
  long total = 0, most = 0;
  for (long w : p.weight) total += w, most = std::max(most, w);
  p.imbalance = total > 0 ? double(most) * double(nranks) / double(total) : 1.0;
  return p;
}

std::string partition_report(const PartitionSummary& p) {
  const std::size_t R = p.solids.size();
  std::string out = " distributed run: " + std::to_string(R) +
                    " MPI ranks, the blocks of solids, shells and beams partitioned by METIS k-way (seed 1)\n"
                    "   rank     solids     shells      beams     blocks   nodes owned   shared nodes\n";
  char buf[160];
  for (std::size_t r = 0; r < R; ++r) {
    std::snprintf(buf, sizeof buf, " %6zu %10d %10d %10d %10d %13d %14d\n", r, p.solids[r], p.shells[r], p.beams[r],
                  p.blocks[r], p.owned_nodes[r], p.shared_nodes[r]);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "   imbalance (largest rank weight / mean) %.4f", p.imbalance);
  return out + buf;
}

}  // namespace impact3d::parallel
