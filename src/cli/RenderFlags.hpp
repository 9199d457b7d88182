// The flags of a render, shared by `glint render`, `converge`, `tree` and `view`.
#pragma once

#include <CLI/CLI.hpp>

#include "job/RenderSetup.hpp"

namespace glint {

// Adds the render's flags to `command`, into `args`. With `outputs` false (converge, tree,
// view), the options that name output files are left out.
void AddRenderOptions(CLI::App* command, RenderArgs& args, bool outputs);
// A check for a number > 0 whose message says so (CLI11's PositiveNumber prints its range
// with a 300-digit upper bound).
CLI::Validator PositiveNumber();
// Records which Monte Carlo switches were given (Prepare refuses them in Whitted mode).
void RecordMonteCarloSwitches(const CLI::App* command, RenderArgs& args);

}  // namespace glint
