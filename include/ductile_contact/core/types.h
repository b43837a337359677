#pragma once

/**
 * @file
 * Names shared by every part of ductile-contact.
 *
 * The program is three-dimensional only (the paper's scene, contact and the
 * fourth-order phase field are all 3-D), so the space dimension is a constant
 * rather than a template parameter: this keeps every heavy deal.II template
 * instantiated once, which matters for compile times on small machines.
 */

#include <deal.II/base/types.h>

namespace DuctileContact
{
  /// Space dimension of every mesh in this program.
  constexpr unsigned int dim = 3;

  /**
   * Blocks of the global system [u | alpha | s] (doc/model.md section 1).
   * The block numbers never change, whether or not a scene has DoFs in a
   * block: a scene without plasticity simply has an empty alpha block.
   */
  namespace Block
  {
    constexpr unsigned int displacement = 0;
    constexpr unsigned int hardening    = 1;
    constexpr unsigned int phase_field  = 2;
    constexpr unsigned int n_blocks     = 3;
  } // namespace Block

  /// Vector components of the FE system: u_x, u_y, u_z, alpha, s.
  namespace Component
  {
    constexpr unsigned int first_displacement = 0;
    constexpr unsigned int hardening          = 3;
    constexpr unsigned int phase_field        = 4;
    constexpr unsigned int n_components       = 5;
  } // namespace Component
} // namespace DuctileContact
