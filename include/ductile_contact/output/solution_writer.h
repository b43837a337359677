#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_parameters.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * Graphical output: results/solution-NNNNN.pvtu (one .vtu per rank) and
   * the time series results/solution.pvd. Point data: displacement (for
   * Warp By Vector), alpha, s. Cell data (averages over the quadrature
   * points, from SystemAssembler's CellQuantities): von Mises equivalent and
   * mean of the Kirchhoff stress [Pa], J, the crack driving force H =
   * -g'(s) psi^+_H [Pa], body (material id) and MPI rank.
   */
  class SolutionWriter
  {
  public:
    SolutionWriter(const std::string                      &directory,
                   const Discretisation                   &discretisation,
                   const std::map<dealii::types::material_id,
                                  const BodyParameters *> &bodies);

    /// @p u with ghost entries. Collective; also rewrites solution.pvd.
    void
    write(const unsigned int                                step,
          const double                                      time,
          const dealii::TrilinosWrappers::MPI::BlockVector &u,
          const CellQuantities                             &cells);

  private:
    const std::string     directory;
    const Discretisation &discretisation;
    const std::map<dealii::types::material_id, const BodyParameters *> bodies;
    std::vector<std::pair<double, std::string>>                        records;
  };
} // namespace DuctileContact
