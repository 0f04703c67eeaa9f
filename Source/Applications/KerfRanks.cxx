// The processes a command runs on, through VTK's MPI controller when mpirun started them.
#include "KerfRanks.h"

#include <vtkMultiProcessStream.h>
#include <vtkSmartPointer.h>

#if KERF_WITH_MPI
#include <vtkMPIController.h>
#endif

#include <algorithm>
#include <cstdlib>

namespace kerf
{

int LaunchedRanks()
{
  for (const char* name : { "OMPI_COMM_WORLD_SIZE", "PMI_SIZE" })
  {
    if (const char* value = std::getenv(name))
    {
      return std::max(1, std::atoi(value));
    }
  }
  return 1;
}

int LaunchedRanksOnThisHost()
{
  for (const char* name : { "OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS" })
  {
    if (const char* value = std::getenv(name))
    {
      return std::max(1, std::atoi(value));
    }
  }
  return LaunchedRanks();
}

bool Ranks::available()
{
  return KERF_WITH_MPI != 0;
}

struct Ranks::Internals
{
#if KERF_WITH_MPI
  vtkSmartPointer<vtkMPIController> controller;
#endif
};

Ranks::Ranks()
  : State(new Internals)
{
#if KERF_WITH_MPI
  if (LaunchedRanks() > 1)
  {
    this->State->controller = vtkSmartPointer<vtkMPIController>::New();
    int argc = 0;
    char** argv = nullptr;
    this->State->controller->Initialize(&argc, &argv, 0);
    this->Rank = this->State->controller->GetLocalProcessId();
    this->Size = this->State->controller->GetNumberOfProcesses();
  }
#endif
}

Ranks::~Ranks()
{
#if KERF_WITH_MPI
  if (this->State->controller)
  {
    this->State->controller->Finalize();
  }
#endif
}

std::vector<vtkMultiProcessStream> Ranks::gather(const vtkMultiProcessStream& mine) const
{
#if KERF_WITH_MPI
  if (this->State->controller)
  {
    std::vector<vtkMultiProcessStream> all;
    this->State->controller->Gather(mine, all, 0);
    if (this->Rank != 0)
    {
      all.clear();
    }
    return all;
  }
#endif
  return { mine };
}

int Ranks::broadcast(int value) const
{
#if KERF_WITH_MPI
  if (this->State->controller)
  {
    this->State->controller->Broadcast(&value, 1, 0);
  }
#endif
  return value;
}

} // namespace kerf
