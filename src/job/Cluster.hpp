// The processes a render runs on: this one alone, or the ranks of an MPI job
// (`mpirun -np N glint render ...`, Slurm's srun, PBS). Rank 0 writes every output and
// alone speaks; a pass is spread over the ranks in batches of pixel chunks handed out
// as ranks ask for them, and every pixel's pass is added on rank 0 in pass order, so
// the image is the same, bit for bit, as one process's with the same seed and flags.
// Without mpirun (or without MPI at build time) everything here is a no-op.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/camera/RenderStats.hpp"

namespace glint {

class Cluster {
 public:
  // This process alone.
  Cluster() = default;
  // Starts MPI when glint runs under an MPI launcher and was built with MPI.
  Cluster(int& argc, char**& argv);
  ~Cluster();
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  int Rank() const { return rank_; }
  int Size() const { return size_; }
  bool Root() const { return rank_ == 0; }
  bool Distributed() const { return size_ > 1; }
  // Ranks on this rank's node, for the default thread count.
  int LocalSize() const { return localSize_; }

  // The threads this rank uses by default: its node's cores divided among the node's
  // ranks (never more than the cores it may run on), or OMP_NUM_THREADS when set.
  int DefaultThreads() const;

  // Collectives (trivial with one process).
  // Whether `ok` holds on every rank; `failedRanks` receives the ranks where it does not.
  bool AllOk(bool ok, std::vector<int>* failedRanks = nullptr) const;
  void Broadcast(void* data, std::size_t bytes) const;
  template <typename T>
  T Broadcast(T value) const {
    Broadcast(&value, sizeof value);
    return value;
  }
  void Barrier() const;
  // values[0..n) summed over the ranks, on rank 0.
  void SumOnRoot(std::uint64_t* values, int n) const;

  // One pass (options.pass, options.raysPerPixel) over all of `camera`'s chunks, spread
  // over the ranks in ranges handed out as ranks ask; on rank 0 the camera ends with the
  // pass added to every pixel, in pass order, and `stats` with every rank's counters
  // (they come with the results). `betweenBatches`, if any, runs on rank 0 between its
  // own ranges (a checkpoint); with one process it splits the pass into batches.
  void RenderPass(Camera& camera, const Integrator& integrator, const RenderOptions& options,
                  RenderStats& stats, const std::function<void()>& betweenBatches) const;

  // The communication of all passes so far, on this rank: messages and bytes sent.
  std::uint64_t MessagesSent() const { return messages_; }
  std::uint64_t BytesSent() const { return bytes_; }

 private:
  void RootPass(Camera& camera, const Integrator& integrator, const RenderOptions& options,
                RenderStats& stats, const std::function<void()>& betweenBatches) const;
  void WorkerPass(Camera& camera, const Integrator& integrator, const RenderOptions& options) const;

  int rank_ = 0;
  int size_ = 1;
  int localSize_ = 1;
  bool started_ = false;
  mutable std::uint64_t messages_ = 0;
  mutable std::uint64_t bytes_ = 0;
};

}  // namespace glint
