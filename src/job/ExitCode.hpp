// The exit codes of every glint command, also listed by --help and in the README.
#pragma once

namespace glint {

enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,      // a bad scene file, override or command-line value
  kExitOutputFailed = 2,  // an output file could not be written
  kExitDisagree = 3,      // glint compare: the renders disagree with the reference
};

}  // namespace glint
