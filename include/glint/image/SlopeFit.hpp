// The slope of a convergence curve: log error against log time (or rays per pixel), fitted
// by least squares through one point per rung, with a standard error from the rungs'
// independent repeats (a bootstrap: the repeats of each rung resampled, the fit redone).
// Repeats run in rounds share the load of their round: then whole rounds are resampled (a
// block bootstrap), so that the error bar holds what a busy spell does to a rung.
// A rung's point is the median of its repeats' x (a time: one preempted run does not move
// it) and the mean of their errors (the expected error: relative MSE is a mean already).
#pragma once

#include <vector>

#include "glint/sampling/Rng.hpp"

namespace glint {

struct Rung {
  std::vector<double> x;   // per repeat: seconds (or rays per pixel)
  std::vector<double> y;   // per repeat: the error, same order
  std::vector<int> block;  // per repeat: its round; empty: every repeat on its own
};

struct Slope {
  double value = 0.0;          // d log y / d log x
  double standardError = 0.0;  // from the bootstrap; 0 with fewer than 2 repeats (or
                               // rounds) per rung
  double logX = 0.0;           // the fit passes through (logX, logY), the points' centroid
  double logY = 0.0;
  int points = 0;  // rungs fitted (those with positive x and y)
};

// The point of one rung: median x, mean y.
double MedianOf(std::vector<double> values);
double MeanOf(const std::vector<double>& values);

// Ordinary least squares of log y on log x; fewer than 2 usable rungs give a value of NaN.
Slope FitSlope(const std::vector<Rung>& rungs, Pcg32& rng, int resamples = 1000);

}  // namespace glint
