#include "cli/Cli.hpp"
#include "job/Cluster.hpp"

int main(int argc, char** argv) {
  // Under mpirun, MPI starts here and ends when `cluster` goes.
  const glint::Cluster cluster(argc, argv);
  return glint::RunCli(argc, argv, cluster);
}
