// Numbers as people write them in messages: the shortest text that reads back as the same
// double (0.5, not 0.500000; 1000000, not 1e+06).
#pragma once

#include <string>

#include "glint/core/Math.hpp"

namespace glint {

std::string FormatNumber(double x);
// A value glint computed (a sphere's extent, a sum), rounded to 12 significant digits
// first so that 0.3 - 0.1 prints as 0.2, not 0.19999999999999998.
std::string FormatComputed(double x);
// "(x, y, z)" with each component as FormatComputed writes it.
std::string FormatPoint(vec3 p);

}  // namespace glint
