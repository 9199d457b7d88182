// `glint converge`: error against a reference as rays per pixel (or time) grow, for one
// or several strategies, as a CSV and a log-log chart.
#pragma once

#include <string>

#include "job/RenderJob.hpp"

namespace glint {

struct ConvergeArgs {
  RenderArgs render;
  std::string reference;
  std::string ladder;      // cumulative rays per pixel: "1,2,4,8"
  std::string timeLadder;  // cumulative seconds: "0.5,1,2"
  std::string compare;     // "strategy=mis,light,brdf"
  std::string csv = "converge.csv";
  std::string chart = "converge.png";
};

int RunConverge(const ConvergeArgs& args);

}  // namespace glint
