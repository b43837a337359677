#pragma once

/**
 * @file
 * Names shared by every part of ductile-contact.
 *
 * The space dimension is a constant of each build rather than a template
 * parameter: the library is compiled once with DUCTILE_CONTACT_DIM = 3 and
 * once with 2 (plane strain), and the program picks the build that the
 * input's `Dimension` names (source/main.cc). This keeps every heavy
 * deal.II template instantiated once per build, which matters for compile
 * times on small machines. The sources that do not depend on the dimension
 * (parameters, the linear algebra, the statistics table) are compiled once,
 * without DUCTILE_CONTACT_DIM: there `dim` and the component layout are not
 * declared, so that a use of either in such a source fails to compile
 * (CMakeLists.txt, ductile_contact_common).
 */

#include <deal.II/base/types.h>

namespace DuctileContact
{
#ifdef DUCTILE_CONTACT_DIM
  /// Space dimension of every mesh of this build: 3, or 2 in plane strain.
  constexpr unsigned int dim = DUCTILE_CONTACT_DIM;
  static_assert(dim == 2 || dim == 3, "DUCTILE_CONTACT_DIM must be 2 or 3");
#endif

  /**
   * Dimension of the material point, 3 in every build: in plane strain the
   * deformation gradient is F = [[F_2x2, 0], [0, 1]] and the laws of
   * materials/ (the isochoric split, F = Fe Fp, the out-of-plane plastic
   * stretch, tau_33) stay the 3-D ones (doc/model.md section 2.2).
   */
  constexpr unsigned int material_dim = 3;

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

#ifdef DUCTILE_CONTACT_DIM
  /// Vector components of the FE system: u_x, u_y (, u_z), alpha, s.
  namespace Component
  {
    constexpr unsigned int first_displacement = 0;
    constexpr unsigned int hardening          = dim;
    constexpr unsigned int phase_field        = dim + 1;
    constexpr unsigned int n_components       = dim + 2;
  } // namespace Component
#endif
} // namespace DuctileContact
