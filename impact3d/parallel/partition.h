#pragma once
// The partition of a model over MPI ranks and each rank's domain (docs/cluster.md).
//
// The units of ownership are the element pass's blocks: the solids' blocks (kLanes solids of
// one group, State::slot_elem), then the shells' chunks (kLanes shells of one group's order,
// shell_processing.h: num_shell_chunks), then the beams' chunks (beam_processing.h), numbered
// in that order.  A rank computes whole
// units, so each block's energy sums (BlockResult, summed over its lanes in lane order) and
// each shell's and beam's results are the same numbers on any rank count, and the reductions over them in
// the one-process order give the same bits as one process.  METIS k-way partitions the element
// graph coarsened to units: one vertex per unit, weighted by its elements times their cost per
// element; an edge between units whose elements share nodes, weighted by the nodes they share.
// Fixed options and seed: the same partition run after run.
//
// A node belongs to the lowest rank among the units of the elements around it (rank 0 for a
// node of no element).  A rank's domain: its units and their elements, its nodes, its ghost
// nodes (nodes of its elements that another rank owns), and per neighbour rank the lists of
// the two exchanges of a cycle, each in increasing order, built alike on both sides:
//  - corner forces: the corners (cfx index, State::corner_index) of this rank's solids at
//    nodes the neighbour owns (sent), and of the neighbour's solids at nodes this rank owns
//    (received); the shells' and beams' corner forces and moments go to every rank instead
//    (distributed_cycle.h);
//  - kinematics: this rank's nodes that are the neighbour's ghosts (sent), the neighbour's
//    nodes that are this rank's ghosts (received).

#include <cstdint>
#include <string>
#include <vector>

#include "impact3d/model/state.h"

namespace impact3d::parallel {

// The unit graph in METIS's CSR form (the solids' blocks, the shells' chunks, the beams' chunks).
struct BlockGraph {
  std::vector<int> xadj, adjncy, adjwgt;  // neighbours of unit b: adjncy[xadj[b] .. xadj[b+1])
  std::vector<int> vwgt;                  // elements of the unit x their cost per element
};

// A group's relative cost per solid (the vertex weights): 1 for the one-point hexahedron, 6 for
// the fully integrated one (eight points' stress updates, scalar; an estimate, not a measurement).
int group_cost_per_solid(const ElementGroup& g);
// A shell's cost in the same measure: 2 (an estimate, not a measurement).
constexpr int kShellCost = 2;
// A beam's: 1 (an estimate).
constexpr int kBeamCost = 1;

BlockGraph block_graph(const State& s);

// Rank of each unit: METIS k-way (METIS_PartGraphKway, seed 1, default options otherwise).
// nparts 1: all blocks on rank 0.  Throws std::runtime_error where the build has no METIS, or
// with fewer blocks than parts.
std::vector<int> partition_blocks(const BlockGraph& g, int nparts);

struct Peer {
  int rank = -1;
  std::vector<int> send_corners, recv_corners;  // corner indices into cfx/cfy/cfz, increasing
  std::vector<int> send_nodes, recv_nodes;      // node indices, increasing
};

struct Domain {
  int rank = 0, nranks = 1;
  std::vector<int> block_rank;        // every unit's rank: the solids' blocks, the shells' chunks, the beams' chunks
  std::vector<int> node_rank;         // every node's owner
  std::vector<std::uint8_t> owns_block;  // per solid block: this rank computes it
  std::vector<std::uint8_t> owns_chunk;  // per shell chunk: this rank computes it
  std::vector<std::uint8_t> owns_beam_chunk;  // per beam chunk: this rank computes it
  std::vector<int> owned_blocks, owned_elems, owned_nodes, ghost_nodes;  // increasing
  std::vector<std::uint8_t> owns_node;  // per node: 1 for this rank's own nodes
  std::vector<int> owned_chunks;      // increasing
  std::vector<int> owned_shells;      // the owned chunks' shells, chunk after chunk
  std::vector<int> owned_beams;       // the owned beam chunks' beams, chunk after chunk
  std::vector<Peer> peers;            // the neighbour ranks, increasing
};

// Rank `rank`'s domain for the given unit ranks.  `together`: groups of nodes (a pressure
// face's corners) whose owners each need all of the group's nodes: a rank that owns one of them
// has the group's other nodes as ghosts (the owners stay those of the elements' rule).
Domain build_domain(const State& s, const std::vector<int>& block_rank, int nranks, int rank,
                    const std::vector<std::vector<int>>& together = {});

// What d3hsp states about a partition: per rank its solids, shells, beams, units ("blocks"), nodes
// owned and shared nodes (nodes of its elements that elements of another rank also use), and
// the imbalance (the largest rank weight over the mean).
struct PartitionSummary {
  std::vector<int> solids, shells, beams, blocks, owned_nodes, shared_nodes;
  std::vector<long> weight;
  double imbalance = 1;
};
PartitionSummary summarize_partition(const State& s, const BlockGraph& g, const std::vector<int>& block_rank,
                                     int nranks);
std::string partition_report(const PartitionSummary& p);

}  // namespace impact3d::parallel
