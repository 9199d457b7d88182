// The command line: `glint render SCENE [options]`.
#pragma once

namespace glint {

// Exit codes, also listed by --help and in the README.
enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,       // a bad scene file, override or command-line value
  kExitUnavailable = 2,    // a mode this build does not have yet
  kExitOutputFailed = 3,   // an output file could not be written
};

int RunCli(int argc, char** argv);

}  // namespace glint
