#include "commands/ViewCommand.hpp"

#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <arpa/inet.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include "commands/LiveRender.hpp"
#include "commands/TreeCommand.hpp"
#include "commands/ViewAssets.hpp"
#include "commands/ViewSettings.hpp"
#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageIO.hpp"
#include "job/ExitCode.hpp"
#include "job/Interrupt.hpp"

namespace glint {

namespace {

constexpr std::size_t kMaxBody = std::size_t{64} * 1024;  // a settings query is a few hundred bytes
constexpr int kMaxTreeNodes = 400;

void SendJson(httplib::Response& res, const nlohmann::json& j, int status = 200) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(j.dump(), "application/json");
}

void SendError(httplib::Response& res, const std::string& message, int status = 400) {
  SendJson(res, {{"error", message}}, status);
}

nlohmann::json State(const LiveRender& live) {
  const std::shared_ptr<const LiveJob> job = live.Job();
  const std::shared_ptr<const LiveFrame> frame = live.Frame();
  nlohmann::json j = {
      {"generation", job->generation}, {"abandoned", live.Abandoned()}, {"status", live.Status()}};
  if (frame && frame->generation == job->generation) {
    const double seconds = frame->seconds > 0.0 ? frame->seconds : 1e-9;
    j["frame"] = {{"id", frame->id},
                  {"passes", frame->passes},
                  {"spp", frame->spp},
                  {"seconds", frame->seconds},
                  {"rays_traced", frame->raysTraced},
                  {"mrays_per_second", static_cast<double>(frame->raysTraced) / seconds / 1e6},
                  {"error", frame->error}};
  }
  return j;
}

int IntParam(const httplib::Request& req, const char* key) {
  const std::string v = req.get_param_value(key);
  if (v.empty() || v.size() > 6 || v.find_first_not_of("0123456789") != std::string::npos) {
    throw InputError(std::string(key) + "=" + v + ": expected a whole number");
  }
  return std::stoi(v);
}

// The settings of the current render and what the page needs to show them.
nlohmann::json Settings(const LiveRender& live) {
  const std::shared_ptr<const LiveJob> job = live.Job();
  return {{"scene", job->args.scene},  // as the command line gave it
          {"generation", job->generation},   {"width", job->setup.width},
          {"height", job->setup.height},     {"threads", job->setup.threads},
          {"exposure", job->setup.exposure}, {"settings", SettingsJson(job->args)},
          {"tunables", job->tunables},       {"reference", live.Reference().has_value()}};
}

// The largest part of `query` that renders: each setting is tried on top of those kept,
// and the ones refused are tried again once more have been kept (walls=diffuse comes good
// after mode=mc, whatever their order). A --set refused falls back to the value the
// current render has for the same pointer, so that a bad slider value keeps the others.
QueryParams GoodSettings(const RenderArgs& base, const RenderArgs& current,
                         const QueryParams& query) {
  QueryParams kept;
  const bool sets =
      std::any_of(query.begin(), query.end(), [](const auto& item) { return item.first == "set"; });
  if (sets) kept.emplace_back("set", "");  // the query's list replaces the command line's
  std::vector<std::string> fallback(query.size());
  for (std::size_t i = 0; i < query.size(); ++i) {
    if (query[i].first != "set" || query[i].second.empty()) continue;
    const std::string pointer = query[i].second.substr(0, query[i].second.find('=') + 1);
    for (const std::string& o : current.overrides) {
      if (o.rfind(pointer, 0) == 0 && o != query[i].second) fallback[i] = o;
    }
  }
  const auto renders = [&](const QueryParams& trial) {
    try {
      LiveRender::Check(ArgsFromQuery(base, trial));
      return true;
    } catch (const InputError&) {
      return false;
    }
  };
  std::vector<bool> taken(query.size(), false);
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t i = 0; i < query.size(); ++i) {
      if (taken[i]) continue;
      QueryParams trial = kept;
      trial.push_back(query[i]);
      bool ok = renders(trial);
      if (!ok && !fallback[i].empty()) {
        trial.back().second = fallback[i];
        ok = renders(trial);
      }
      if (!ok) continue;
      kept = std::move(trial);
      taken[i] = true;
      grew = true;
    }
  }
  return kept;
}

// The page's assets, its state and its settings.
void PageRoutes(httplib::Server& server, LiveRender& live, const RenderArgs& base) {
  for (const ViewAsset& asset : ViewAssets()) {
    const std::string path = asset.path;
    server.Get(path == "/index.html" ? "/" : path,
               [asset](const httplib::Request&, httplib::Response& res) {
                 res.set_content(asset.body.data(), asset.body.size(), asset.type);
               });
  }
  server.Get("/api/state", [&live](const httplib::Request&, httplib::Response& res) {
    live.Asked();
    SendJson(res, State(live));
  });
  server.Get("/api/settings", [&live](const httplib::Request&, httplib::Response& res) {
    SendJson(res, Settings(live));
  });
  // New settings, as the body of a form (the page's URL query).
  server.Post("/api/settings", [&live, base](const httplib::Request& req, httplib::Response& res) {
    const QueryParams query = ParseQuery(req.body);
    try {
      live.Apply(ArgsFromQuery(base, query));
    } catch (const InputError& e) {
      // A bad value never drops the others: apply what is good, say what is not.
      try {
        live.Apply(ArgsFromQuery(base, GoodSettings(base, live.Job()->args, query)));
      } catch (const InputError&) {  // NOLINT(bugprone-empty-catch): the first error says it
      }
      nlohmann::json body = {{"error", e.what()}, {"applied", Settings(live)}};
      return SendJson(res, body, 400);
    }
    SendJson(res, Settings(live));
  });
}

// The images: the current frame and the reference, for the page (RGBE).
void ImageRoutes(httplib::Server& server, LiveRender& live) {
  server.Get("/api/frame", [&live](const httplib::Request&, httplib::Response& res) {
    live.Asked();
    const std::shared_ptr<const LiveFrame> frame = live.Frame();
    if (!frame) return SendError(res, "no frame yet", 404);
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Glint-Frame", std::to_string(frame->id));
    res.set_header("X-Glint-Generation", std::to_string(frame->generation));
    res.set_header("X-Glint-Size", std::to_string(frame->image.Width()) + "x" +
                                       std::to_string(frame->image.Height()));
    res.set_content(RgbePixels(frame->image), "application/octet-stream");
  });
  server.Get("/api/reference", [&live](const httplib::Request&, httplib::Response& res) {
    if (!live.Reference()) return SendError(res, "no --reference was given", 404);
    res.set_content(RgbePixels(*live.Reference()), "application/octet-stream");
  });
}

// A pixel's ray trees, and the downloads.
void InspectAndSaveRoutes(httplib::Server& server, LiveRender& live) {
  server.Get("/api/tree", [&live](const httplib::Request& req, httplib::Response& res) {
    const std::shared_ptr<const LiveJob> job = live.Job();
    try {
      const int x = IntParam(req, "x");
      const int y = IntParam(req, "y");
      if (x >= job->setup.width || y >= job->setup.height) {
        throw InputError("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                         ") is outside the image");
      }
      const PixelTrees p = TracePixelTrees(job->args, job->setup, *job->integrator, x, y);
      nlohmann::json j = TreeJson(p.trees, job->setup.scene, kMaxTreeNodes);
      j["x"] = x;
      j["y"] = y;
      j["radiance"] = {p.radiance.x, p.radiance.y, p.radiance.z};
      SendJson(res, j);
    } catch (const InputError& e) {
      SendError(res, e.what());
    }
  });
  // The current image as a file: ?format=png|pfm|exr, &exposure= for PNG.
  server.Get("/api/image", [&live](const httplib::Request& req, httplib::Response& res) {
    const std::shared_ptr<const LiveFrame> frame = live.Frame();
    if (!frame) return SendError(res, "no frame yet", 404);
    const std::string format = req.get_param_value("format");
    double exposure = live.Job()->setup.exposure;
    if (req.has_param("exposure")) {
      char* end = nullptr;
      const std::string text = req.get_param_value("exposure");
      exposure = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !(exposure > 0.0 && exposure < 1e9)) {
        return SendError(res, "exposure=" + text + ": expected a positive number");
      }
    }
    const std::vector<std::pair<std::string, ImageFormat>> formats = {
        {"png", ImageFormat::Png}, {"pfm", ImageFormat::Pfm}, {"exr", ImageFormat::Exr}};
    for (const auto& [name, f] : formats) {
      if (name != format) continue;
      res.set_header("Content-Disposition", "attachment; filename=\"glint-view." + name + "\"");
      res.set_header("X-Glint-Frame", std::to_string(frame->id));
      res.set_content(EncodeImage(frame->image, f, exposure),
                      name == "png" ? "image/png" : "application/octet-stream");
      return;
    }
    SendError(res, "format=" + format + ": expected png, pfm or exr");
  });
  server.Get("/api/scene.json", [&live](const httplib::Request&, httplib::Response& res) {
    const std::shared_ptr<const LiveJob> job = live.Job();
    res.set_header("Content-Disposition",
                   "attachment; filename=\"" +
                       std::filesystem::path(job->args.scene).stem().string() + "-view.json\"");
    res.set_content(job->document.dump(2) + "\n", "application/json");
  });
}

// Why a port cannot be had, in the system's words (cpp-httplib only says that it failed).
std::string WhyNotBound(const std::string& host, int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return std::strerror(errno);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, host.c_str(), &address.sin_addr) != 1) {
    ::close(fd);
    return "not an IPv4 address";
  }
  const int rc = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
  std::string why = rc == 0 ? "refused" : std::strerror(errno);
  ::close(fd);
  return why;
}

}  // namespace

int RunView(const ViewArgs& a) {
  std::optional<Image> reference;
  if (!a.reference.empty()) {
    try {
      reference = ReadImage(a.reference);
    } catch (const std::runtime_error& e) {
      throw InputError(std::string("--reference: ") + e.what());
    }
  }
  httplib::Server server;
  server.set_payload_max_length(kMaxBody);
  // One request a connection, answered with "Connection: close": no connection waits
  // idle for a next request (so SIGINT ends the server within a second), and a browser
  // never sends one on a connection the server is closing (with keep-alive, Chromium's
  // fetch failed now and then). The page asks a few times a second, on loopback.
  // A slow request holds a worker thread for half a second at most.
  server.set_keep_alive_max_count(1);
  server.set_read_timeout(0, 500000);
  server.set_write_timeout(5, 0);
  server.new_task_queue = [] { return new httplib::ThreadPool(8); };
  server.set_exception_handler(
      [](const httplib::Request&, httplib::Response& res, const std::exception_ptr& error) {
        std::string what = "unknown error";
        try {
          std::rethrow_exception(error);
        } catch (const std::exception& e) {
          what = e.what();
        } catch (...) {  // NOLINT(bugprone-empty-catch): the answer says it
        }
        SendError(res, what, 500);
      });
  int port = a.port;
  if (port == 0) {
    port = server.bind_to_any_port(a.host);
    if (port < 0) throw InputError("--host " + a.host + ": cannot listen there");
  } else if (!server.bind_to_port(a.host, port)) {
    throw InputError("--port " + std::to_string(port) + ": cannot listen on " + a.host + ":" +
                     std::to_string(port) + " (" + WhyNotBound(a.host, port) +
                     "); choose another with --port N, or --port 0 for any free one");
  }
  std::signal(SIGPIPE, SIG_IGN);  // a browser that goes away mid-answer is not an error
  const std::atomic<bool>& interrupted = InstallInterruptHandlers();
  LiveRender live(a.render, std::move(reference), a.limits);
  PageRoutes(server, live, a.render);
  ImageRoutes(server, live);
  InspectAndSaveRoutes(server, live);
  std::thread listener([&server]() { server.listen_after_bind(); });
  std::fprintf(stderr, "glint view: http://%s:%d/\n", a.host.c_str(), port);
  while (!interrupted.load()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  live.Stop();
  server.stop();
  listener.join();
  std::fprintf(stderr, "glint view: stopped by %s\n",
               InterruptSignal() == SIGTERM ? "SIGTERM" : "SIGINT");
  return kExitOk;
}

}  // namespace glint
