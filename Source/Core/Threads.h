// Kerf's threads: the one limit on how many it uses, and the loop that spreads independent tasks over them.
#pragma once

#include <functional>

namespace kerf
{

/// The most threads a Kerf computation uses at once (the calling thread among them): the value
/// setThreadLimit gave, else the environment variable KERF_NUM_THREADS (a whole number >= 1),
/// else the hardware's cores. At least 1. Results never depend on it: every parallel loop
/// gives the same output, bit for bit, on any number of threads.
int threadLimit();

/// Limits Kerf's threads to `threads` (1: everything on the calling thread); 0 returns to
/// KERF_NUM_THREADS or the hardware's cores. Throws kerf::Error for a negative value.
void setThreadLimit(int threads);

/// The hardware's cores (std::thread::hardware_concurrency), at least 1: the limit by default.
int hardwareThreads();

/// The value the last setThreadLimit gave: 0 when none did or it returned to the default.
int threadLimitSetting();

/// Runs task(i) once for every i in [0, count), on up to threadLimit() threads (the calling one
/// among them), handing out the indices in order as threads come free; returns when all are done.
/// Tasks must be independent: each writes only its own results. Inside a task, a nested
/// parallelFor runs on that task's thread. When tasks throw, the exception of the lowest index is
/// rethrown once all have finished, so the error does not depend on the threads either.
void parallelFor(int count, const std::function<void(int)>& task);

} // namespace kerf
