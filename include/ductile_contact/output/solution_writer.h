#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/output/output_parameters.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * Graphical output, Output/Format = vtu: solution_NNNNN.pvtu (one .vtu
   * per rank) and the time series solution.pvd; hdf5: solution_NNNNN.h5
   * (parallel HDF5, all ranks into one file), the mesh in mesh_NNNNN.h5
   * of the first step on it (written again only when the mesh changes:
   * mesh_changed()), the time series
   * solution.xdmf. Nodes are never merged: DataOut writes each cell's
   * nodes, and the HDF5 filter is told not to join nodes of equal
   * coordinates, which would glue bodies in contact. Point data: displacement
   * (for Warp By Vector), alpha, s, and in a dynamic run the velocity
   * [m/s]. Cell data (averages over the quadrature
   * points, from SystemAssembler's CellQuantities): von Mises equivalent and
   * mean of the Kirchhoff stress [Pa], J, the crack driving force H =
   * -g'(s) psi^+_H [Pa], the stress triaxiality sigma_m / sigma_eq of the
   * averaged Cauchy stress, body (material id) and MPI rank; and piecewise
   * constant (in vtu 3 x 3 tensors, in HDF5 the six components NAME_xx,
   * _yy, _zz, _xy, _xz, _yz): kirchhoff_stress tau and
   * cauchy_stress sigma = tau / J [Pa], log_strain 1/2 ln(b) of the averaged
   * b = F F^T and plastic_strain 1/2 ln(C^p) of the averaged C^p = F^pT F^p
   * (zero in elastic bodies).
   */
  class SolutionWriter
  {
  public:
    SolutionWriter(const std::string                      &directory,
                   const OutputFormat                      format,
                   const Discretisation                   &discretisation,
                   const std::map<dealii::types::material_id,
                                  const BodyParameters *> &bodies);

    /// @p u with ghost entries; @p velocity (owned entries, dynamic runs)
    /// adds the node field velocity. Collective; also rewrites
    /// solution.pvd.
    void
    write(const unsigned int                                step,
          const double                                      time,
          const dealii::TrilinosWrappers::MPI::BlockVector &u,
          const CellQuantities                             &cells,
          const dealii::TrilinosWrappers::MPI::BlockVector *velocity = nullptr);

    /// The mesh has changed since the last output: hdf5 writes it again.
    void
    mesh_changed();

    /// The series written so far (checkpoints).
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &records &xdmf_entries &mesh_file;
    }

  private:
    const std::string     directory;
    const OutputFormat    format;
    const Discretisation &discretisation;
    const std::map<dealii::types::material_id, const BodyParameters *> bodies;
    std::vector<std::pair<double, std::string>>                        records;
    std::vector<dealii::XDMFEntry> xdmf_entries;
    /// The mesh file of the hdf5 output ("" until written).
    std::string mesh_file;
  };
} // namespace DuctileContact
