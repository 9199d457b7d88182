// Running another program (Graphviz's dot, Debian's python3) without a shell: the
// arguments go as they are, so a file name with quotes or spaces is no risk.
#pragma once

#include <string>
#include <vector>

namespace glint {

// Runs argv[0] (found on PATH) with the arguments, waits for it, and returns its exit
// code; 127 if it could not be started, 128 + N if signal N ended it.
int RunProgram(const std::vector<std::string>& argv);

// Whether `program` is an executable file on PATH.
bool OnPath(const std::string& program);

}  // namespace glint
