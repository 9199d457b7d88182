// A lane kernel runs over whole vectors: `count` lanes rounded up to its width. The
// spare lanes at the end must hold real inputs (a zero vector would normalise to NaN and
// waste a slow path), so each kernel's caller fills them with lane 0's, and ignores what
// comes out of them.
#pragma once

#include <array>
#include <cstddef>

namespace glint {

// `count` rounded up to a whole number of vectors of `width` lanes.
constexpr int PaddedLaneCount(int count, int width) {
  return (count + width - 1) / width * width;
}

namespace lane_padding {

template <std::size_t N>
void FromLaneZero(std::array<double, N>& lane, int count, int padded) {
  for (int i = count; i < padded; ++i) lane[static_cast<std::size_t>(i)] = lane[0];
}

template <std::size_t N, std::size_t M>
void FromLaneZero(std::array<std::array<double, N>, M>& lanes, int count, int padded) {
  for (auto& lane : lanes) FromLaneZero(lane, count, padded);
}

}  // namespace lane_padding

// Pads each field (a lane, or an array of lanes such as a vector's three components)
// from lane 0 up to `count` rounded to `width`; returns that padded count.
template <typename... Fields>
int PadLanesFromLaneZero(int count, int width, Fields&... fields) {
  const int padded = PaddedLaneCount(count, width);
  (lane_padding::FromLaneZero(fields, count, padded), ...);
  return padded;
}

}  // namespace glint
