// The flags of a render, shared by `glint render`, `converge`, `tree` and `view`.
#pragma once

#include <CLI/CLI.hpp>

#include "job/RenderSetup.hpp"

namespace glint {

// Adds the render's flags to `command`, into `args`. With `outputs` false (converge, tree,
// view), the options that name output files are left out.
void AddRenderOptions(CLI::App* command, RenderArgs& args, bool outputs);
// Records which Monte Carlo switches were given (Prepare refuses them in Whitted mode).
void RecordMonteCarloSwitches(const CLI::App* command, RenderArgs& args);

}  // namespace glint
