// Benchmarks of the geodesics family: heat-method set-up and sources, paths beside VTK's Dijkstra path and CGAL's heat
// method, seams, ROI Scissor.
//
// Surfaces: the harmonic-cut benchmark's dumbbell (half length 2.2, lobe radii 1 and 0.8, neck at
// 0.3 pinched by 0.65) from a subdivided cube (kerf::benchmarks::MakeCubeDumbbell) with 22,188,
// 99,372 and 1,002,252 triangles, and for the errors the unit icosphere of 81,920 triangles
// (40,962 vertices) against great-circle distances. For each size:
//   BM_HeatSetup/<size>          kerf::HeatGeodesics with its default options, what a user gets:
//                                intrinsic Delaunay flips, one analysis with the automatic ordering
//                                (AMD at 22k and 100k, the geometric nested dissection at 1M),
//                                two numeric factorizations
//   BM_HeatSetupAMD/<size>       the same with AMD ordering
//   BM_HeatSetupMetis/<size>     the same with METIS ordering
//   BM_HeatSetupGeometric/<size> the same with the geometric nested dissection
//   BM_HeatSource/<size>         one new source vertex (distance and face gradients)
//   BM_VTKDijkstraPath/<size>    vtkDijkstraGraphGeodesicPath, one path between two vertices on a
//                                new filter (its graph built each time), for reference; counter
//                                length, the path's (along edges)
//   BM_GeodesicPolylineFirst/<size>  kerf::shortestPath between the same two vertices as VTK's path on a
//                                new kerf::Surface: the heat set-up, one distance and the streamline
//                                (every size; at 1M several seconds)
//   BM_GeodesicPolyline/<size>       the same path with the surface's heat set-up kept (a new path)
//   BM_GeodesicPolylineAnisotropic/<size>  the same path under the anisotropic metric (gamma = 1, Short-
//                                Term Vector Dijkstra), the surface's curvature and metric kept
//   BM_CGALHeatSetup/<size>      CGAL's Heat_method_3 (Direct), construction with one source and
//                                its first estimate (22k and 100k only: 43 s at 1M)
//   BM_CGALHeatSource/<size>     CGAL: a new source and its estimate
//   BM_SeamNew/<size>            kerf::SeamField from the neck's isoline (gamma = 1, Short-Term
//                                Vector Dijkstra) and one seam
//   BM_SeamRegrowth/<size>       a seam to a new target on the same field
//   BM_RoiScissorClick/<size>    kerf::roiScissor with a disc covering 10% of the vertices, the
//                                surface's heat set-up, curvature and weights already cached
//   BM_GeodesicDiscClick/<size>  kerf::geodesicDiscs, the same click's disc alone (a new click:
//                                one heat distance and the region), the heat set-up cached;
//                                counter area_fraction
//   BM_GeodesicDiscRadius/<size> the same disc with the click's distance kept (kerf::ClickDistances,
//                                as the filters keep it): a new radius
// and once:
//   BM_SphereErrorKerf, BM_SphereErrorCGAL, BM_SphereErrorCGALIntrinsic: one source on the
//   icosphere, with counters mean_error and max_error (relative, outside the source's one-ring).
#include "BenchmarkMeshes.h"
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"

#include "Geodesic/GeodesicPaths.h"
#include "Geodesic/GeodesicSeam.h"
#include "Geodesic/HeatGeodesics.h"
#include "Geodesic/ROIScissor.h"
#include "Geometry/ClosestPoint.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshGenerators.h"
#include "Surface/Surface.h"

#include <benchmark/benchmark.h>

#include <vtkDijkstraGraphGeodesicPath.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#ifdef KERF_HAVE_CGAL
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace
{
using kerf::benchmarks::Fail;

constexpr double HalfLength = 2.2;
const std::array<double, 2> LobeRadii = { { 1.0, 0.8 } };
constexpr double NeckCentre = 0.3;
constexpr double NeckDepth = 0.65;

struct GeodesicSize
{
  const char* label;
  int cells;
  double minimumSeconds;
};
const std::array<GeodesicSize, 3> Sizes = { { { "22k", 43, 0.5 }, { "100k", 91, 1.0 }, { "1M", 289, 2.0 } } };

// One size's surface, kept while its benchmarks run.
struct Scene
{
  std::shared_ptr<kerf::Surface> surface;
  vtkSmartPointer<vtkPolyData> polyData;
  kerf::SurfaceCurve neck;
  std::vector<kerf::SurfacePoint> targets;
  kerf::ROIClick click;
};

const Scene& sceneFor(const GeodesicSize& size)
{
  static std::map<int, std::unique_ptr<Scene>> scenes;
  auto found = scenes.find(size.cells);
  if (found != scenes.end())
  {
    return *found->second;
  }
  scenes.clear(); // one size at a time
  auto scene = std::make_unique<Scene>();
  scene->surface = std::make_shared<kerf::Surface>(
    kerf::benchmarks::MakeCubeDumbbell(HalfLength, LobeRadii, NeckCentre, NeckDepth, size.cells));
  const kerf::TriangleMesh& mesh = scene->surface->mesh();
  scene->polyData = kerf::benchmarks::MakePolyData(mesh);
  std::vector<double> height(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    height[v] = mesh.point(v).z();
  }
  const kerf::Isoline neck = kerf::extractIsolines(mesh, height, NeckCentre).at(0);
  scene->neck.points = neck.points;
  scene->neck.faces = neck.faces;
  scene->neck.closed = neck.closed;
  for (double angle : { 0.4, 2.5 })
  {
    const double z = 1.4;
    const double r = kerf::dumbbellRadius(z, HalfLength, LobeRadii, NeckCentre, NeckDepth);
    const kerf::ClosestPointLocator::Hit hit =
      scene->surface->locator().closest(kerf::Vector3(r * std::cos(angle), r * std::sin(angle), z));
    scene->targets.push_back({ hit.face, hit.barycentric });
  }
  // A click at the top whose disc holds 10% of the vertices.
  const kerf::Vector3 top(0.0, 0.0, HalfLength);
  const kerf::ClosestPointLocator::Hit hit = scene->surface->locator().closest(top);
  kerf::GeodesicSource source;
  source.points = { { hit.face, hit.barycentric } };
  std::vector<double> distance = kerf::HeatGeodesics::of(*scene->surface).compute(source).distance;
  std::nth_element(distance.begin(), distance.begin() + distance.size() / 10, distance.end());
  scene->click = { hit.position, distance[distance.size() / 10] };
  return *scenes.emplace(size.cells, std::move(scene)).first->second;
}

// Relative errors against great-circle distances on the unit sphere, outside the one-ring of s.
void sphereErrors(benchmark::State& state, const kerf::TriangleMesh& sphere, const std::vector<double>& distance, int s)
{
  double sum = 0.0, maximum = 0.0;
  int count = 0;
  const kerf::IndexRange ring = sphere.vertexNeighbors(s);
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    if (v == s || std::find(ring.begin(), ring.end(), v) != ring.end())
    {
      continue;
    }
    const double exact = std::acos(std::clamp(sphere.point(v).dot(sphere.point(s)), -1.0, 1.0));
    const double error = std::abs(distance[v] - exact) / exact;
    sum += error;
    maximum = std::max(maximum, error);
    ++count;
  }
  state.counters["mean_error"] = sum / count;
  state.counters["max_error"] = maximum;
}

const kerf::TriangleMesh& errorSphere()
{
  static const kerf::TriangleMesh sphere = kerf::makeIcosphere(1.0, 6);
  return sphere;
}
constexpr int SphereSource = 1000;

void heatSetup(benchmark::State& state, const Scene& scene, kerf::CholeskyOrdering ordering)
{
  kerf::HeatGeodesicOptions options;
  options.ordering = ordering;
  for (auto _ : state)
  {
    kerf::HeatGeodesics heat(scene.surface->mesh(), options);
    benchmark::DoNotOptimize(heat.timeStep());
  }
}

void heatSource(benchmark::State& state, const Scene& scene)
{
  const kerf::HeatGeodesics& heat = kerf::HeatGeodesics::of(*scene.surface);
  int source = 0;
  for (auto _ : state)
  {
    kerf::GeodesicSource from;
    from.vertices = { source };
    source = (source + 7919) % scene.surface->mesh().vertexCount();
    benchmark::DoNotOptimize(heat.compute(from).distance.data());
  }
}

void vtkDijkstraPath(benchmark::State& state, const Scene& scene)
{
  const int last = static_cast<int>(scene.polyData->GetNumberOfPoints()) - 1;
  double length = 0.0;
  for (auto _ : state)
  {
    vtkNew<vtkDijkstraGraphGeodesicPath> path;
    path->SetInputData(scene.polyData);
    path->SetStartVertex(0);
    path->SetEndVertex(last);
    path->Update();
    vtkPolyData* line = path->GetOutput();
    length = 0.0;
    for (vtkIdType i = 1; i < line->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      line->GetPoint(i - 1, a);
      line->GetPoint(i, b);
      length += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
    }
    benchmark::DoNotOptimize(length);
  }
  state.counters["length"] = length;
}

// kerf::shortestPath between the vertices vtkDijkstraPath joins, on `surface`.
double geodesicPath(const kerf::Surface& surface, const kerf::GeodesicPathOptions& options)
{
  const kerf::TriangleMesh& mesh = surface.mesh();
  return kerf::shortestPath(
    surface, kerf::vertexSurfacePoint(mesh, 0), kerf::vertexSurfacePoint(mesh, mesh.vertexCount() - 1), options)
    .length;
}

void geodesicPathFirst(benchmark::State& state, const Scene& scene)
{
  for (auto _ : state)
  {
    const kerf::Surface fresh(scene.surface->mesh());
    benchmark::DoNotOptimize(geodesicPath(fresh, kerf::GeodesicPathOptions()));
  }
}

void geodesicPathKept(benchmark::State& state, const Scene& scene, double gamma)
{
  kerf::GeodesicPathOptions options;
  options.metric.gamma = gamma;
  double length = geodesicPath(*scene.surface, options); // the surface's caches
  for (auto _ : state)
  {
    length = geodesicPath(*scene.surface, options);
    benchmark::DoNotOptimize(length);
  }
  state.counters["length"] = length;
}

void seamNew(benchmark::State& state, const Scene& scene)
{
  kerf::SeamOptions options;
  options.metric.gamma = 1.0;
  scene.surface->descriptors(); // curvature is per surface, computed once
  for (auto _ : state)
  {
    const kerf::SeamField field(*scene.surface, scene.neck, options);
    benchmark::DoNotOptimize(field.seam(scene.targets[0]).length);
  }
}

void seamRegrowth(benchmark::State& state, const Scene& scene)
{
  kerf::SeamOptions options;
  options.metric.gamma = 1.0;
  const kerf::SeamField field(*scene.surface, scene.neck, options);
  std::size_t next = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(field.seam(scene.targets[next]).length);
    next = 1 - next;
  }
}

void roiScissorClick(benchmark::State& state, const Scene& scene)
{
  kerf::roiScissor(*scene.surface, { scene.click }); // the surface's caches
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(kerf::roiScissor(*scene.surface, { scene.click }).faceLabels.data());
  }
  state.counters["radius"] = scene.click.radius;
}

void geodesicDiscClick(benchmark::State& state, const Scene& scene, bool keepDistances)
{
  kerf::ClickDistances distances(scene.surface);
  const auto disc = [&]() {
    return kerf::geodesicDiscs(
      *scene.surface, { scene.click }, {}, 1e-3, kerf::HeatGeodesicOptions(), keepDistances ? &distances : nullptr);
  };
  kerf::GeodesicDiscs discs = disc(); // the heat set-up, and the click's distance when kept
  for (auto _ : state)
  {
    discs = disc();
    benchmark::DoNotOptimize(discs.faces.data());
  }
  state.counters["area_fraction"] = discs.area / discs.surfaceArea;
}

#ifdef KERF_HAVE_CGAL
using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using CgalVertex = CgalMesh::Vertex_index;

CgalMesh toCgal(const kerf::TriangleMesh& mesh)
{
  CgalMesh out;
  std::vector<CgalVertex> vertices;
  for (const kerf::Vector3& p : mesh.points())
  {
    vertices.push_back(out.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  }
  for (const kerf::Triangle& t : mesh.triangles())
  {
    out.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
  }
  return out;
}

template <typename Mode>
std::vector<double> cgalDistances(const CgalMesh& mesh, int source)
{
  auto map = const_cast<CgalMesh&>(mesh).add_property_map<CgalVertex, double>("v:distance", 0.0).first;
  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<CgalMesh, Mode> heat(mesh);
  heat.add_source(CgalVertex(source));
  heat.estimate_geodesic_distances(map);
  std::vector<double> result;
  for (CgalVertex v : mesh.vertices())
  {
    result.push_back(map[v]);
  }
  const_cast<CgalMesh&>(mesh).remove_property_map(map);
  return result;
}

void cgalSetup(benchmark::State& state, const Scene& scene)
{
  const CgalMesh mesh = toCgal(scene.surface->mesh());
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(cgalDistances<CGAL::Heat_method_3::Direct>(mesh, 0).data());
  }
}

void cgalSource(benchmark::State& state, const Scene& scene)
{
  CgalMesh mesh = toCgal(scene.surface->mesh());
  auto map = mesh.add_property_map<CgalVertex, double>("v:distance", 0.0).first;
  CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<CgalMesh> heat(mesh);
  int source = 0;
  heat.add_source(CgalVertex(source));
  heat.estimate_geodesic_distances(map);
  for (auto _ : state)
  {
    heat.clear_sources();
    source = (source + 7919) % static_cast<int>(mesh.number_of_vertices());
    heat.add_source(CgalVertex(source));
    heat.estimate_geodesic_distances(map);
    benchmark::DoNotOptimize(map[CgalVertex(0)]);
  }
}
#endif

void run(
  benchmark::State& state, const GeodesicSize* size, const std::function<void(benchmark::State&, const Scene&)>& body)
{
  try
  {
    body(state, sceneFor(*size));
  }
  catch (const std::exception& e)
  {
    Fail(state, e.what());
  }
}
} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterGeodesicsBenchmarks(bool useSizeMinimumTimes)
{
  using Body = std::function<void(benchmark::State&, const Scene&)>;
  std::vector<std::pair<std::string, Body>> benchmarks = {
    { "BM_HeatSetup", [](benchmark::State& s, const Scene& c) { heatSetup(s, c, kerf::CholeskyOrdering::Automatic); } },
    { "BM_HeatSetupAMD", [](benchmark::State& s, const Scene& c) { heatSetup(s, c, kerf::CholeskyOrdering::AMD); } },
    { "BM_HeatSetupMetis",
      [](benchmark::State& s, const Scene& c) { heatSetup(s, c, kerf::CholeskyOrdering::METIS); } },
    { "BM_HeatSetupGeometric",
      [](benchmark::State& s, const Scene& c) { heatSetup(s, c, kerf::CholeskyOrdering::Geometric); } },
    { "BM_HeatSource", heatSource },
    { "BM_VTKDijkstraPath", vtkDijkstraPath },
    { "BM_GeodesicPolylineFirst", geodesicPathFirst },
    { "BM_GeodesicPolyline", [](benchmark::State& s, const Scene& c) { geodesicPathKept(s, c, 0.0); } },
    { "BM_GeodesicPolylineAnisotropic", [](benchmark::State& s, const Scene& c) { geodesicPathKept(s, c, 1.0); } },
#ifdef KERF_HAVE_CGAL
    { "BM_CGALHeatSetup", cgalSetup },
    { "BM_CGALHeatSource", cgalSource },
#endif
    { "BM_SeamNew", seamNew },
    { "BM_SeamRegrowth", seamRegrowth },
    { "BM_RoiScissorClick", roiScissorClick },
    { "BM_GeodesicDiscClick", [](benchmark::State& s, const Scene& c) { geodesicDiscClick(s, c, false); } },
    { "BM_GeodesicDiscRadius", [](benchmark::State& s, const Scene& c) { geodesicDiscClick(s, c, true); } },
  };
  for (const GeodesicSize& size : Sizes)
  {
    for (const auto& [name, body] : benchmarks)
    {
      if (name.rfind("BM_CGAL", 0) == 0 && size.cells > 100)
      {
        continue;
      }
      const std::string fullName = name + "/" + size.label;
      benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(
        fullName.c_str(), [size = &size, body = body](benchmark::State& state) { run(state, size, body); });
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(size.minimumSeconds);
      }
    }
  }
  benchmark::RegisterBenchmark("BM_SphereErrorKerf",
    [](benchmark::State& state) {
      const kerf::HeatGeodesics heat(errorSphere());
      std::vector<double> distance;
      for (auto _ : state)
      {
        kerf::GeodesicSource from;
        from.vertices = { SphereSource };
        distance = heat.compute(from).distance;
      }
      sphereErrors(state, errorSphere(), distance, SphereSource);
    })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#ifdef KERF_HAVE_CGAL
  benchmark::RegisterBenchmark("BM_SphereErrorCGAL",
    [](benchmark::State& state) {
      const CgalMesh mesh = toCgal(errorSphere());
      std::vector<double> distance;
      for (auto _ : state)
      {
        distance = cgalDistances<CGAL::Heat_method_3::Direct>(mesh, SphereSource);
      }
      sphereErrors(state, errorSphere(), distance, SphereSource);
    })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
  benchmark::RegisterBenchmark("BM_SphereErrorCGALIntrinsic",
    [](benchmark::State& state) {
      const CgalMesh mesh = toCgal(errorSphere());
      std::vector<double> distance;
      for (auto _ : state)
      {
        distance = cgalDistances<CGAL::Heat_method_3::Intrinsic_Delaunay>(mesh, SphereSource);
      }
      sphereErrors(state, errorSphere(), distance, SphereSource);
    })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#endif
}

} // namespace benchmarks
} // namespace kerf
