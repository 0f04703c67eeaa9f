// Benchmarks of the sketch widget's gestures, which cost the same on any mesh: a stroke and a disc drawn on a view's
// depth image.
//
// The view: 1300 x 770 pixels (the render view of a 1600 x 1000 ParaView window) showing a sphere
// of radius 0.5 filling its height, seen by an orthographic camera; the depth image is computed
// analytically once, and a pixel goes back to space through a display-to-world matrix
// (kerf::DepthImage::projective), as the widget's do.
//   BM_SketchStroke/1300x770   a drag of 900 pixels in 30 mouse moves across the sphere and back
//                              onto the background: kerf::SurfaceStrokeTracer, then
//                              kerf::simplifyPolyline to half a pixel (the widget's whole work
//                              between the press and the release, but for the depth read)
//   BM_SketchDiscMove/1300x770 one mouse move of a disc drag: kerf::dragRadius and the rim of 64
//                              walks (kerf::discRim) for a disc reaching a third of the sphere
#include "KerfBenchmarks.h"

#include "Sketch/SurfaceSketch.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace
{
constexpr int Width = 1300;
constexpr int Height = 770;
constexpr double Radius = 0.5;
// World units per pixel: the sphere's diameter spans 700 of the 770 rows.
constexpr double Scale = 2.0 * Radius / 700.0;

kerf::DepthImage sphereView()
{
  std::vector<float> depth(static_cast<std::size_t>(Width) * Height, 1.0f);
  for (int row = 0; row < Height; ++row)
  {
    for (int column = 0; column < Width; ++column)
    {
      const double x = (column - 0.5 * Width) * Scale;
      const double y = (row - 0.5 * Height) * Scale;
      const double h = Radius * Radius - x * x - y * y;
      if (h >= 0.0)
      {
        depth[static_cast<std::size_t>(row) * Width + column] = static_cast<float>(0.5 - 0.5 * std::sqrt(h));
      }
    }
  }
  Eigen::Matrix4d displayToWorld = Eigen::Matrix4d::Identity();
  displayToWorld(0, 0) = Scale;
  displayToWorld(0, 3) = -0.5 * Width * Scale;
  displayToWorld(1, 1) = Scale;
  displayToWorld(1, 3) = -0.5 * Height * Scale;
  displayToWorld(2, 2) = -2.0;
  displayToWorld(2, 3) = 1.0;
  return kerf::DepthImage(Width, Height, std::move(depth), kerf::DepthImage::projective(displayToWorld));
}

const kerf::DepthImage& view()
{
  static const kerf::DepthImage image = sphereView();
  return image;
}

void sketchStroke(benchmark::State& state)
{
  const kerf::DepthImage& image = view();
  std::size_t points = 0;
  for (auto _ : state)
  {
    kerf::SurfaceStrokeTracer tracer(image, 200, 385);
    for (int i = 1; i <= 30; ++i)
    {
      tracer.moveTo(200 + 30.0 * i, 385 + 40.0 * std::sin(0.2 * i));
    }
    points = 0;
    for (const std::vector<kerf::Vector3>& piece : tracer.pieces())
    {
      points += kerf::simplifyPolyline(piece, 0.5 * Scale).size();
    }
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = static_cast<double>(points);
  if (points < 10)
  {
    state.SkipWithError("the stroke did not cross the sphere");
  }
}

void sketchDiscMove(benchmark::State& state)
{
  const kerf::DepthImage& image = view();
  double radius = 0.0;
  std::size_t rim = 0;
  for (auto _ : state)
  {
    radius = kerf::dragRadius(image, 650, 385, 650, 385 + 150);
    rim = kerf::discRim(image, 650, 385, radius).size();
    benchmark::DoNotOptimize(rim);
  }
  state.counters["radius"] = radius;
  if (rim != 64 || !(radius > 0.1))
  {
    state.SkipWithError("the disc has no rim");
  }
}
} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterSketchBenchmarks()
{
  benchmark::RegisterBenchmark("BM_SketchStroke/1300x770", sketchStroke)->Unit(benchmark::kMillisecond)->UseRealTime();
  benchmark::RegisterBenchmark("BM_SketchDiscMove/1300x770", sketchDiscMove)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
}

} // namespace benchmarks
} // namespace kerf
