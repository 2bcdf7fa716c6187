// The partition over MPI ranks and the ranks' domains (impact3d/parallel/partition.h): every
// solid, shell, beam and node owned once, the exchange lists of two neighbours the same on both
// sides, the same partition run after run.  These run in any build; the METIS partitions are
// skipped (with the reason) in a build without MPI and METIS.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "common/messages.h"
#include "impact3d/init/initialize.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/parallel/comm.h"
#include "impact3d/parallel/partition.h"
#include "impact3d/solve/beam_processing.h"
#include "impact3d/solve/shell_processing.h"

using namespace impact3d;
using namespace impact3d::parallel;

namespace {

struct Loaded {
  Model model;
  State state;
};

const Loaded& deck(const std::string& name) {
  static std::map<std::string, Loaded> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Loaded& l = cache[name];
  Diagnostics d;
  EXPECT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/" + name, l.model, d));
  initialize_state(l.model, l.state);
  return l;
}

// Units (solid blocks, shell chunks, beam chunks) in runs of `run` per rank, round robin: a partition
// without METIS that still has many shared nodes.
std::vector<int> striped(const State& s, int nranks, int run) {
  std::vector<int> r(s.slot_elem.size() / kLanes + std::size_t(num_shell_chunks(s.shells)) +
                     std::size_t(num_beam_chunks(s.beams)));
  for (std::size_t b = 0; b < r.size(); ++b) r[b] = int(b / std::size_t(run)) % nranks;
  return r;
}

// The checks every partition passes.
void check_domains(const State& s, const std::vector<int>& block_rank, int nranks) {
  std::vector<Domain> d;
  for (int r = 0; r < nranks; ++r) d.push_back(build_domain(s, block_rank, nranks, r));
  // every solid owned once, by the rank of its block
  std::vector<int> elem_owner(std::size_t(s.ne), -1);
  for (const Domain& dr : d)
    for (int e : dr.owned_elems) {
      ASSERT_EQ(elem_owner[std::size_t(e)], -1) << "solid " << e << " owned twice";
      elem_owner[std::size_t(e)] = dr.rank;
      EXPECT_EQ(block_rank[std::size_t(s.elem_slot[std::size_t(e)]) / kLanes], dr.rank);
    }
  for (int e = 0; e < s.ne; ++e) EXPECT_GE(elem_owner[std::size_t(e)], 0) << "solid " << e << " owned by none";
  // every shell owned once, by the rank of its chunk
  const std::size_t nb = s.slot_elem.size() / kLanes;
  const std::vector<int> chunk = shell_chunk_of_shells(s.shells);
  std::vector<int> shell_owner(std::size_t(s.shells.ns), -1);
  for (const Domain& dr : d)
    for (int k : dr.owned_shells) {
      ASSERT_EQ(shell_owner[std::size_t(k)], -1) << "shell " << k << " owned twice";
      shell_owner[std::size_t(k)] = dr.rank;
      EXPECT_EQ(block_rank[nb + std::size_t(chunk[std::size_t(k)])], dr.rank);
    }
  for (int k = 0; k < s.shells.ns; ++k) EXPECT_GE(shell_owner[std::size_t(k)], 0) << "shell " << k << " owned by none";
  // every beam owned once, by the rank of its chunk (after the shells' chunks)
  const std::size_t nsc = std::size_t(num_shell_chunks(s.shells));
  const std::vector<int> beam_chunk = beam_chunk_of_beams(s.beams);
  std::vector<int> beam_owner(std::size_t(s.beams.nb), -1);
  for (const Domain& dr : d)
    for (int b : dr.owned_beams) {
      ASSERT_EQ(beam_owner[std::size_t(b)], -1) << "beam " << b << " owned twice";
      beam_owner[std::size_t(b)] = dr.rank;
      EXPECT_EQ(block_rank[nb + nsc + std::size_t(beam_chunk[std::size_t(b)])], dr.rank);
    }
  for (int b = 0; b < s.beams.nb; ++b) EXPECT_GE(beam_owner[std::size_t(b)], 0) << "beam " << b << " owned by none";
  // every node owned once, by the lowest rank of the solids and shells around it
  std::vector<int> node_owner(std::size_t(s.nn), -1);
  for (const Domain& dr : d) {
    EXPECT_TRUE(std::is_sorted(dr.owned_nodes.begin(), dr.owned_nodes.end()));
    for (int n : dr.owned_nodes) {
      ASSERT_EQ(node_owner[std::size_t(n)], -1) << "node " << n << " owned twice";
      node_owner[std::size_t(n)] = dr.rank;
    }
  }
  std::vector<int> lowest(std::size_t(s.nn), nranks);
  for (int e = 0; e < s.ne; ++e)
    for (int n : s.conn[std::size_t(e)])
      lowest[std::size_t(n)] = std::min(lowest[std::size_t(n)], elem_owner[std::size_t(e)]);
  for (int k = 0; k < s.shells.ns; ++k)
    for (int n : s.shells.conn[std::size_t(k)])
      lowest[std::size_t(n)] = std::min(lowest[std::size_t(n)], shell_owner[std::size_t(k)]);
  for (int b = 0; b < s.beams.nb; ++b)  // a beam's two ends (its orientation node is not its node)
    for (int j = 0; j < 2; ++j) {
      const int n = s.beams.conn[std::size_t(b)][std::size_t(j)];
      lowest[std::size_t(n)] = std::min(lowest[std::size_t(n)], beam_owner[std::size_t(b)]);
    }
  for (int n = 0; n < s.nn; ++n)
    EXPECT_EQ(node_owner[std::size_t(n)], lowest[std::size_t(n)] == nranks ? 0 : lowest[std::size_t(n)]);
  for (const Domain& dr : d) {
    // ghosts: the nodes of the rank's solids and shells that another rank owns
    std::set<int> ghosts;
    for (int e : dr.owned_elems)
      for (int n : s.conn[std::size_t(e)])
        if (node_owner[std::size_t(n)] != dr.rank) ghosts.insert(n);
    for (int k : dr.owned_shells)
      for (int n : s.shells.conn[std::size_t(k)])
        if (node_owner[std::size_t(n)] != dr.rank) ghosts.insert(n);
    for (int b : dr.owned_beams)
      for (int j = 0; j < 2; ++j)
        if (const int n = s.beams.conn[std::size_t(b)][std::size_t(j)]; node_owner[std::size_t(n)] != dr.rank) ghosts.insert(n);
    EXPECT_EQ(std::vector<int>(ghosts.begin(), ghosts.end()), dr.ghost_nodes);
    std::set<int> received;
    for (const Peer& p : dr.peers) {
      ASSERT_NE(p.rank, dr.rank);
      const Domain& dq = d[std::size_t(p.rank)];
      auto other = std::find_if(dq.peers.begin(), dq.peers.end(), [&](const Peer& x) { return x.rank == dr.rank; });
      ASSERT_NE(other, dq.peers.end()) << "rank " << p.rank << " does not list rank " << dr.rank;
      // what one sends the other receives, in the same order
      EXPECT_EQ(p.send_corners, other->recv_corners);
      EXPECT_EQ(p.send_nodes, other->recv_nodes);
      EXPECT_TRUE(std::is_sorted(p.recv_corners.begin(), p.recv_corners.end()));
      for (int c : p.send_corners) {  // a corner of this rank's solid at a node the peer owns
        const int e = s.corner_element(std::size_t(c));
        ASSERT_GE(e, 0);
        EXPECT_EQ(elem_owner[std::size_t(e)], dr.rank);
        const int j = (c % (8 * kLanes)) / kLanes;
        EXPECT_EQ(node_owner[std::size_t(s.conn[std::size_t(e)][std::size_t(j)])], p.rank);
      }
      for (int n : p.recv_nodes) {
        EXPECT_EQ(node_owner[std::size_t(n)], p.rank);
        received.insert(n);
      }
    }
    EXPECT_EQ(std::vector<int>(received.begin(), received.end()), dr.ghost_nodes);
    // every solid corner at an owned node is the rank's own or received (the shells' corners
    // go to every rank)
    for (int n : dr.owned_nodes)
      for (int c = s.corner_start[std::size_t(n)]; c < s.corner_start[std::size_t(n) + 1]; ++c) {
        const int cc = s.corner_list[std::size_t(c)];
        if (s.corner_element(std::size_t(cc)) < 0) continue;
        const int owner = elem_owner[std::size_t(s.corner_element(std::size_t(cc)))];
        if (owner == dr.rank) continue;
        const Peer* p = nullptr;
        for (const Peer& x : dr.peers)
          if (x.rank == owner) p = &x;
        ASSERT_NE(p, nullptr);
        EXPECT_TRUE(std::binary_search(p->recv_corners.begin(), p->recv_corners.end(), cc));
      }
  }
}

}  // namespace

TEST(Partition, BlockGraphIsSymmetricWithSolidWeights) {
  const State& s = deck("taylor_bar.dyn").state;
  const BlockGraph g = block_graph(s);
  const std::size_t nb = s.slot_elem.size() / kLanes;
  ASSERT_EQ(g.vwgt.size(), nb);
  long solids = 0;
  for (int w : g.vwgt) solids += w;
  EXPECT_EQ(solids, s.ne);  // one-point solids: weight 1 each
  for (std::size_t b = 0; b < nb; ++b)
    for (int k = g.xadj[b]; k < g.xadj[b + 1]; ++k) {
      const int b2 = g.adjncy[std::size_t(k)];
      EXPECT_NE(b2, int(b));
      bool back = false;
      for (int k2 = g.xadj[std::size_t(b2)]; k2 < g.xadj[std::size_t(b2) + 1]; ++k2)
        if (g.adjncy[std::size_t(k2)] == int(b)) back = g.adjwgt[std::size_t(k2)] == g.adjwgt[std::size_t(k)];
      EXPECT_TRUE(back) << "edge " << b << "-" << b2 << " not mirrored with its weight";
    }
}

TEST(Partition, DomainsOfStripedBlocksAreConsistent) {
  for (const char* name : {"taylor_bar.dyn", "two_bars.dyn", "../tests/parallel/shell_tube.k",
                           "../tests/parallel/shell_tube_beams.k"}) {
    const State& s = deck(name).state;
    for (int nranks : {1, 2, 3, 4}) {
      SCOPED_TRACE(std::string(name) + " on " + std::to_string(nranks) + " ranks");
      check_domains(s, striped(s, nranks, 3), nranks);
    }
  }
}

TEST(Partition, ShellChunksAreVerticesAfterTheBlocks) {
  const State& s = deck("../tests/parallel/shell_tube.k").state;
  const BlockGraph g = block_graph(s);
  const std::size_t nb = s.slot_elem.size() / kLanes, nc = std::size_t(num_shell_chunks(s.shells));
  ASSERT_EQ(nb, 3u);   // the collar's 24 solids
  ASSERT_EQ(nc, 48u);  // 144, 144 and 96 shells in three groups, 8 a chunk
  ASSERT_EQ(g.vwgt.size(), nb + nc);
  for (std::size_t c = 0; c < nc; ++c) EXPECT_EQ(g.vwgt[nb + c], kShellCost * kLanes);
  // the collar's blocks touch the first rows' shell chunks (nodes shared by solids and shells)
  bool solid_shell_edge = false;
  for (int k = g.xadj[0]; k < g.xadj[1]; ++k) solid_shell_edge = solid_shell_edge || g.adjncy[std::size_t(k)] >= int(nb);
  EXPECT_TRUE(solid_shell_edge);
}

TEST(Partition, OneRankOwnsEverythingAndExchangesNothing) {
  const State& s = deck("taylor_bar.dyn").state;
  const Domain d = build_domain(s, std::vector<int>(s.slot_elem.size() / kLanes, 0), 1, 0);
  EXPECT_EQ(int(d.owned_elems.size()), s.ne);
  EXPECT_EQ(int(d.owned_nodes.size()), s.nn);
  EXPECT_TRUE(d.ghost_nodes.empty());
  EXPECT_TRUE(d.peers.empty());
}

TEST(Partition, MetisKwayIsConsistentBalancedAndRepeatable) {
  if (!built_with_mpi()) GTEST_SKIP() << "this build has no MPI and METIS (CMake option IMPACT3D_MPI off)";
  for (const char* name : {"taylor_bar.dyn", "two_bars.dyn", "../tests/parallel/shell_tube.k",
                           "../tests/parallel/shell_tube_beams.k"}) {
    const State& s = deck(name).state;
    const BlockGraph g = block_graph(s);
    for (int nranks : {2, 3, 4}) {
      SCOPED_TRACE(std::string(name) + " on " + std::to_string(nranks) + " ranks");
      const std::vector<int> part = partition_blocks(g, nranks);
      EXPECT_EQ(part, partition_blocks(block_graph(s), nranks)) << "not the same partition run after run";
      for (int r = 0; r < nranks; ++r) EXPECT_NE(std::count(part.begin(), part.end(), r), 0) << "rank " << r << " empty";
      check_domains(s, part, nranks);
      const PartitionSummary p = summarize_partition(s, g, part, nranks);
      EXPECT_LT(p.imbalance, 1.1);  // METIS's default tolerance is 1.03 on the weights
      long solids = 0, shells = 0, beams = 0;
      for (int n : p.solids) solids += n;
      for (int n : p.shells) shells += n;
      for (int n : p.beams) beams += n;
      EXPECT_EQ(solids, s.ne);
      EXPECT_EQ(shells, s.shells.ns);
      EXPECT_EQ(beams, s.beams.nb);
    }
  }
}

TEST(Partition, MoreRanksThanBlocksIsRefused) {
  const State& s = deck("taylor_bar.dyn").state;
  const BlockGraph g = block_graph(s);
  EXPECT_THROW(partition_blocks(g, int(g.vwgt.size()) + 1), std::runtime_error);
}
