#pragma once

#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/materials/material_response.h>

#include <functional>

namespace DuctileContact
{
  /**
   * Plane stress of a material point of a 2-D run (`Out-of-plane state =
   * plane stress`, doc/model.md section 2.2): the out-of-plane stretch
   * F_33 = lambda_3 is the one for which
   *
   *   P_33(F_ab, lambda_3) = 0,
   *
   * found by Newton's method on lambda_3 with the law's own dP_33/dF_33,
   * and every derivative the law returns is condensed at P_33 = 0 (so the
   * tangent is exact for the in-plane unknowns): with A = dP/dF and k = 33,
   *
   *   dP/dF_cD <- dP/dF_cD - dP/dF_k A_k,cD / A_k,k,
   *   dP/ds    <- dP/ds    - dP/dF_k dP_k/ds / A_k,k   (alpha alike),
   *
   * and alike for r and psi^+. The energy is the law's at lambda_3, so P_aB
   * = dPsi/dF_aB of the in-plane F (P_33 = 0). Forces, energies and works
   * stay per unit reference thickness.
   *
   * If lambda_3 is not found in 30 iterations (or would be <= 0), P is NaN:
   * the assembly then reports a residual that is not finite, and the load
   * step is cut back. The stretch found is returned in updated.stretch (the
   * history of an accepted step keeps it).
   *
   * @param law  the 3-D material law at F, always called with its tangent
   * @param F    the in-plane deformation gradient (F_33 = 1, F_a3 = F_3a = 0)
   * @param first_guess  lambda_3 to start from (the accepted step's)
   */
  MaterialResponse
  plane_stress(const std::function<MaterialResponse(
                 const dealii::Tensor<2, material_dim> &)> &law,
               const dealii::Tensor<2, material_dim>       &F,
               const double                                 first_guess);

  /// @p F with F_33 = @p stretch: the whole deformation gradient of a
  /// plane-stress point.
  inline dealii::Tensor<2, material_dim>
  with_stretch(const dealii::Tensor<2, material_dim> &F, const double stretch)
  {
    dealii::Tensor<2, material_dim> G = F;
    G[2][2]                           = stretch;
    return G;
  }
} // namespace DuctileContact
