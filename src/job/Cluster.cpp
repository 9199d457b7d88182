#include "job/Cluster.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <thread>

#if defined(GLINT_MPI)
#include <mpi.h>
#endif

namespace glint {

namespace {

// Whether an MPI launcher started this process (OpenMPI, MPICH/Hydra, PMIx, Slurm).
bool UnderMpiLauncher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

}  // namespace

Cluster::Cluster(int& argc, char**& argv) {
#if defined(GLINT_MPI)
  if (!UnderMpiLauncher()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  started_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &localSize_);
  MPI_Comm_free(&node);
#else
  (void)argc;
  (void)argv;
  (void)UnderMpiLauncher;
#endif
}

Cluster::~Cluster() {
#if defined(GLINT_MPI)
  if (started_) MPI_Finalize();
#endif
}

int Cluster::DefaultThreads() const {
  if (std::getenv("OMP_NUM_THREADS") != nullptr) return omp_get_max_threads();
  const int node = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  // omp_get_num_procs: the cores this process may run on (a launcher may bind it).
  return std::max(1, std::min(omp_get_num_procs(), node / std::max(1, localSize_)));
}

bool Cluster::AllOk(bool ok, std::vector<int>* failedRanks) const {
  if (failedRanks) failedRanks->clear();
  if (!Distributed()) {
    if (!ok && failedRanks) failedRanks->push_back(0);
    return ok;
  }
#if defined(GLINT_MPI)
  int mine = ok ? 1 : 0;
  std::vector<int> all(static_cast<std::size_t>(size_));
  MPI_Allgather(&mine, 1, MPI_INT, all.data(), 1, MPI_INT, MPI_COMM_WORLD);
  bool every = true;
  for (int r = 0; r < size_; ++r) {
    if (all[static_cast<std::size_t>(r)] == 0) {
      every = false;
      if (failedRanks) failedRanks->push_back(r);
    }
  }
  return every;
#else
  return ok;
#endif
}

void Cluster::Broadcast(void* data, std::size_t bytes) const {
#if defined(GLINT_MPI)
  if (!Distributed()) return;
  // In pieces below 2^31 bytes, MPI's count being an int.
  auto* p = static_cast<char*>(data);
  constexpr std::size_t kPiece = std::size_t{1} << 30;
  for (std::size_t done = 0; done < bytes; done += kPiece) {
    MPI_Bcast(p + done, static_cast<int>(std::min(kPiece, bytes - done)), MPI_BYTE, 0,
              MPI_COMM_WORLD);
  }
  if (Root()) {
    messages_ += static_cast<std::uint64_t>(size_ - 1);
    bytes_ += static_cast<std::uint64_t>(size_ - 1) * bytes;
  }
#else
  (void)data;
  (void)bytes;
#endif
}

void Cluster::SumOnRoot(std::uint64_t* values, int n) const {
#if defined(GLINT_MPI)
  if (!Distributed()) return;
  std::vector<std::uint64_t> out(static_cast<std::size_t>(n));
  MPI_Reduce(values, out.data(), n, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  if (Root()) std::copy(out.begin(), out.end(), values);
#else
  (void)values;
  (void)n;
#endif
}

void Cluster::Barrier() const {
#if defined(GLINT_MPI)
  if (Distributed()) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

}  // namespace glint
