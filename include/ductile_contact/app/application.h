#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/core/types.h>

namespace DuctileContact
{
  /**
   * The program: `ductile-contact [--validate] [--print-parameters] FILE.prm`.
   * Returns the process exit code: 0 on success, 1 for bad input (one
   * message on rank 0, nothing computed), 2 when a run started but could
   * not finish (results so far are kept).
   */
  int
  run_application(int argc, char **argv, const MPI_Comm comm);

  /**
   * Builds the scene's mesh (refined when @p refine) and checks that the
   * material and boundary ids of the input exist in it and that every body
   * of the mesh has a `Body <id>` subsection; throws InputError.
   */
  void
  build_and_check_mesh(const RunParameters &parameters,
                       dealii::parallel::distributed::Triangulation<dim> &tria,
                       const bool refine);
} // namespace DuctileContact
