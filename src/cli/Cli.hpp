// The command line: `glint render SCENE [options]` and the other commands.
#pragma once

#include "job/ExitCode.hpp"

namespace glint {

class Cluster;

// `cluster`: the MPI ranks this process is one of (or this process alone).
int RunCli(int argc, char** argv, const Cluster& cluster);

}  // namespace glint
