// The Cluster's second half: one pass spread over the ranks (Cluster::RenderPass); the
// first half (Cluster.cpp) starts the processes and has their collectives.
#include "job/Cluster.hpp"

#include <omp.h>

#include <algorithm>
#include <cstring>

#if defined(GLINT_MPI)
#include <mpi.h>
#endif

namespace glint {

namespace {

#if defined(GLINT_MPI)
enum Tag : int { kRequest = 1, kReply = 2, kResult = 3, kDone = 4 };

// A range's pixels as sent to rank 0: per pixel r, g, b and the sample count (as a
// double, exact below 2^53), or -1 for a pixel a resumed pass had done already.
constexpr std::size_t kPerPixel = 4;
#endif

}  // namespace

namespace {

// The next range of chunks to hand out, guided: a quarter of what is left shared among
// the ranks, so that the first ranges are large (few messages) and the last are single
// chunks (no rank waits long for another at the end of a pass).
int GuidedChunks(int left, int ranks) {
  return std::max(1, left / (4 * ranks));
}

#if defined(GLINT_MPI)
// The counters travel as doubles (exact below 2^53) in a result's header.
void AppendStats(std::vector<double>& out, const RenderStats& s) {
  for (const std::uint64_t v : s.ToCounters()) out.push_back(static_cast<double>(v));
}
RenderStats StatsAt(const double* p) {
  RenderStats::Counters c;
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = static_cast<std::uint64_t>(p[i]);
  return RenderStats::FromCounters(c);
}
// A result: first chunk, last chunk, abandoned, the counters, then the pixels, then light
// tracing's splats (anywhere in the image): their number, and per splat the pixel and
// each component's 64-bit sum as two 32-bit halves (doubles hold them exactly).
constexpr std::size_t kHeader = 3 + std::tuple_size_v<RenderStats::Counters>;
constexpr std::size_t kPerSplat = 7;

// Moves this rank's splats into `out` and clears them.
void TakeSplats(Camera& camera, std::vector<double>& out) {
  const std::size_t at = out.size();
  out.push_back(0.0);
  const std::size_t count =
      static_cast<std::size_t>(camera.Width()) * static_cast<std::size_t>(camera.Height());
  for (std::size_t i = 0; i < count; ++i) {
    Pixel& pixel = camera.PixelAt(i);
    const Pixel::SplatSum& s = pixel.Splats();
    if (s[0] == 0 && s[1] == 0 && s[2] == 0) continue;
    out.push_back(static_cast<double>(i));
    for (const std::int64_t v : s) {
      const auto bits = static_cast<std::uint64_t>(v);
      out.push_back(static_cast<double>(bits >> 32U));
      out.push_back(static_cast<double>(bits & 0xffffffffULL));
    }
    pixel.RestoreSplats({});
    out[at] += 1.0;
  }
}

// Adds the splats TakeSplats wrote at `p`.
void AddSplats(Camera& camera, const double* p) {
  const auto count = static_cast<std::size_t>(p[0]);
  ++p;
  for (std::size_t k = 0; k < count; ++k, p += kPerSplat) {
    Pixel::SplatSum s{};
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint64_t bits = (static_cast<std::uint64_t>(p[1 + 2 * c]) << 32U) |
                                 static_cast<std::uint64_t>(p[2 + 2 * c]);
      s[c] = static_cast<std::int64_t>(bits);
    }
    camera.PixelAt(static_cast<std::size_t>(p[0])).AddSplats(s);
  }
}
#endif

}  // namespace

void Cluster::RenderPass(Camera& camera, const Integrator& integrator, const RenderOptions& options,
                         RenderStats& stats, const std::function<void()>& betweenBatches) const {
  if (Distributed()) {
    if (Root()) {
      RootPass(camera, integrator, options, stats, betweenBatches);
    } else {
      WorkerPass(camera, integrator, options);
    }
    return;
  }
  if (!betweenBatches) {
    stats += camera.Render(integrator, options);
    return;
  }
  // One process with a checkpoint: the pass in batches of 32 chunks a thread or more,
  // between which it is saved (each batch ends on a barrier of the threads: half a
  // chunk a thread lost, under 2%).
  const int chunks = camera.Chunks();
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const int batch = std::max(32 * threads, chunks / 64);
  for (int first = 0; first < chunks; first += batch) {
    stats += camera.RenderChunks(integrator, options, first, std::min(chunks, first + batch));
    if (options.cancel && options.cancel->load()) break;
    betweenBatches();
  }
}

#if defined(GLINT_MPI)

// The nonblocking requests below complete through MPI_Test in loops and lambdas, which
// clang's MPI checker does not follow: it reports every one as never waited for.
// NOLINTBEGIN(clang-analyzer-optin.mpi.MPI-Checker)
void Cluster::RootPass(Camera& camera, const Integrator& integrator, const RenderOptions& options,
                       RenderStats& stats, const std::function<void()>& betweenBatches) const {
  const int chunks = camera.Chunks();
  const std::size_t count =
      static_cast<std::size_t>(camera.Width()) * static_cast<std::size_t>(camera.Height());
  int next = 0;         // the first chunk not handed out
  int pending = 0;      // ranges handed to other ranks whose result has not come
  int doneWorkers = 0;  // ranks that have said they are done with this pass
  int requests = 0;     // requests received in this pass
  const auto cancelled = [&]() { return options.cancel && options.cancel->load(); };
  const auto take = [&](int range[2]) {
    if (cancelled() || next >= chunks) {
      range[0] = range[1] = -1;
      return false;
    }
    range[0] = next;
    range[1] = next = std::min(chunks, next + GuidedChunks(chunks - next, size_));
    return true;
  };
  // A result is received without waiting (a large message waits for its sender, busy
  // rendering) and added once it has come.
  struct Incoming {
    std::vector<double> data;
    MPI_Request request;
  };
  std::vector<Incoming> incoming;
  const auto add = [&](const std::vector<double>& buffer) {
    --pending;
    stats += StatsAt(&buffer[3]);
    if (buffer[2] != 0.0) return;  // abandoned at an interrupt: the pixels stay as they were
    const std::size_t first = static_cast<std::size_t>(buffer[0]) * Camera::kChunk;
    const std::size_t last = std::min(count, static_cast<std::size_t>(buffer[1]) * Camera::kChunk);
    for (std::size_t i = first; i < last; ++i) {
      const double* p = &buffer[kHeader + (i - first) * kPerPixel];
      if (p[3] < 0.0) continue;  // done before the resume
      PixelPass pass;
      pass.sum = Colour(p[0], p[1], p[2]);
      pass.samples = static_cast<std::uint64_t>(p[3]);
      camera.PixelAt(i).Add(pass);  // in pass order, as one process adds it
    }
    // Integer sums: the same whatever order the ranges come in (Pixel::AddSplat).
    AddSplats(camera, &buffer[kHeader + (last - first) * kPerPixel]);
  };
  // Answers what the other ranks sent: requests first (small, and a rank waits on
  // them; a tag of their own lets them pass a large result queued before them), then
  // results. Returns whether anything happened.
  const auto serve = [&]() {
    bool any = false;
    MPI_Status status;
    int flag = 0;
    for (const int tag : {kRequest, kDone}) {
      while (MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status), flag) {
        any = true;
        int unused = 0;
        MPI_Recv(&unused, 1, MPI_INT, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (tag == kDone) {
          ++doneWorkers;
          continue;
        }
        ++requests;
        int range[2];
        pending += take(range) ? 1 : 0;
        MPI_Send(range, 2, MPI_INT, status.MPI_SOURCE, kReply, MPI_COMM_WORLD);
        ++messages_;
        bytes_ += sizeof range;
      }
    }
    while (MPI_Iprobe(MPI_ANY_SOURCE, kResult, MPI_COMM_WORLD, &flag, &status), flag) {
      any = true;
      int n = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &n);
      Incoming in{std::vector<double>(static_cast<std::size_t>(n)), MPI_REQUEST_NULL};
      MPI_Irecv(in.data.data(), n, MPI_DOUBLE, status.MPI_SOURCE, kResult, MPI_COMM_WORLD,
                &in.request);
      incoming.push_back(std::move(in));  // the buffer moves with its data in place
    }
    for (std::size_t i = 0; i < incoming.size();) {
      int done = 0;
      MPI_Test(&incoming[i].request, &done, MPI_STATUS_IGNORE);
      if (done) {
        any = true;
        add(incoming[i].data);
        incoming.erase(incoming.begin() + static_cast<std::ptrdiff_t>(i));
      } else {
        ++i;
      }
    }
    return any;
  };
  // Every other rank's first request answered before rank 0 takes a range of its own:
  // the first ranges are the largest.
  while (requests < size_ - 1) serve();
  // Rank 0 answers between the chunks of its own ranges too (its main thread, which MPI
  // was started on, runs the progress callback): a range of the costly rows under the
  // spheres took 52 ms, and a rank that asked meanwhile sat idle (1.73x on 2 ranks).
  RenderOptions mine = options;
  mine.progress = [&](std::size_t done, std::size_t total) {
    if (options.progress) options.progress(done, total);
    serve();
  };
  for (int range[2]; take(range);) {
    stats += camera.RenderChunks(integrator, mine, range[0], range[1]);
    if (betweenBatches && !cancelled()) betweenBatches();
    serve();
  }
  while (pending > 0 || doneWorkers < size_ - 1) serve();  // MPI's own wait polls as well
}

void Cluster::WorkerPass(Camera& camera, const Integrator& integrator,
                         const RenderOptions& options) const {
  const std::size_t count =
      static_cast<std::size_t>(camera.Width()) * static_cast<std::size_t>(camera.Height());
  const auto cancelled = [&]() { return options.cancel && options.cancel->load(); };
  const auto send = [&](const void* data, int n, MPI_Datatype type, std::size_t size, int tag) {
    MPI_Send(data, n, type, 0, tag, MPI_COMM_WORLD);
    ++messages_;
    bytes_ += static_cast<std::uint64_t>(n) * size;
  };
  // Two requests in flight: while this rank renders one range, the answer to its next
  // request waits in the queue, however long rank 0 takes to look at its messages.
  int outstanding = 0;
  const int request = 0;
  for (int i = 0; i < 2; ++i, ++outstanding) send(&request, 1, MPI_INT, sizeof(int), kRequest);
  bool noMore = false;
  // Results go out without waiting, and the next request before them: a large message
  // is sent only when rank 0, busy with its own range, receives it, and a rank that
  // waited for that sat idle (measured: 1.37x on 2 ranks with blocking sends, 1.77x when
  // the request followed the wait for an earlier result's buffer). A buffer is reused
  // once its send is done; until then another one is taken.
  struct Outgoing {
    std::vector<double> data;
    MPI_Request request = MPI_REQUEST_NULL;
  };
  std::vector<Outgoing> outgoing;
  const auto freeBuffer = [&]() -> Outgoing& {
    for (Outgoing& o : outgoing) {
      int done = 0;
      MPI_Test(&o.request, &done, MPI_STATUS_IGNORE);
      if (done) return o;
    }
    outgoing.emplace_back();
    return outgoing.back();
  };
  std::vector<char> skip;
  while (outstanding > 0) {
    int range[2];
    MPI_Recv(range, 2, MPI_INT, 0, kReply, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    --outstanding;
    if (range[0] < 0) {
      noMore = true;
      continue;
    }
    const std::size_t first = static_cast<std::size_t>(range[0]) * Camera::kChunk;
    const std::size_t last = std::min(count, static_cast<std::size_t>(range[1]) * Camera::kChunk);
    // This rank's pixels start each pass empty: rank 0 adds the pass to its own sums.
    skip.assign(last - first, 0);
    for (std::size_t i = first; i < last; ++i) {
      Pixel& pixel = camera.PixelAt(i);
      skip[i - first] = options.skipDone && pixel.Passes() > options.pass ? 1 : 0;
      if (skip[i - first] == 0) pixel.Restore(Colour(0.0), 0, options.pass);
    }
    RenderStats batch;
    if (!cancelled()) batch = camera.RenderChunks(integrator, options, range[0], range[1]);
    if (!noMore && !cancelled()) {
      send(&request, 1, MPI_INT, sizeof(int), kRequest);
      ++outstanding;
    }
    Outgoing& out = freeBuffer();
    std::vector<double>& buffer = out.data;
    buffer.assign(
        {static_cast<double>(range[0]), static_cast<double>(range[1]), cancelled() ? 1.0 : 0.0});
    AppendStats(buffer, batch);
    for (std::size_t i = first; i < last; ++i) {
      const Pixel& pixel = camera.PixelAt(i);
      if (skip[i - first] != 0) {
        buffer.insert(buffer.end(), {0.0, 0.0, 0.0, -1.0});
        continue;
      }
      if (pixel.Passes() != options.pass + 1) buffer[2] = 1.0;  // cut short: abandoned
      const Colour s = pixel.Sum();
      buffer.insert(buffer.end(), {s.x, s.y, s.z, static_cast<double>(pixel.Samples())});
    }
    TakeSplats(camera, buffer);
    MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_DOUBLE, 0, kResult,
              MPI_COMM_WORLD, &out.request);
    ++messages_;
    bytes_ += buffer.size() * sizeof(double);
  }
  for (Outgoing& o : outgoing) {
    MPI_Wait(&o.request, MPI_STATUS_IGNORE);
  }
  send(&request, 1, MPI_INT, sizeof(int), kDone);
}
// NOLINTEND(clang-analyzer-optin.mpi.MPI-Checker)

#else

void Cluster::RootPass(Camera&, const Integrator&, const RenderOptions&, RenderStats&,
                       const std::function<void()>&) const {}
void Cluster::WorkerPass(Camera&, const Integrator&, const RenderOptions&) const {}

#endif

}  // namespace glint
