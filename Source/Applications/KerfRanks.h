// The processes a command runs on: this one alone, or the MPI ranks of mpirun.
#pragma once

#include <memory>
#include <string>
#include <vector>

class vtkMultiProcessStream;

namespace kerf
{

/// The ranks of the job this process belongs to. Launched by mpirun on several ranks (LaunchedRanks),
/// MPI is initialized here and finalized when the object goes; otherwise, or in a build without
/// VTK's ParallelMPI, the job is this process alone (rank 0 of 1) and nothing is initialized, so a
/// plain run never touches MPI.
class Ranks
{
public:
  Ranks();
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  /// Whether this build can run on several ranks (VTK's ParallelMPI was found).
  static bool available();

  int rank() const { return this->Rank; }
  int size() const { return this->Size; }
  /// Rank 0 gets every rank's stream, in rank order; the other ranks get nothing. Every rank must call it.
  std::vector<vtkMultiProcessStream> gather(const vtkMultiProcessStream& mine) const;
  /// Every rank gets rank 0's value. Every rank must call it.
  int broadcast(int value) const;

private:
  struct Internals;
  std::unique_ptr<Internals> State;
  int Rank = 0;
  int Size = 1;
};

/// The number of ranks an MPI launcher started this process among (Open MPI's OMPI_COMM_WORLD_SIZE
/// or MPICH's PMI_SIZE in the environment); 1 without a launcher.
int LaunchedRanks();

/// The ranks the launcher started on this host (Open MPI's OMPI_COMM_WORLD_LOCAL_SIZE or MPICH's
/// MPI_LOCALNRANKS), else LaunchedRanks().
int LaunchedRanksOnThisHost();

} // namespace kerf
