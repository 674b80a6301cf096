// `luz bench whitted`. For each scene: one untimed render that keeps every ray it traced (and
// sizes every thread's scratch queues and wakes TBB's workers), then N rounds of the full render
// followed by those rays traced bare through the same Embree scene on the same TBB threads and
// in the same calls as the renderer (--renderer) made them: each stream of rays (the wavefront's
// every generation, a kind of ray at a time; the recursion's first generation of a tile) as one
// stream, every other ray on its own. render / bare is how close the tracer comes to Embree's
// limit on this machine; what it spends beyond is shading, sampling and bookkeeping.
#include "app/cli/bench/bench_command.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <span>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <tbb/info.h>

#include "app/cli/bench/bench_scenes.h"
#include "app/cli/bench/bench_table.h"
#include "app/cli/render_command.h"
#include "app/common/i18n.h"
#include "app/common/options_tables.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "raytracing/renderer.h"
#include "raytracing/sampling.h"

namespace luz::app {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Slide 24's ray kinds as the rows under a scene name them, indexed by RayKind.
constexpr const char* kKindLabels[rt::kRayKinds] = {N_("primary"), N_("shadow"), N_("reflected"),
                                                    N_("transmitted")};

// The rays of one kind as the renderer handed them to Embree: the rays, and the calls it made
// (a stream, or a ray on its own).
struct BareRays {
  struct Call {
    size_t first, count;
    bool stream;
  };
  std::vector<rt::Ray> rays;
  std::vector<Call> calls;
};

std::array<BareRays, rt::kRayKinds> bare_rays(std::span<const rt::RecordedRay> recorded) {
  std::array<BareRays, rt::kRayKinds> by_kind;
  for (const rt::RecordedRay& r : recorded) {
    BareRays& kind = by_kind[size_t(r.kind)];
    if (r.traced != rt::Traced::in_stream || kind.calls.empty())
      kind.calls.push_back({kind.rays.size(), 0, r.traced != rt::Traced::alone});
    ++kind.calls.back().count;
    kind.rays.push_back(r.ray);
  }
  return by_kind;
}

// The rays of one kind traced bare in the renderer's calls: no shading, no recursion, no counters.
double trace_bare(const rt::Intersector& embree, const BareRays& bare, rt::RayKind kind) {
  const auto start = Clock::now();
  parallel_for(size_t(0), bare.calls.size(), [&](size_t c) {
    thread_local std::vector<rt::Hit> hits;
    thread_local rt::BlockedFlags blocked;
    const BareRays::Call& call = bare.calls[c];
    const std::span<const rt::Ray> part = std::span(bare.rays).subspan(call.first, call.count);
    uint64_t tests = 0;
    if (!call.stream) {
      if (kind == rt::RayKind::shadow)
        (void)embree.occluded(part[0], tests);
      else
        (void)embree.intersect(part[0], tests);
    } else if (kind == rt::RayKind::shadow) {
      embree.occluded(part, blocked.first(part.size()), tests);
    } else {
      hits.resize(part.size());
      embree.intersect(part, hits, tests);
    }
  });
  return seconds_since(start);
}

}  // namespace

void add_bench_flags(CLI::App& bench, WhittedBenchSettings& settings) {
  bench.add_option_function<std::string>(
      "--size",
      [&settings](const std::string& text) {
        if (!parse_size(text, settings.width, settings.height))
          throw CLI::ValidationError("--size", tr("expected WxH, e.g. 1920x1080"));
      },
      tr("Image size WxH (default 1920x1080)"));
  bench.add_option("--depth", settings.depth, tr("Maximum ray depth (slide 26)"))
      ->check(CLI::Range(1, 64))->capture_default_str();
  bench.add_option("--spp", settings.spp, tr("Samples per pixel (a square)"))
      ->check(CLI::Validator([](std::string& text) {  // as luz render's --spp
        int n = 0;
        if (!CLI::detail::lexical_cast(text, n) || !rt::is_square(n) || n > 4096)
          return std::string(tr("expected a square number of samples: 1, 4, 9, 16, ... (at most 4096)"));
        return std::string();
      }, "SQUARE"))->capture_default_str();
  bench.add_option("--repeats", settings.repeats, tr("Best of this many runs"))
      ->check(CLI::Range(1, 100))->capture_default_str();
  // The render's own --renderer row (options_tables.cpp): the same names, help and check.
  const WhittedRow& renderer = *find_row(whitted_rows(), "renderer");
  bench.add_option_function<std::string>(
           "--renderer",
           [&settings, &renderer](const std::string& text) {
             const std::optional<double> value = parse_value(renderer, text);
             if (!value)
               throw CLI::ValidationError("--renderer", trf("{}: expected {}", text, accepted_text(renderer, Wording::translated)));
             settings.renderer = rt::RendererKind(int(*value));
           },
           trf("{} ({}; default {})", tr(renderer.help), accepted_text(renderer, Wording::translated),
               default_text(renderer)))
      ->type_name("wavefront|recursive");
  bench.add_option("--scenes", settings.scenes, tr("Shipped scene names or glTF paths"))
      ->delimiter(',')->capture_default_str();
}

int run_bench_whitted(const WhittedBenchSettings& settings) {
  try {
    const std::vector<BenchScene> scenes = load_bench_scenes(settings.scenes);
    fmt::print("{}\n", trf("luz bench whitted: {}x{}, depth {}, {} spp, best of {}; {} threads on {}",
                            settings.width, settings.height, settings.depth, settings.spp,
                            settings.repeats, tbb::info::default_concurrency(), cpu_model()));
    // The tracer's figures, then the same rays bare, then render / bare.
    const BenchTable table({{.header = tr("scene"), .width = 14, .left = true},
                            {.header = tr("render s"), .width = 9},
                            {.header = tr("median s"), .width = 9},
                            {.header = tr("rays"), .width = 10},
                            {.header = tr("Mrays/s"), .width = 9, .bar_after = true},
                            {.header = tr("bare s"), .width = 9},
                            {.header = tr("Mrays/s"), .width = 9, .bar_after = true},
                            {.header = tr("ratio"), .width = 6}});
    fmt::print("{}\n", trf("renderer: {}", find_row(whitted_rows(), "renderer")->choices[size_t(settings.renderer)]));
    fmt::print("{}", table.header());
    for (const auto& [name, loaded] : scenes) {
      const Scene& scene = loaded.scene;
      const Camera& camera = scene.cameras.front();
      rt::WhittedOptions options;
      options.max_depth = settings.depth;
      options.spp = settings.spp;
      options.renderer = settings.renderer;

      auto start = Clock::now();
      rt::WhittedRenderer tracer(scene);
      const double build = seconds_since(start);

      // Untimed, keeping every ray it traces for the bare runs: the first render of a process also
      // pays for its threads' start and their scratch queues' first growth (about 5% at
      // 1024x1024), which a benchmark of the tracer leaves out.
      tracer.keep_rays(true);
      tracer.render(camera, settings.width, settings.height, options);
      tracer.keep_rays(false);
      const std::array<BareRays, rt::kRayKinds> by_kind = bare_rays(tracer.take_rays());

      // Rounds of one render, then its rays bare: a machine whose speed drifts from minute to
      // minute (a shared virtual machine) slows both alike, and each round gives a ratio.
      double render = 1e30;
      rt::Counters counters;
      std::vector<double> times, ratios;
      std::array<double, rt::kRayKinds> bare{};
      bare.fill(1e30);
      for (int r = 0; r < settings.repeats; ++r) {
        tracer.render(camera, settings.width, settings.height, options);
        const double seconds = tracer.counters().seconds;
        times.push_back(seconds);
        if (seconds < render) {
          render = seconds;
          counters = tracer.counters();
        }
        double round_bare = 0.0;
        for (int k = 0; k < rt::kRayKinds; ++k) {
          const double t = trace_bare(tracer.intersector(options), by_kind[size_t(k)], rt::RayKind(k));
          bare[size_t(k)] = std::min(bare[size_t(k)], t);
          round_bare += t;
        }
        ratios.push_back(seconds / round_bare);
      }
      const double median = best_and_median(times).median;
      double bare_total = 0.0;
      for (double b : bare) bare_total += b;
      const double rays = double(counters.total_rays());
      fmt::print("{}", table.row({name, fmt::format("{:.4f}", render), fmt::format("{:.4f}", median),
                                  fmt::format("{:.2f}M", rays * 1e-6),
                                  fmt::format("{:.2f}", rays / render * 1e-6), fmt::format("{:.4f}", bare_total),
                                  fmt::format("{:.2f}", rays / bare_total * 1e-6),
                                  fmt::format("{:.2f}", render / bare_total)}));
      for (int k = 0; k < rt::kRayKinds; ++k) {
        const double n = double(by_kind[size_t(k)].rays.size());
        fmt::print("{}\n", trf("  {:<12} {:>10} rays, bare {:7.2f} Mrays/s", tr(kKindLabels[k]),
                                by_kind[size_t(k)].rays.size(),
                                bare[size_t(k)] > 0 ? n / bare[size_t(k)] * 1e-6 : 0.0));
      }
      const Timing round_ratio = best_and_median(ratios);
      fmt::print("{}\n", trf("  render / bare of each round: best {:.2f}, median {:.2f}", round_ratio.best,
                              round_ratio.median));
      fmt::print("{}\n", trf("  BVH build {:.3f} s", build));
    }
    return 0;
  } catch (const Error& error) {
    fmt::print(stderr, "luz: {}\n", error.what());
    return error.kind == ErrorKind::usage ? 2 : 1;
  }
}

}  // namespace luz::app
