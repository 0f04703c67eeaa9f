/**
 * @class vtkKerfSettings
 * @brief Kerf's settings for the whole process: how many threads its filters use.
 *
 * One instance serves the process: New() and GetInstance() return the same object (ParaView's
 * settings proxy "KerfSettings", Edit > Settings > Kerf, creates it with New()). ThreadLimit is
 * the most threads a Kerf computation uses at once: 1 runs Kerf's loops on the calling thread, 0
 * (the default) uses the environment variable KERF_NUM_THREADS if it is set, else every core.
 * Results never depend on it: Kerf's parallel loops give the same output, bit for bit, on any
 * number of threads. A negative value is refused with an error and the limit stays as it was.
 * The limit covers Kerf's own parallel loops; the BLAS that CHOLMOD calls (OpenBLAS) keeps its
 * own thread count, set with OPENBLAS_NUM_THREADS before the process starts.
 *
 * From Python:
 *
 *     import kerf
 *     kerf.vtkKerfSettings.GetInstance().SetThreadLimit(4)
 */
#ifndef vtkKerfSettings_h
#define vtkKerfSettings_h

#include "KerfFiltersModule.h"
#include "vtkObject.h"

class KERFFILTERS_EXPORT vtkKerfSettings : public vtkObject
{
public:
  /// The process's one instance, with a new reference (the caller deletes it, as after any New).
  static vtkKerfSettings* New();
  vtkTypeMacro(vtkKerfSettings, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The process's one instance, without a new reference.
  static vtkKerfSettings* GetInstance();

  ///@{
  /// The thread limit: 0 (KERF_NUM_THREADS, else every core) or at least 1. The value is Kerf's
  /// own for the whole process, so GetThreadLimit returns what the last SetThreadLimit gave.
  void SetThreadLimit(int threads);
  int GetThreadLimit();
  ///@}

  /// The threads Kerf uses now: the limit, or with 0 KERF_NUM_THREADS or the hardware's cores.
  int GetEffectiveThreadLimit();

  /// The hardware's cores (kerf::hardwareThreads: std::thread::hardware_concurrency, at least 1).
  static int GetNumberOfCores();

protected:
  vtkKerfSettings() = default;
  ~vtkKerfSettings() override = default;

private:
  vtkKerfSettings(const vtkKerfSettings&) = delete;
  void operator=(const vtkKerfSettings&) = delete;
};

#endif
