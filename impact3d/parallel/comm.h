#pragma once
// The communication layer: the one place that talks MPI (comm.cpp).  Everything else of the
// distributed run (partition.h, distributed_cycle.h) calls these functions, which work the same
// in a build without MPI (one process: rank 0 of 1, the exchanges copy nothing).  Only the
// calls the distributed cycle needs, on raw bytes and doubles; no floating-point reduction is
// offered on purpose: sums are made in a fixed global order by the caller (same bits for any
// rank count).

#include <cstddef>
#include <vector>

namespace impact3d::parallel {

// Whether this build has MPI and METIS (CMake option IMPACT3D_MPI).
bool built_with_mpi();
// Starts MPI when the program was launched by mpirun/srun (the launcher's environment
// variables are set; a plain run never initializes MPI).  Safe to call once, before anything
// else reads the arguments.
void init(int* argc, char*** argv);
// Ends MPI if init started it.
void finalize();
int rank();
int size();
// The number of processes the launcher started (its environment: OMPI_COMM_WORLD_SIZE,
// PMI_SIZE), 1 for a plain run; a build without MPI run under mpirun -np 2 sees 2 here and 1
// in size().
int launcher_size();
// Stops every rank at once (an error on one rank).
[[noreturn]] void abort(int code);

// `bytes` bytes at data, from root to every rank.
void broadcast(void* data, std::size_t bytes, int root = 0);
// Every rank's piece (send_bytes at send) to every rank: rank q's piece lands at recv +
// displs[q], recv_bytes[q] bytes (both arrays size() long, the same on every rank).
void allgather(const void* send, int send_bytes, void* recv, const int* recv_bytes, const int* displs);
// The same, to root only (recv, recv_bytes and displs are read on root only).
void gather(const void* send, int send_bytes, void* recv, const int* recv_bytes, const int* displs, int root = 0);

// One neighbour of a point-to-point exchange: `send_count` doubles from `send` go to `peer`,
// `recv_count` doubles from it land at `recv` (the counts agree by construction: both sides
// build their lists from the same partition).
struct Exchange {
  int peer = -1;
  const double* send = nullptr;
  int send_count = 0;
  double* recv = nullptr;
  int recv_count = 0;
};
// All the exchanges at once (non-blocking sends and receives, then wait for all); `tag`
// separates the kinds of exchange of one cycle.
void exchange(const std::vector<Exchange>& with, int tag);

}  // namespace impact3d::parallel
