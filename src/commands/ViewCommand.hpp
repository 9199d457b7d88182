// `glint view SCENE`: a local web page that shows the render refining, with the design's
// studies as controls (src/commands/view/ holds the page). The server (cpp-httplib) answers only
// its own routes: the page's three assets and the /api/ calls below; no request reaches
// the file system.
#pragma once

#include <string>

#include "commands/LiveRender.hpp"
#include "job/RenderJob.hpp"

namespace glint {

struct ViewArgs {
  RenderArgs render;
  std::string host = "127.0.0.1";  // loopback unless the user says otherwise
  int port = 8765;                 // 0: any free port
  std::string reference;           // PFM or EXR for the compare views
  LiveLimits limits;               // --time, --max-spp
};

// Serves until SIGINT or SIGTERM; 0 then, 1 for bad input or a port that cannot be had.
int RunView(const ViewArgs& args);

}  // namespace glint
