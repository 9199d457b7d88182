// `glint compare A B REF [REF2]`: do two independent renders agree with a reference
// within their noise? One line of verdict; the exit code says it (BiasTest.hpp).
#pragma once

#include <string>

namespace glint {

struct CompareArgs {
  std::string a;
  std::string b;
  std::string reference;
  std::string reference2;  // optional: a second, independent reference, whose noise counts
  int block = 16;
  double meanSigma = 4.0;
  double familyAlpha = 1e-3;
  double scale = 1.0;  // A and B are multiplied by this first (to calibrate the test)
};

int RunCompare(const CompareArgs& args);

}  // namespace glint
