#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/materials/material_response.h>

namespace DuctileContact
{
  /**
   * Compressible neo-Hooke law of doc/model.md (16) and (19) for an intact
   * (s = 0), elastic (C^p = I) material point:
   *
   *   Psi = kappa/2 (J - 1)^2 + mu/2 (tr bbar - 3),  bbar = J^{-2/3} F F^T,
   *   tau = kappa (J^2 - J) I + mu dev[bbar].
   *
   * The tangent is exact: A_aBcD = F^{-1}_Bb F^{-1}_Dd (c_abcd + delta_ac
   * tau_bd), with c the spatial Kirchhoff tangent (c = J x Eulerian tangent;
   * volumetric part kappa (2J^2 - J) I x I - 2 kappa (J^2 - J) II, isochoric
   * part 2/3 mu tr(bbar) PP - 2/3 (tau_iso x I + I x tau_iso), PP the
   * deviatoric projector).
   *
   * A pure function of F and the moduli; J must be positive (the caller
   * checks, see Newton's line search).
   *
   * @param mu     shear modulus [Pa]
   * @param kappa  bulk modulus [Pa]
   * @param with_tangent  compute A (otherwise A is left zero)
   */
  MaterialResponse
  neo_hooke(const dealii::Tensor<2, material_dim> &F,
            const double                           mu,
            const double                           kappa,
            const bool                             with_tangent);

  /// A from the spatial tangent c and tau (see neo_hooke()).
  dealii::Tensor<4, material_dim>
  first_elasticity_tensor(const dealii::Tensor<2, material_dim>          &F_inv,
                          const dealii::SymmetricTensor<4, material_dim> &c,
                          const dealii::SymmetricTensor<2, material_dim> &tau);

  /// von Mises equivalent sqrt(3/2 dev(t):dev(t)) of a stress tensor.
  inline double
  von_mises(const dealii::SymmetricTensor<2, material_dim> &t)
  {
    const auto d = dealii::deviator(t);
    return std::sqrt(1.5 * (d * d));
  }
} // namespace DuctileContact
