// Frame cost of the polar view under whatever OpenGL the display offers (Mesa llvmpipe under
// xvfb-run in CI): the analytic grid pass, the point pass at 2k / 20k / 200k points, and the CPU
// side that builds the vertex array. Run: xvfb-run -a -s "-screen 0 1280x800x24" bench_frame
// Each GPU iteration ends with glFinish so the time is the work, not the queueing.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "ui/render/polar_renderer.h"
#include "ui/render/sprite_splat.h"
#include "ui/view/geometry/grid_geometry.h"
#include "ui/view/geometry/grid_layout.h"
#include "ui/view/scene/lap_history.h"
#include "ui/view/scene/pixel_merge.h"
#include "ui/view/scene/source_cloud.h"
#include "ui/view/scene/source_clouds.h"
#include "ui/view/scene/point_cloud.h"

namespace {

using namespace ydscope;
using namespace ydscope::ui;

constexpr int kWidth = 1280;
constexpr int kHeight = 800;

// One hidden 1280x800 GL 3.3 core window for the whole run.
struct GlWindow {
  GLFWwindow* window = nullptr;
  std::unique_ptr<PolarRenderer> renderer;  // sprites drawn as GL points
  std::unique_ptr<PolarRenderer> on_cpu;    // sprites drawn on the CPU and laid as a picture
  GlWindow() {
    if (!std::getenv("DISPLAY") || !glfwInit()) return;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    window = glfwCreateWindow(kWidth, kHeight, "bench", nullptr, nullptr);
    if (!window) return;
    glfwMakeContextCurrent(window);
    glfwSwapInterval(0);
    renderer = std::make_unique<PolarRenderer>(PointDrawing::gl);
    on_cpu = std::make_unique<PolarRenderer>(PointDrawing::cpu);
  }
  ~GlWindow() {
    renderer.reset();
    on_cpu.reset();
    if (window) glfwDestroyWindow(window);
    glfwTerminate();
  }
};

GlWindow& gl() {
  static GlWindow instance;
  return instance;
}

// A room-like lap of `n` points: walls at 3-6 m with some texture.
Lap make_lap(std::size_t n, std::uint64_t index) {
  Lap lap;
  lap.index = index;
  lap.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float a = 360.0f * static_cast<float>(i) / static_cast<float>(n);
    const float r =
        3000.0f + 1500.0f * std::fabs(std::sin(a * 0.05f)) + 40.0f * std::sin(a * 3.1f + static_cast<float>(index));
    lap.points[i] = {a, r, PointFlag::None};
  }
  return lap;
}

ViewTransform make_view() {
  ViewTransform view;
  view.set_viewport({430.0f, 0.0f}, {static_cast<float>(kWidth - 430), static_cast<float>(kHeight)});
  view.fit_range(6500.0f);
  return view;
}

// `points` in total spread over 10 laps of persistence, as the app shows them, the first of index
// `first_lap` (laps of other indices land a little apart).
void fill_history(LapHistory& history, std::size_t points, std::uint64_t first_lap = 0) {
  history.set_depth(10);
  for (std::uint64_t i = 0; i < 10; ++i) history.push(make_lap(points / 10, first_lap + i));
}

void BM_BuildCloud(benchmark::State& state) {
  LapHistory history;
  fill_history(history, static_cast<std::size_t>(state.range(0)));
  FadingCloud cloud;
  for (auto _ : state) {
    build_point_cloud(history, ColourParams{}, InterferenceSettings{}, cloud);
    benchmark::DoNotOptimize(cloud.vertices.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BuildCloud)->Arg(2000)->Arg(20000)->Arg(200000)->Unit(benchmark::kMillisecond);

// A lidar of several: its layer's cloud built and posed (3 m out, turned), as each of its laps asks.
// A layer's ten laps posed and put together, all built (as after a change of colours), or with
// only its newest lap built (as at each of its laps).
void BM_BuildPosedLayer(benchmark::State& state) {
  LapHistory history;
  fill_history(history, static_cast<std::size_t>(state.range(0)));
  const bool new_lap_only = state.range(1) != 0;
  const Lap next = make_lap(static_cast<std::size_t>(state.range(0)) / 10, 10);
  SourceLayer layer;
  layer.history = &history;
  layer.pose = {3.0, -1.5, 120.0, false, 2.0};
  SourceClouds clouds;
  clouds.update({&layer, 1}, ColourParams{}, InterferenceSettings{}, true);
  for (auto _ : state) {
    if (new_lap_only) history.push(next);
    clouds.update({&layer, 1}, ColourParams{}, InterferenceSettings{}, !new_lap_only);
    benchmark::DoNotOptimize(clouds.cloud().vertices.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BuildPosedLayer)->Args({20000, 0})->Args({20000, 1})->Unit(benchmark::kMillisecond);

// What a frame between laps pays: the cloud built once, faded again for a new phase.
void BM_FadeCloud(benchmark::State& state) {
  LapHistory history;
  fill_history(history, static_cast<std::size_t>(state.range(0)));
  FadingCloud cloud;
  build_point_cloud(history, ColourParams{}, InterferenceSettings{}, cloud);
  float phase = 0.0f;
  for (auto _ : state) {
    phase = phase >= 1.0f ? 0.0f : phase + 0.03f;
    fade_cloud(cloud, ColourParams{}, phase);
    benchmark::DoNotOptimize(cloud.vertices.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_FadeCloud)->Arg(20000)->Arg(200000)->Unit(benchmark::kMillisecond);

// What a lap costs the pixel merge: every point put in its pixel's stack again (the grouping),
// then the stacks laid. Two clouds of different laps alternate, so each iteration groups anew; the
// copy of the cloud the merge replaces is counted too.
void BM_PixelMergeGrouping(benchmark::State& state) {
  FadingCloud clouds[2];
  for (std::uint64_t k = 0; k < 2; ++k) {
    LapHistory history;
    fill_history(history, static_cast<std::size_t>(state.range(0)), k * 10);
    build_point_cloud(history, ColourParams{}, InterferenceSettings{}, clouds[k]);
  }
  const float cell_mm = 1.0f / make_view().px_per_mm();
  PixelMerger merger;
  std::vector<PointVertex> vertices;
  std::size_t which = 0;
  for (auto _ : state) {
    vertices = clouds[which ^= 1].vertices;
    merger.merge(vertices, cell_mm);
    benchmark::DoNotOptimize(vertices.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_PixelMergeGrouping)->Arg(20000)->Arg(200000)->Unit(benchmark::kMillisecond);

// The sprites drawn on the CPU (a software renderer's path): a cloud of the persistence, merged as
// the app merges it, painted into the view's picture as a frame paints it.
void BM_SpriteSplat(benchmark::State& state) {
  LapHistory history;
  fill_history(history, static_cast<std::size_t>(state.range(0)));
  FadingCloud cloud;
  build_point_cloud(history, ColourParams{}, InterferenceSettings{}, cloud);
  const ViewTransform view = make_view();
  std::vector<PointVertex> vertices = cloud.vertices;
  PixelMerger merger;
  merger.merge(vertices, 1.0f / view.px_per_mm());
  const NdcTransform ndc = view.ndc_transform();
  const SplatFrame frame{ndc.scale_x,
                         ndc.scale_y,
                         ndc.offset_x,
                         ndc.offset_y,
                         static_cast<int>(view.viewport_size().x),
                         static_cast<int>(view.viewport_size().y),
                         3.0f};
  SpriteSplat splat;
  for (auto _ : state) {
    splat.paint(vertices, frame);
    benchmark::DoNotOptimize(splat.pixels());
  }
  state.counters["sprites"] = static_cast<double>(vertices.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(vertices.size()));
}
BENCHMARK(BM_SpriteSplat)->Arg(20000)->Arg(200000)->Unit(benchmark::kMillisecond);

// Motion highlighting's share: the cloud built in motion colours against a learned room, and the
// learning itself, once per lap.
void BM_BuildCloudWithMotion(benchmark::State& state) {
  LapHistory history;
  fill_history(history, static_cast<std::size_t>(state.range(0)));
  MotionBackground motion;
  for (std::uint64_t i = 0; i < MotionBackground::kLaps; ++i)
    motion.add_lap(make_lap(static_cast<std::size_t>(state.range(0)) / 10, i));
  ColourParams colours;
  colours.mode = ColourMode::Motion;
  FadingCloud cloud;
  for (auto _ : state) {
    build_point_cloud(history, colours, InterferenceSettings{}, cloud, &motion);
    benchmark::DoNotOptimize(cloud.vertices.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BuildCloudWithMotion)->Arg(20000)->Unit(benchmark::kMillisecond);

void BM_MotionLearnsALap(benchmark::State& state) {
  MotionBackground motion;
  const Lap lap = make_lap(static_cast<std::size_t>(state.range(0)), 1);
  for (auto _ : state) motion.add_lap(lap);
}
BENCHMARK(BM_MotionLearnsALap)->Arg(2000)->Unit(benchmark::kMillisecond);

// draw_grid: 0 points only, 1 grid + points. Uploads a fresh cloud every frame, as with a new lap.
// The second argument: 0 the sprites drawn as GL points, 1 on the CPU (the software renderer's
// path). Timed as the process's CPU, so llvmpipe's raster threads count.
void frame_bench(benchmark::State& state, bool draw_grid, bool draw_points) {
  GlWindow& g = gl();
  if (!g.renderer) {
    state.SkipWithError("no OpenGL 3.3 window (no DISPLAY?); run under xvfb-run");
    return;
  }
  PolarRenderer& renderer = state.range(1) == 0 ? *g.renderer : *g.on_cpu;
  LapHistory history;
  fill_history(history, static_cast<std::size_t>(state.range(0)));
  FadingCloud faded;
  build_point_cloud(history, ColourParams{}, InterferenceSettings{}, faded);
  fade_cloud(faded, ColourParams{}, 0.0f);
  std::vector<PointVertex> cloud = std::move(faded.vertices);
  const ViewTransform view = make_view();
  const GridLayout grid = layout_grid(view);
  PolarStyle style;
  style.show_grid = draw_grid;
  std::vector<LineVertex> lines;
  build_grid_geometry(view, grid, style.grid, lines);
  renderer.upload_grid(lines);
  if (!draw_points) cloud.clear();
  for (auto _ : state) {
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.03f, 0.04f, 0.06f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    renderer.upload_points(cloud);
    for (const GlLayer layer : {GlLayer::grid, GlLayer::points}) renderer.draw(view, style, 1.0f, kHeight, layer);
    glFinish();
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_GridOnly(benchmark::State& state) { frame_bench(state, true, false); }
void BM_PointsOnly(benchmark::State& state) { frame_bench(state, false, true); }
void BM_GridAndPoints(benchmark::State& state) { frame_bench(state, true, true); }
BENCHMARK(BM_GridOnly)->Args({0, 0})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_PointsOnly)
    ->ArgsProduct({{2000, 20000, 200000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_GridAndPoints)
    ->ArgsProduct({{2000, 20000, 200000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
