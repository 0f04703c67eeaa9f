// Kerf's thread limit and its parallel loop over independent tasks (std::thread).
#include "Threads.h"

#include "Error.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>
#include <vector>

namespace kerf
{

namespace
{
std::atomic<int> LimitSet{ 0 };

// Inside a parallelFor's task: nested loops stay on the task's thread.
thread_local bool InsideTask = false;

int limitFromEnvironment()
{
  const char* text = std::getenv("KERF_NUM_THREADS");
  if (text && *text)
  {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end && *end == '\0' && value >= 1)
    {
      return static_cast<int>(std::min(value, 1024L));
    }
  }
  return hardwareThreads();
}
} // namespace

int hardwareThreads()
{
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int threadLimit()
{
  const int set = LimitSet.load();
  return set > 0 ? set : limitFromEnvironment();
}

void setThreadLimit(int threads)
{
  if (threads < 0)
  {
    throw Error(
      "the thread limit must be 0 (the environment's or the hardware's) or at least 1, got " + std::to_string(threads));
  }
  LimitSet.store(threads);
}

int threadLimitSetting()
{
  return LimitSet.load();
}

void parallelFor(int count, const std::function<void(int)>& task)
{
  if (count <= 0)
  {
    return;
  }
  const int threads = InsideTask ? 1 : std::min(threadLimit(), count);
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
  std::atomic<int> next{ 0 };
  auto work = [&]() {
    const bool outer = InsideTask;
    InsideTask = true;
    for (int i = next++; i < count; i = next++)
    {
      try
      {
        task(i);
      }
      catch (...)
      {
        errors[static_cast<std::size_t>(i)] = std::current_exception();
      }
    }
    InsideTask = outer;
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads; ++t)
  {
    helpers.emplace_back(work);
  }
  work();
  for (std::thread& helper : helpers)
  {
    helper.join();
  }
  for (const std::exception_ptr& error : errors)
  {
    if (error)
    {
      std::rethrow_exception(error);
    }
  }
}

} // namespace kerf
