#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ductile_contact/core/memory_use.h>

#include <iomanip>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  MemoryUse
  MemoryUse::peak(const MPI_Comm comm)
  {
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    const double bytes = 1024. * static_cast<double>(stats.VmHWM);
    MemoryUse    use;
    use.rank_0  = Utilities::MPI::broadcast(comm, bytes, 0);
    use.largest = Utilities::MPI::max(bytes, comm);
    use.total   = Utilities::MPI::sum(bytes, comm);
    return use;
  }



  std::string
  MemoryUse::describe(const types::global_dof_index n_unknowns) const
  {
    const double       gib = 1024. * 1024. * 1024.;
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << "peak memory " << rank_0 / gib
      << " GiB on rank 0, " << largest / gib << " GiB at most on one rank, "
      << total / gib << " GiB in all";
    if (n_unknowns > 0)
      s << ": " << std::setprecision(1)
        << total / 1000. / static_cast<double>(n_unknowns) << " kB per unknown";
    return s.str();
  }
} // namespace DuctileContact
