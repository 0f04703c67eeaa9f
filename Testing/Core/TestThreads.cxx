// Kerf's threads: the limit, the parallel loop, the surface's cache under several threads, and the
// ensemble giving the same output bit for bit on any number of threads.
#include "Error.h"
#include "Segmentation/EnsembleSegmentation.h"
#include "SegmentationShapes.h"
#include "Surface/Surface.h"
#include "Threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace
{
// Sets the thread limit for a scope, and returns to the environment's afterwards.
struct ThreadLimit
{
  explicit ThreadLimit(int threads) { setThreadLimit(threads); }
  ~ThreadLimit() { setThreadLimit(0); }
};
} // namespace

TEST(Threads, TheLimitComesFromTheCallTheEnvironmentOrTheHardware)
{
  const char* before = std::getenv("KERF_NUM_THREADS");
  const std::string saved = before ? before : "";
  ::setenv("KERF_NUM_THREADS", "3", 1);
  EXPECT_EQ(threadLimit(), 3);
  EXPECT_EQ(threadLimitSetting(), 0);
  {
    const ThreadLimit two(2);
    EXPECT_EQ(threadLimit(), 2);
    EXPECT_EQ(threadLimitSetting(), 2);
  }
  EXPECT_EQ(threadLimit(), 3);
  EXPECT_EQ(threadLimitSetting(), 0);
  // Not a whole number >= 1: the hardware's cores.
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(hardwareThreads(), cores);
  for (const char* bad : { "0", "-2", "two", "4x", "" })
  {
    ::setenv("KERF_NUM_THREADS", bad, 1);
    EXPECT_EQ(threadLimit(), cores) << "KERF_NUM_THREADS=" << bad;
  }
  ::unsetenv("KERF_NUM_THREADS");
  EXPECT_EQ(threadLimit(), cores);
  EXPECT_THROW(setThreadLimit(-1), Error);
  EXPECT_EQ(threadLimitSetting(), 0);
  {
    const ThreadLimit two(2);
    EXPECT_THROW(setThreadLimit(-1), Error);
    EXPECT_EQ(threadLimitSetting(), 2); // a refused value changes nothing
  }
  if (before)
  {
    ::setenv("KERF_NUM_THREADS", saved.c_str(), 1);
  }
}

TEST(Threads, EachTaskRunsOnceOnAtMostTheLimit)
{
  for (const int limit : { 1, 2, 4 })
  {
    const ThreadLimit scope(limit);
    std::vector<int> runs(100, 0);
    std::mutex guard;
    std::set<std::thread::id> threads;
    std::atomic<int> busy{ 0 }, mostBusy{ 0 };
    parallelFor(100, [&](int i) {
      const int now = ++busy;
      for (int seen = mostBusy.load(); now > seen && !mostBusy.compare_exchange_weak(seen, now);)
      {
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      ++runs[static_cast<std::size_t>(i)];
      {
        const std::lock_guard<std::mutex> lock(guard);
        threads.insert(std::this_thread::get_id());
      }
      --busy;
    });
    EXPECT_EQ(runs, std::vector<int>(100, 1)) << limit << " threads";
    EXPECT_LE(static_cast<int>(threads.size()), limit);
    EXPECT_LE(mostBusy.load(), limit);
    if (limit == 1)
    {
      EXPECT_EQ(*threads.begin(), std::this_thread::get_id()); // the calling thread only
    }
  }
  // No tasks: nothing runs.
  int calls = 0;
  parallelFor(0, [&](int) { ++calls; });
  parallelFor(-3, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(Threads, NestedLoopsStayOnTheirTasksThread)
{
  const ThreadLimit scope(4);
  std::vector<int> sums(8, 0);
  parallelFor(8, [&](int i) {
    const std::thread::id outer = std::this_thread::get_id();
    bool same = true;
    parallelFor(10, [&](int j) {
      same = same && std::this_thread::get_id() == outer;
      sums[static_cast<std::size_t>(i)] += j;
    });
    if (!same)
    {
      sums[static_cast<std::size_t>(i)] = -1;
    }
  });
  EXPECT_EQ(sums, std::vector<int>(8, 45));
}

TEST(Threads, TheLowestTasksErrorIsRethrownAfterAllFinish)
{
  for (const int limit : { 1, 3 })
  {
    const ThreadLimit scope(limit);
    std::atomic<int> finished{ 0 };
    try
    {
      parallelFor(20, [&](int i) {
        if (i == 13 || i == 6 || i == 17)
        {
          throw std::runtime_error("task " + std::to_string(i));
        }
        ++finished;
      });
      ADD_FAILURE() << "no exception";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_EQ(std::string(e.what()), "task 6") << limit << " threads";
    }
    EXPECT_EQ(finished.load(), 17);
  }
}

TEST(Threads, TheSurfaceComputesADerivedItemOnceForAllThreads)
{
  const ThreadLimit scope(4);
  const Surface surface{ fingers().surface->mesh() };
  std::atomic<int> computed{ 0 };
  std::vector<const int*> seen(16, nullptr);
  parallelFor(16, [&](int i) {
    seen[static_cast<std::size_t>(i)] = &surface.derived<int>("answer", [&] {
      ++computed;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      return 42;
    });
  });
  EXPECT_EQ(computed.load(), 1);
  EXPECT_EQ(surface.computations(), 1);
  for (const int* item : seen)
  {
    ASSERT_EQ(item, seen.front());
    EXPECT_EQ(*item, 42);
  }
  // A computation that throws leaves the item absent; the next request computes it.
  EXPECT_THROW(surface.derived<int>("refused", []() -> int { throw Error("no"); }), Error);
  EXPECT_EQ(surface.derived<int>("refused", [] { return 7; }), 7);
  EXPECT_EQ(surface.computations(), 2);
}

// The ensemble at one count and choosing its count, and the hierarchy: the members and the counts
// run on Kerf's threads, and the output is the same bit for bit on 1, 2 and 3 threads.
TEST(Threads, TheEnsembleIsTheSameOnAnyNumberOfThreads)
{
  const TriangleMesh& mesh = fingers().surface->mesh();
  const EnsembleSegmentationOptions options;
  std::vector<int> atCount, chosen, hierarchyCut;
  std::vector<double> scores, hierarchyScores;
  for (const int limit : { 1, 2, 3 })
  {
    const ThreadLimit scope(limit);
    const Surface surface{ mesh }; // nothing cached from another run
    const EnsembleSegmentationResult one = segmentByEnsemble(surface, FingerCount + 1, options);
    const EnsembleSegmentationResult choosing = segmentByEnsembleChoosingCount(surface, 2, 7, options);
    const EnsembleHierarchy hierarchy = ensembleHierarchy(surface, 2, 7, options);
    const std::vector<int> cut = cutEnsembleHierarchy(surface, hierarchy, 4, options.refinement).labels;
    if (limit == 1)
    {
      atCount = one.labels;
      chosen = choosing.labels;
      scores = choosing.countScores;
      hierarchyCut = cut;
      hierarchyScores = hierarchy.countScores;
      ASSERT_EQ(scores.size(), 6u);
      ASSERT_EQ(hierarchyScores.size(), 6u);
      continue;
    }
    EXPECT_EQ(one.labels, atCount) << limit << " threads";
    EXPECT_EQ(choosing.labels, chosen) << limit << " threads";
    EXPECT_EQ(cut, hierarchyCut) << limit << " threads";
    for (std::size_t c = 0; c < scores.size(); ++c)
    {
      EXPECT_EQ(choosing.countScores[c], scores[c]) << limit << " threads, count " << 2 + c; // bit for bit
      EXPECT_EQ(hierarchy.countScores[c], hierarchyScores[c]) << limit << " threads, count " << 2 + c;
    }
  }
}
