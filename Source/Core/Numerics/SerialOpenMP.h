// Runs the OpenMP parallel regions of the libraries Kerf calls (CHOLMOD) on the calling thread.
#pragma once

#include <dlfcn.h>

namespace kerf
{
// CHOLMOD's supernodal factorization runs a few memory copies in OpenMP parallel regions with a
// fixed team size. On small machines their synchronisation costs more than it saves (a
// 100k-triangle factorization takes twice as long on two cores), so while one is alive the
// OpenMP runtime CHOLMOD loaded, if any, runs parallel regions on the calling thread. The
// factor is the same either way.
class SerialOpenMP
{
public:
  SerialOpenMP()
    : Get(reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels")))
    , Set(reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
  {
    if (this->Get && this->Set)
    {
      this->Previous = this->Get();
      this->Set(0);
    }
  }
  ~SerialOpenMP()
  {
    if (this->Get && this->Set)
    {
      this->Set(this->Previous);
    }
  }
  SerialOpenMP(const SerialOpenMP&) = delete;
  SerialOpenMP& operator=(const SerialOpenMP&) = delete;

private:
  int (*Get)() = nullptr;
  void (*Set)(int) = nullptr;
  int Previous = 1;
};
} // namespace kerf
