// `glint bench`: whole-image throughput of a scene in both modes, for one or more
// thread counts: camera paths/s and rays/s (all kinds, as --stats counts them), per
// thread, and the speedup over the first thread count. Best of several runs.
#pragma once

#include <string>
#include <vector>

#include "job/RenderJob.hpp"

namespace glint {

struct BenchArgs {
  std::string scene = "scenes/cornell.json";
  std::string size = "256";
  std::vector<int> threads{1, 2};
  int mcSpp = 64;
  int whittedSpp = 0;  // 0: the scene's value for Whitted mode
  int repeat = 3;
  std::vector<std::string> modes{"mc", "whitted"};
  std::string sampler = "sobol";
  // Monte Carlo rows for each SIMD target (--simd auto|scalar|sse4|avx2|avx512, a list):
  // the targets' rows take turns like the others.
  std::vector<std::string> simd{"auto"};
  std::string json;  // optional: the table as JSON
};

class Cluster;

// Under MPI (`mpirun -np N glint bench`): the scaling over ranks, one thread each.
int RunBench(const BenchArgs& args, const Cluster& cluster);

}  // namespace glint
