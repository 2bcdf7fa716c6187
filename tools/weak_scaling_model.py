#!/usr/bin/env python3
"""Weak-scaling model of IMPACT-3D's distributed cycle (issue 26; docs/cluster.md, "A weak-scaling
model").  Prints, for a model of N hexahedra on a cluster, the time of one cycle per part:
element work, the neighbour exchanges, and the global exchanges as they are today and as an
exact reduction would make them.

The message sizes are the code's (impact3d/parallel/distributed_cycle.cpp, state.h): a block
result is 72 bytes (7 doubles, 4 ints) per block of 8 solids and goes to every rank; a node
record is 8 bytes per node (its kinetic energy; 40 more per fixed wall) and goes to rank 0; a
corner force is 24 bytes, a ghost node's position and velocity 48; the command 16 bytes.
Everything else (machine and network) is an assumption, listed below with its value: change
them on the command line.

    tools/weak_scaling_model.py                 # 10^8 solids on 64 nodes (the issue's case)
    tools/weak_scaling_model.py --elements 1e6 --nodes 1 --ranks-per-node 2
"""
import argparse
import math


def parse():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--elements", type=float, default=1e8, help="hexahedra in the model (default 1e8)")
    a.add_argument("--nodes", type=int, default=64, help="cluster nodes (default 64)")
    a.add_argument("--cores", type=int, default=32, help="cores per node (assumed: 32)")
    a.add_argument("--ranks-per-node", type=int, nargs="*", default=[1, 32],
                   help="ranks per node to model (threads = cores / ranks); default 1 and 32")
    a.add_argument("--ns-core", type=float, default=150.0,
                   help="ns per solid-cycle of one core alone (measured here at 1e6 solids: 138-174)")
    a.add_argument("--node-speedup", type=float, default=16.0,
                   help="speed-up of all cores of a node over one (memory-bound: assumed 16 of 32)")
    a.add_argument("--bandwidth", type=float, default=12.5e9, help="bytes/s per node (assumed 100 Gb/s InfiniBand)")
    a.add_argument("--latency", type=float, default=1.5e-6, help="s per message (assumed 1.5 us)")
    a.add_argument("--neighbours", type=int, default=14, help="neighbour ranks of a subdomain (assumed 14)")
    a.add_argument("--reduction-bytes", type=int, default=1024,
                   help="bytes of one exact reduction of the step and energy books (assumed 1 KiB)")
    return a.parse_args()


def cycle_parts(o, ranks_per_node):
    P = o.nodes * ranks_per_node
    n = o.elements / P                                   # solids per rank
    side = n ** (1.0 / 3.0)                              # a cube-shaped subdomain
    shared = 6.0 * side * side                           # its nodes on faces shared with a neighbour
    threads = o.cores // ranks_per_node
    speedup = o.node_speedup * threads / o.cores         # a rank's share of its node's speed-up
    t_elem = n * o.ns_core * 1e-9 / speedup
    bw_rank = o.bandwidth / ranks_per_node               # the node's link shared by its ranks
    # neighbour exchanges: corners of the half of the shared nodes the neighbours own (4 solids
    # each on this side), ghosts of the half this rank owns
    halo_bytes = shared / 2 * 4 * 24 + shared / 2 * 48
    t_halo = halo_bytes / bw_rank + 2 * o.neighbours * o.latency
    tree = math.ceil(math.log2(P)) * o.latency if P > 1 else 0.0
    t_command = tree
    blocks = o.elements / 8
    t_blocks = blocks * 72 * (P - 1) / P / bw_rank + tree      # allgather: every block to every rank
    t_records = o.elements * 8 / o.bandwidth + tree            # every node's record into rank 0
    t_exact = 2 * tree + 2 * o.reduction_bytes / bw_rank       # allreduce of the books instead
    if P == 1:  # one process: no messages at all
        halo_bytes = t_halo = t_blocks = t_records = t_exact = 0.0
    return dict(P=P, n=n, threads=threads, t_elem=t_elem, halo_bytes=halo_bytes, t_halo=t_halo,
                t_command=t_command, t_blocks=t_blocks, t_records=t_records, t_exact=t_exact)


def ms(x):
    return f"{1e3 * x:.3g} ms"


def main():
    o = parse()
    print(f"Model: {o.elements:.3g} hexahedra on {o.nodes} nodes of {o.cores} cores; one core {o.ns_core:g} ns per "
          f"solid-cycle, a node {o.node_speedup:g} x one core; {o.bandwidth / 1e9:g} GB/s and {1e6 * o.latency:g} us per "
          f"message; {o.neighbours} neighbours per subdomain.\n")
    print("| ranks (threads each) | solids per rank | element work | neighbour exchanges (bytes per rank) | command "
          "| block results, allgather (today) | node records to rank 0 (today) | cycle today, efficiency | "
          "exact reductions instead | cycle then, efficiency |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in o.ranks_per_node:
        c = cycle_parts(o, r)
        today = c["t_elem"] + c["t_halo"] + c["t_command"] + c["t_blocks"] + c["t_records"]
        then = c["t_elem"] + c["t_halo"] + c["t_command"] + c["t_exact"]
        print(f"| {c['P']} ({c['threads']}) | {c['n']:.3g} | {ms(c['t_elem'])} | {ms(c['t_halo'])} "
              f"({c['halo_bytes'] / 1e6:.3g} MB) | {ms(c['t_command'])} | {ms(c['t_blocks'])} | {ms(c['t_records'])} | "
              f"{ms(today)}, {c['t_elem'] / today:.0%} | {ms(c['t_exact'])} | {ms(then)}, {c['t_elem'] / then:.0%} |")
    print("\n(efficiency: element work over the whole cycle, no overlap of exchanges with work; output not included)")


if __name__ == "__main__":
    main()
