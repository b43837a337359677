#pragma once

#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/contact_surface.h>
#include <ductile_contact/output/output_parameters.h>

#include <mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /// Nodal contact quantities of one slave surface.
  struct ContactNodalData
  {
    const ContactSurface               *surface = nullptr;
    std::vector<double>                 pressure; ///< lambda_j [Pa]
    std::vector<double>                 gap;      ///< g_j / A_j [m]
    std::vector<dealii::Tensor<1, dim>> normal;
    /// Slip since the last accepted step [m] and tangential traction [Pa].
    std::vector<dealii::Tensor<1, dim>> slip, traction;
    std::vector<bool>                   active;
    /// 0 not in contact, 1 stick, 2 slip.
    std::vector<unsigned char> friction_state;
  };

  /**
   * Output of one slave surface after an accepted step, by every rank
   * (the surface is replicated; rank r writes the faces f with f mod
   * n_ranks = r), in the format of the field output:
   *  - vtu: `<name>_NNNNN.pvtu` with a `<name>_NNNNN.R.vtu` per rank R, the
   *    series `<name>.pvd`; hdf5: `<name>_NNNNN.h5` (mesh and fields of the
   *    step, parallel HDF5) and the series `<name>.xdmf`. The deformed slave
   *    faces (each quad9 face a patch of 2 x 2 quadrilaterals through its
   *    nine nodes) with point data pressure [Pa], gap [m] (negative:
   *    penetration), active (0/1), friction_state (0 not in contact, 1
   *    stick, 2 slip) and the vectors normal, slip [m] (of the step) and
   *    traction (tangential) [Pa];
   *  - `<name>_NNNNN.txt` (rank 0): one row per slave node, columns X Y Z
   *    (reference) x y z (current) [m], pressure [Pa], gap [m], active
   *    (0/1), slip_x slip_y slip_z [m], traction_x traction_y traction_z
   *    [Pa], for scripts.
   * @p records holds per step written its time and its series entry (the
   * .pvtu name, or the XDMF grid of the step).
   */
  void
  write_contact_surface(const ContactNodalData                      &data,
                        const std::string                           &directory,
                        const std::string                           &name,
                        const unsigned int                           step,
                        const double                                 time,
                        const OutputFormat                           format,
                        const MPI_Comm                               comm,
                        std::vector<std::pair<double, std::string>> &records);
} // namespace DuctileContact
