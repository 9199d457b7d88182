// `glint render SCENE [options]`: a render to images, its --stats and summary line.
#pragma once

#include "job/RenderSetup.hpp"

namespace glint {

class Cluster;

// Every rank checks the input; rank 0 writes the outputs. Returns the exit code.
int RunRender(const RenderArgs& args, const Cluster& cluster);

}  // namespace glint
