#pragma once

#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/contact_surface.h>

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
  };

  /**
   * Output of one slave surface after an accepted step (written by one
   * rank; the surface is replicated):
   *  - `<name>_NNNNN.vtu`: the deformed slave faces (VTK biquadratic quads)
   *    with point data pressure [Pa], gap [m] (negative: penetration),
   *    active, and the vectors normal, slip [m] (of the step), traction
   *    (tangential) [Pa]; `<name>.pvd` lists every step written (ParaView);
   *  - `<name>_NNNNN.txt`: one row per slave node, columns X Y Z (reference)
   *    x y z (current) [m], pressure [Pa], gap [m], active (0/1), slip_x
   *    slip_y slip_z [m], traction_x traction_y traction_z [Pa], for
   *    scripts.
   * @p records holds (time, vtu file) of the steps written so far.
   */
  void
  write_contact_surface(const ContactNodalData                      &data,
                        const std::string                           &directory,
                        const std::string                           &name,
                        const unsigned int                           step,
                        const double                                 time,
                        std::vector<std::pair<double, std::string>> &records);
} // namespace DuctileContact
