// Benchmarks of automatic segmentation: hierarchical face clustering (Garland et al.) at 100k and 1M triangles, and the
// ensemble with its reference at a psb-dev model's size.
//
// On the cube dumbbell of the harmonic-cut benchmarks (kerf::benchmarks::MakeBenchmarkDumbbell,
// 99,372 and 1,002,252 triangles):
//   BM_FaceClusterHierarchy/<size>   kerf::buildFaceClusterHierarchy (the dual graph built
//                                    outside the timed loop) and a cut at k = 10: the whole
//                                    method of survey section 3.3 for one k, with its defaults
//                                    (above 50,000 triangles the contractions start in blocks:
//                                    exactClusterCount)
//   BM_FaceClusterHierarchyExact/<size>  the same in the paper's greedy order from the first
//                                    face (exactClusterCount above the face count): the reference
//   BM_FaceClusterGraph/<size>       kerf::FaceGraph, the dual graph the methods share
//   BM_FaceClusterSlide/<size>       cutHierarchyAtCount on the built tree for k = 2..21, the
//                                    cost of sliding k without recomputing
// and, on the 22,188-triangle dumbbell (a psb-dev model's size; k = 6):
//   BM_EnsembleSegmentation/22k      kerf::segmentByEnsemble with its defaults on a new Surface
//                                    each time (nothing cached): the flagship's whole cost
//   BM_EnsembleChoosingCount/22k     kerf::segmentByEnsembleChoosingCount with its defaults
//                                    (counts 5 to 11), beside the ensemble at one count
//   BM_EnsembleHierarchy/22k         kerf::ensembleHierarchy with its defaults (counts 5 to 11) and
//                                    the cut at the count it chooses: the slider's set-up, beside
//                                    the ensemble choosing its count
//   BM_ConsensusCutSegmentation/22k  kerf::segmentByConsensusCuts the same way, its costliest
//                                    member and the reference its cost is quoted against
//   BM_BoundaryBandCut/22k           kerf::refineSegmentBoundaries of the ensemble's labels
//                                    without its band (computed once): the band's own cost
//   BM_CoreExtraction/22k            kerf::segmentByCoreExtraction with its defaults (it chooses
//                                    its own number of parts), beside the ensemble in the same run
// and BM_CoreExtraction/100k, beside BM_FaceClusterHierarchy/100k, on the 99,372-triangle dumbbell,
// where also
//   BM_EnsembleHierarchySlide/100k   a new count on the built ensemble hierarchy (counts 5 to 11,
//                                    built once): kerf::cutEnsembleHierarchy at k = 12, 13, .., 20 in
//                                    turn, one per iteration, with the boundary refinement
//   BM_EnsembleHierarchySlideKept/100k  the same at k = 5, .., 11, whose refined cuts the build kept
//   BM_EnsembleHierarchyCut/100k     k = 12, .., 20 without the refinement (band 0): the tree's cut
//   BM_EnsembleSegmentation/100k, BM_EnsembleChoosingCount/100k  as at 22k (k = 6; counts 5 to 11)
//   BM_EnsembleSegmentation/100k-threads, BM_EnsembleChoosingCount/100k-threads  the same on the
//                                    hardware's cores (kerf::setThreadLimit; the others run on one)
// and on the models of KERF_SHARED_DATA_DIR/psb-dev (only when the folder exists; each model's
// surface built anew in every iteration, from its mesh read once):
//   BM_EnsembleChoosingCount/1model, /all   the default of `kerf segment --auto` and of
//                                    vtkEnsembleSegmentation's ChooseSegmentCount: counts 5 to 11
//   BM_EnsembleSegmentation/1model, /all    the ensemble at the humans' count (nSeg-ByModel.txt),
//                                    as the benchmark runner asks for it: the reference
// whose counter s_per_model is the time per model (all models' time over their number), and
//   BM_EnsembleChoosingCount/1model-threads, /all-threads, BM_EnsembleSegmentation/1model-threads,
//   /all-threads                     the same on the hardware's cores.
// The meshes are built once per size, outside the timed loops.
#include "BenchmarkMeshes.h"
#include "KerfBenchmarks.h"

#include "Evaluation/BenchmarkCase.h"
#include "Evaluation/PrincetonBenchmark.h"
#include "Segmentation/BoundaryRefinement.h"
#include "Segmentation/ConsensusCutSegmentation.h"
#include "Segmentation/CoreExtraction.h"
#include "Segmentation/EnsembleSegmentation.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/HierarchicalFaceClustering.h"
#include "Surface/Surface.h"
#include "Threads.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{

struct ClusterSize
{
  const char* label;
  int cells;
  double minimumSeconds;
};

const std::array<ClusterSize, 2> Sizes = { { { "100k", 91, 1.0 }, { "1M", 289, 4.0 } } };

struct ClusterScene
{
  kerf::TriangleMesh mesh;
  std::unique_ptr<kerf::FaceGraph> graph;
};

const ClusterScene& sceneOfSize(const ClusterSize& size)
{
  static std::map<std::string, std::unique_ptr<ClusterScene>> scenes;
  std::unique_ptr<ClusterScene>& scene = scenes[size.label];
  if (!scene)
  {
    auto built = std::make_unique<ClusterScene>();
    built->mesh = kerf::benchmarks::MakeBenchmarkDumbbell(size.cells);
    built->graph = std::make_unique<kerf::FaceGraph>(built->mesh);
    scene = std::move(built);
  }
  return *scene;
}

void setCounters(benchmark::State& state, const ClusterScene& scene)
{
  state.counters["triangles"] = scene.mesh.faceCount();
}

void clusterHierarchyBenchmark(benchmark::State& state, const ClusterSize& size, bool exact)
{
  kerf::HierarchicalClusteringOptions options;
  if (exact)
  {
    options.exactClusterCount = std::numeric_limits<int>::max();
  }
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ClusterScene& { return sceneOfSize(size); },
    [options](benchmark::State& st, const ClusterScene& scene) {
      std::size_t clusters = 0;
      for (auto _ : st)
      {
        const kerf::FaceClusterHierarchy tree = kerf::buildFaceClusterHierarchy(*scene.graph, options);
        const std::vector<int> labels = kerf::cutHierarchyAtCount(tree, 10);
        clusters = static_cast<std::size_t>(*std::max_element(labels.begin(), labels.end()) + 1);
        benchmark::DoNotOptimize(labels.data());
      }
      if (clusters != 10)
      {
        kerf::benchmarks::Fail(st, "the cut gave " + std::to_string(clusters) + " clusters, not 10");
      }
    },
    setCounters);
}

void clusterGraphBenchmark(benchmark::State& state, const ClusterSize& size)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ClusterScene& { return sceneOfSize(size); },
    [](benchmark::State& st, const ClusterScene& scene) {
      for (auto _ : st)
      {
        const kerf::FaceGraph graph(scene.mesh);
        benchmark::DoNotOptimize(&graph);
      }
    },
    setCounters);
}

void clusterSlideBenchmark(benchmark::State& state, const ClusterSize& size)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ClusterScene& { return sceneOfSize(size); },
    [](benchmark::State& st, const ClusterScene& scene) {
      const kerf::FaceClusterHierarchy tree =
        kerf::buildFaceClusterHierarchy(*scene.graph, kerf::HierarchicalClusteringOptions());
      for (auto _ : st)
      {
        for (int k = 2; k <= 21; ++k)
        {
          benchmark::DoNotOptimize(kerf::cutHierarchyAtCount(tree, k).data());
        }
      }
    },
    setCounters);
}

// The ensemble and its reference on the 22,188-triangle dumbbell, k = 6.
constexpr ClusterSize EnsembleSize{ "22k", 43, 2.0 };
constexpr int EnsembleSegments = 6;

void ensembleBenchmark(benchmark::State& state, bool consensusCutsOnly, const ClusterSize& size, bool threads)
{
  const kerf::benchmarks::ThreadsFor scope(threads);
  state.counters["threads"] = kerf::threadLimit();
  kerf::benchmarks::RunOnScene(
    state, [&size]() -> const ClusterScene& { return sceneOfSize(size); },
    [consensusCutsOnly](benchmark::State& st, const ClusterScene& scene) {
      int segments = 0;
      for (auto _ : st)
      {
        const kerf::Surface surface(scene.mesh);
        const std::vector<int> labels = consensusCutsOnly
          ? kerf::segmentByConsensusCuts(surface, EnsembleSegments, kerf::ConsensusCutOptions()).labels
          : kerf::segmentByEnsemble(surface, EnsembleSegments, kerf::EnsembleSegmentationOptions()).labels;
        segments = *std::max_element(labels.begin(), labels.end()) + 1;
        benchmark::DoNotOptimize(labels.data());
      }
      if (segments != EnsembleSegments)
      {
        kerf::benchmarks::Fail(st, std::to_string(segments) + " segments, not " + std::to_string(EnsembleSegments));
      }
    },
    setCounters);
}

void choosingCountBenchmark(benchmark::State& state, const ClusterSize& size, bool threads)
{
  const kerf::benchmarks::ThreadsFor scope(threads);
  state.counters["threads"] = kerf::threadLimit();
  kerf::benchmarks::RunOnScene(
    state, [&size]() -> const ClusterScene& { return sceneOfSize(size); },
    [](benchmark::State& st, const ClusterScene& scene) {
      int segments = 0;
      for (auto _ : st)
      {
        const kerf::Surface surface(scene.mesh);
        const kerf::EnsembleSegmentationResult result =
          kerf::segmentByEnsembleChoosingCount(surface, 5, 11, kerf::EnsembleSegmentationOptions());
        segments = result.segmentCount;
        benchmark::DoNotOptimize(result.labels.data());
      }
      st.counters["segments"] = segments;
    },
    setCounters);
}

void hierarchyBenchmark(benchmark::State& state)
{
  kerf::benchmarks::RunOnScene(
    state, []() -> const ClusterScene& { return sceneOfSize(EnsembleSize); },
    [](benchmark::State& st, const ClusterScene& scene) {
      int segments = 0;
      const kerf::EnsembleSegmentationOptions options;
      for (auto _ : st)
      {
        const kerf::Surface surface(scene.mesh);
        const kerf::EnsembleHierarchy hierarchy = kerf::ensembleHierarchy(surface, 5, 11, options);
        const kerf::EnsembleSegmentationResult result =
          kerf::cutEnsembleHierarchy(surface, hierarchy, hierarchy.chosenCount, options.refinement);
        segments = result.segmentCount;
        benchmark::DoNotOptimize(result.labels.data());
      }
      st.counters["segments"] = segments;
    },
    setCounters);
}

// The ensemble hierarchy of a scene, built once per size.
const kerf::EnsembleHierarchy& hierarchyOf(const ClusterSize& size, const kerf::Surface& surface)
{
  static std::map<std::string, kerf::EnsembleHierarchy> built;
  const auto at = built.find(size.label);
  if (at != built.end())
  {
    return at->second;
  }
  return built[size.label] = kerf::ensembleHierarchy(surface, 5, 11, kerf::EnsembleSegmentationOptions());
}

void hierarchySlideBenchmark(benchmark::State& state, const ClusterSize& size, bool refined, int lowest, int highest)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ClusterScene& { return sceneOfSize(size); },
    [&size, refined, lowest, highest](benchmark::State& st, const ClusterScene& scene) {
      static std::map<std::string, std::unique_ptr<kerf::Surface>> surfaces;
      std::unique_ptr<kerf::Surface>& surface = surfaces[size.label];
      if (!surface)
      {
        surface = std::make_unique<kerf::Surface>(scene.mesh);
      }
      const kerf::EnsembleHierarchy& hierarchy = hierarchyOf(size, *surface);
      kerf::BoundaryRefinementOptions refinement;
      if (!refined)
      {
        refinement.bandWidth = 0.0;
      }
      int k = lowest;
      int wrong = 0;
      for (auto _ : st)
      {
        const kerf::EnsembleSegmentationResult result = kerf::cutEnsembleHierarchy(*surface, hierarchy, k, refinement);
        wrong += result.segmentCount != k ? 1 : 0;
        benchmark::DoNotOptimize(result.labels.data());
        k = k == highest ? lowest : k + 1;
      }
      st.counters["atoms"] = hierarchy.consensus.atoms;
      if (wrong > 0)
      {
        kerf::benchmarks::Fail(st, std::to_string(wrong) + " cuts gave another number of segments than asked");
      }
    },
    setCounters);
}

void bandCutBenchmark(benchmark::State& state)
{
  kerf::benchmarks::RunOnScene(
    state, []() -> const ClusterScene& { return sceneOfSize(EnsembleSize); },
    [](benchmark::State& st, const ClusterScene& scene) {
      const kerf::Surface surface(scene.mesh);
      kerf::EnsembleSegmentationOptions unbanded;
      unbanded.refinement.bandWidth = 0.0;
      const std::vector<int> labels = kerf::segmentByEnsemble(surface, EnsembleSegments, unbanded).labels;
      int moved = 0;
      for (auto _ : st)
      {
        const kerf::BoundaryRefinementResult result =
          kerf::refineSegmentBoundaries(*scene.graph, labels, kerf::BoundaryRefinementOptions());
        moved = result.movedFaces;
        benchmark::DoNotOptimize(result.labels.data());
      }
      st.counters["moved"] = moved;
    },
    setCounters);
}

// The psb-dev models, read once (their meshes; every iteration builds the surfaces anew).
const std::string PsbDirectory = std::string(KERF_SHARED_DATA_DIR) + "/psb-dev";

struct PsbScene
{
  std::vector<kerf::TriangleMesh> meshes;
  std::vector<int> humanCounts; // nSeg-ByModel.txt
  double triangles = 0.0;       // mean over the models
};

const PsbScene& psbScene(const std::vector<kerf::BenchmarkModel>& models)
{
  static std::map<std::size_t, std::unique_ptr<PsbScene>> scenes;
  std::unique_ptr<PsbScene>& scene = scenes[models.size()];
  if (!scene)
  {
    auto built = std::make_unique<PsbScene>();
    for (const kerf::BenchmarkModel& model : models)
    {
      const kerf::BenchmarkCase loaded = kerf::loadBenchmarkCase(model);
      built->meshes.push_back(loaded.surface->mesh());
      built->humanCounts.push_back(model.requestedSegments > 0 ? model.requestedSegments : EnsembleSegments);
      built->triangles += loaded.surface->mesh().faceCount() / static_cast<double>(models.size());
    }
    scene = std::move(built);
  }
  return *scene;
}

// Every model of `models` in turn, per iteration: the ensemble choosing its count (counts 5 to
// 11), or at the humans' count. Each result is checked for its number of segments.
void psbEnsembleBenchmark(
  benchmark::State& state, const std::vector<kerf::BenchmarkModel>* models, bool choosing, bool threads)
{
  const kerf::benchmarks::ThreadsFor scope(threads);
  state.counters["threads"] = kerf::threadLimit();
  kerf::benchmarks::RunOnScene(
    state, [models]() -> const PsbScene& { return psbScene(*models); },
    [choosing](benchmark::State& st, const PsbScene& scene) {
      double chosen = 0.0;
      int wrong = 0;
      for (auto _ : st)
      {
        chosen = 0.0;
        for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        {
          const kerf::Surface surface(scene.meshes[m]);
          const kerf::EnsembleSegmentationResult result = choosing
            ? kerf::segmentByEnsembleChoosingCount(surface, 5, 11, kerf::EnsembleSegmentationOptions())
            : kerf::segmentByEnsemble(surface, scene.humanCounts[m], kerf::EnsembleSegmentationOptions());
          const bool right = choosing ? result.segmentCount >= 1 : result.segmentCount == scene.humanCounts[m];
          wrong += right ? 0 : 1;
          chosen += result.segmentCount / static_cast<double>(scene.meshes.size());
          benchmark::DoNotOptimize(result.labels.data());
        }
      }
      st.counters["segments"] = chosen; // the mean over the models
      st.counters["s_per_model"] = benchmark::Counter(static_cast<double>(scene.meshes.size()),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
      if (wrong > 0)
      {
        kerf::benchmarks::Fail(st, std::to_string(wrong) + " results gave another number of segments than asked");
      }
    },
    [models](benchmark::State& st, const PsbScene& scene) {
      st.counters["models"] = static_cast<double>(models->size());
      st.counters["triangles"] = scene.triangles;
    });
}

// Registers the psb-dev benchmarks when the folder exists (and says why not otherwise).
void registerPsbBenchmarks(bool useSizeMinimumTimes)
{
  static std::vector<kerf::BenchmarkModel> all;
  try
  {
    all = kerf::scanBenchmark(PsbDirectory);
  }
  catch (const std::exception& e)
  {
    benchmark::AddCustomContext("psb_dev_ensemble", std::string(e.what()) + "; the psb-dev ensemble not registered");
    return;
  }
  if (all.empty())
  {
    benchmark::AddCustomContext(
      "psb_dev_ensemble", PsbDirectory + " holds no model; the psb-dev ensemble not registered");
    return;
  }
  static const std::vector<kerf::BenchmarkModel> first = { all.front() };
  const std::pair<const char*, const std::vector<kerf::BenchmarkModel>*> sets[] = { { "1model", &first },
    { "all", &all } };
  for (const auto& [label, models] : sets)
  {
    for (const bool threads : { false, true })
    {
      for (const bool choosing : { true, false })
      {
        const std::string name = std::string(choosing ? "BM_EnsembleChoosingCount/" : "BM_EnsembleSegmentation/") +
          label + (threads ? "-threads" : "");
        benchmark::internal::Benchmark* registered =
          benchmark::RegisterBenchmark(name.c_str(), psbEnsembleBenchmark, models, choosing, threads);
        registered->Unit(benchmark::kMillisecond)->UseRealTime();
        if (useSizeMinimumTimes)
        {
          registered->MinTime(0.1); // one iteration of all models takes seconds
        }
      }
    }
  }
}

void coreExtractionBenchmark(benchmark::State& state, const ClusterSize& size)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ClusterScene& { return sceneOfSize(size); },
    [](benchmark::State& st, const ClusterScene& scene) {
      int segments = 0;
      for (auto _ : st)
      {
        const kerf::CoreExtractionResult result =
          kerf::segmentByCoreExtraction(*scene.graph, kerf::CoreExtractionOptions());
        segments = result.segmentCount;
        benchmark::DoNotOptimize(result.labels.data());
      }
      st.counters["segments"] = segments;
    },
    setCounters);
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterAutomaticSegmentationBenchmarks(bool useSizeMinimumTimes)
{
  for (benchmark::internal::Benchmark* registered :
    {
      benchmark::RegisterBenchmark("BM_EnsembleSegmentation/22k", ensembleBenchmark, false, EnsembleSize, false),
      benchmark::RegisterBenchmark("BM_EnsembleChoosingCount/22k", choosingCountBenchmark, EnsembleSize, false),
      benchmark::RegisterBenchmark("BM_EnsembleSegmentation/100k", ensembleBenchmark, false, Sizes[0], false),
      benchmark::RegisterBenchmark("BM_EnsembleChoosingCount/100k", choosingCountBenchmark, Sizes[0], false),
      benchmark::RegisterBenchmark("BM_EnsembleSegmentation/100k-threads", ensembleBenchmark, false, Sizes[0], true),
      benchmark::RegisterBenchmark("BM_EnsembleChoosingCount/100k-threads", choosingCountBenchmark, Sizes[0], true),
      benchmark::RegisterBenchmark("BM_EnsembleHierarchy/22k", hierarchyBenchmark),
      benchmark::RegisterBenchmark("BM_EnsembleHierarchySlide/100k", hierarchySlideBenchmark, Sizes[0], true, 12, 20),
      benchmark::RegisterBenchmark(
        "BM_EnsembleHierarchySlideKept/100k", hierarchySlideBenchmark, Sizes[0], true, 5, 11),
      benchmark::RegisterBenchmark("BM_EnsembleHierarchyCut/100k", hierarchySlideBenchmark, Sizes[0], false, 12, 20),
      benchmark::RegisterBenchmark("BM_ConsensusCutSegmentation/22k", ensembleBenchmark, true, EnsembleSize, false),
      benchmark::RegisterBenchmark("BM_BoundaryBandCut/22k", bandCutBenchmark),
      benchmark::RegisterBenchmark("BM_CoreExtraction/22k", coreExtractionBenchmark, EnsembleSize),
      benchmark::RegisterBenchmark("BM_CoreExtraction/100k", coreExtractionBenchmark, Sizes[0]),
    })
  {
    registered->Unit(benchmark::kMillisecond)->UseRealTime();
    if (useSizeMinimumTimes)
    {
      registered->MinTime(EnsembleSize.minimumSeconds);
    }
  }
  registerPsbBenchmarks(useSizeMinimumTimes);
  for (const ClusterSize& size : Sizes)
  {
    const std::string label = size.label;
    for (benchmark::internal::Benchmark* registered : {
           benchmark::RegisterBenchmark(
             ("BM_FaceClusterHierarchy/" + label).c_str(), clusterHierarchyBenchmark, size, false),
           benchmark::RegisterBenchmark(
             ("BM_FaceClusterHierarchyExact/" + label).c_str(), clusterHierarchyBenchmark, size, true),
           benchmark::RegisterBenchmark(("BM_FaceClusterGraph/" + label).c_str(), clusterGraphBenchmark, size),
           benchmark::RegisterBenchmark(("BM_FaceClusterSlide/" + label).c_str(), clusterSlideBenchmark, size),
         })
    {
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(size.minimumSeconds);
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
