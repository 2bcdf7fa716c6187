// The communication layer (comm.h): MPI when the build has it (IMPACT3D_HAVE_MPI, set for this
// file and partition.cpp only by the CMake option IMPACT3D_MPI), else one process.
#include "impact3d/parallel/comm.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#if IMPACT3D_HAVE_MPI
#include <mpi.h>
#endif

namespace impact3d::parallel {

namespace {
bool g_started = false;  // init() started MPI
int g_rank = 0, g_size = 1;

// mpirun (OpenMPI), srun and Hydra set these in each process they start.
bool launched_by_mpi_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}
}  // namespace

#if IMPACT3D_HAVE_MPI

bool built_with_mpi() { return true; }

void init(int* argc, char*** argv) {
  if (g_started || !launched_by_mpi_launcher()) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);  // MPI calls from the main thread only
  g_started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
}

void finalize() {
  if (g_started) MPI_Finalize();
  g_started = false;
}

void abort(int code) {
  if (g_started) MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

void broadcast(void* data, std::size_t bytes, int root) {
  if (g_size == 1) return;
  MPI_Bcast(data, int(bytes), MPI_BYTE, root, MPI_COMM_WORLD);
}

void allgather(const void* send, int send_bytes, void* recv, const int* recv_bytes, const int* displs) {
  if (g_size == 1) {
    if (send_bytes > 0) std::memmove(static_cast<char*>(recv) + displs[0], send, std::size_t(send_bytes));
    return;
  }
  MPI_Allgatherv(send, send_bytes, MPI_BYTE, recv, recv_bytes, displs, MPI_BYTE, MPI_COMM_WORLD);
}

void gather(const void* send, int send_bytes, void* recv, const int* recv_bytes, const int* displs, int root) {
  if (g_size == 1) {
    if (send_bytes > 0) std::memmove(static_cast<char*>(recv) + displs[0], send, std::size_t(send_bytes));
    return;
  }
  MPI_Gatherv(send, send_bytes, MPI_BYTE, recv, recv_bytes, displs, MPI_BYTE, root, MPI_COMM_WORLD);
}

void exchange(const std::vector<Exchange>& with, int tag) {
  if (with.empty()) return;
  static std::vector<MPI_Request> req;  // (sized at the first exchange; main thread only)
  req.assign(2 * with.size(), MPI_REQUEST_NULL);
  for (std::size_t i = 0; i < with.size(); ++i)
    if (with[i].recv_count > 0)
      MPI_Irecv(with[i].recv, with[i].recv_count, MPI_DOUBLE, with[i].peer, tag, MPI_COMM_WORLD, &req[2 * i]);
  for (std::size_t i = 0; i < with.size(); ++i)
    if (with[i].send_count > 0)
      MPI_Isend(with[i].send, with[i].send_count, MPI_DOUBLE, with[i].peer, tag, MPI_COMM_WORLD, &req[2 * i + 1]);
  MPI_Waitall(int(req.size()), req.data(), MPI_STATUSES_IGNORE);
}

#else  // one process

bool built_with_mpi() { return false; }
void init(int*, char***) {
  (void)g_started;
  (void)launched_by_mpi_launcher;
}
void finalize() {}
void abort(int code) { std::_Exit(code); }
void broadcast(void*, std::size_t, int) {}
void allgather(const void* send, int send_bytes, void* recv, const int*, const int* displs) {
  if (send_bytes > 0) std::memmove(static_cast<char*>(recv) + displs[0], send, std::size_t(send_bytes));
}
void gather(const void* send, int send_bytes, void* recv, const int*, const int* displs, int) {
  if (send_bytes > 0) std::memmove(static_cast<char*>(recv) + displs[0], send, std::size_t(send_bytes));
}
void exchange(const std::vector<Exchange>& with, int) {
  if (!with.empty()) throw std::logic_error("parallel::exchange: no peers in a one-process build");
}

#endif

int launcher_size() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* n = std::getenv(v)) return std::max(1, std::atoi(n));
  return 1;
}

int rank() { return g_rank; }
int size() { return g_size; }

}  // namespace impact3d::parallel
