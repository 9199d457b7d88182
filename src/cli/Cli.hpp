// The command line: `glint render SCENE [options]`.
#pragma once

namespace glint {

// Exit codes, also listed by --help and in the README.
enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,      // a bad scene file, override or command-line value
  kExitOutputFailed = 2,  // an output file could not be written
  kExitDisagree = 3,      // glint compare: the renders disagree with the reference
};

class Cluster;

// `cluster`: the MPI ranks this process is one of (or this process alone).
int RunCli(int argc, char** argv, const Cluster& cluster);

}  // namespace glint
