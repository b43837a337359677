#pragma once

#include <deal.II/base/types.h>

#include <mpi.h>
#include <string>

namespace DuctileContact
{
  /**
   * The peak resident memory (the kernel's VmHWM, the largest resident set
   * so far) of each rank of a communicator: rank 0's, the largest, and
   * their sum, in bytes.
   */
  struct MemoryUse
  {
    double rank_0  = 0.;
    double largest = 0.;
    double total   = 0.;

    /// Collective over @p comm.
    static MemoryUse
    peak(MPI_Comm comm);

    /// "peak memory 1.2 GiB on rank 0, 1.3 GiB at most on one rank, 2.5 GiB
    /// in all: 9.6 kB per unknown" for a system of @p n_unknowns.
    std::string
    describe(dealii::types::global_dof_index n_unknowns) const;
  };
} // namespace DuctileContact
