// What a render reports when it ends: the --stats JSON and the summary line.
#pragma once

#include <string>

#include "job/RenderJob.hpp"

namespace glint {

std::string StatsJson(const RenderArgs& args, const RenderSetup& s, const Camera& camera,
                      const RenderResult& r);
void PrintSummary(const RenderArgs& args, const RenderSetup& s, const RenderResult& r);
// The process's peak resident memory so far (for --stats and glint bench).
double PeakResidentMiB();

}  // namespace glint
