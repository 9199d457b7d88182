#include "glint/core/Format.hpp"

#include <array>
#include <charconv>

namespace glint {

std::string FormatNumber(double x) {
  std::array<char, 64> buffer{};
  // std::to_chars without a format is the shortest round-trip form, in scientific
  // notation when that is shorter; between 1e-4 and 1e15 people prefer plain digits.
  const double magnitude = std::abs(x);
  const bool plain = magnitude == 0.0 || (magnitude >= 1e-4 && magnitude < 1e15);
  const auto result = plain ? std::to_chars(buffer.data(), buffer.data() + buffer.size(), x,
                                            std::chars_format::fixed)
                            : std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  return {buffer.data(), result.ptr};
}

std::string FormatComputed(double x) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x,
                                    std::chars_format::general, 12);
  double rounded = x;
  std::from_chars(buffer.data(), result.ptr, rounded);
  return FormatNumber(rounded);
}

std::string FormatPoint(vec3 p) {
  return "(" + FormatComputed(p.x) + ", " + FormatComputed(p.y) + ", " + FormatComputed(p.z) + ")";
}

}  // namespace glint
