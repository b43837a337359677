#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>

namespace DuctileContact
{
  /// Quadrature-point history of the plastic update, committed only on
  /// accepted steps (doc/model.md section 3).
  struct PlasticHistory
  {
    /// (C^p)^{-1}, symmetric with determinant 1.
    dealii::SymmetricTensor<2, material_dim> Cp_inv =
      dealii::unit_symmetric_tensor<material_dim>();
    /// alpha_n
    double alpha = 0.;
    /// r_n, the local part r of (50) at the accepted state, in Pa: the
    /// force with which the rest of the alpha field (the gradient term, the
    /// interpolation shared by a cell's points) holds the point where it
    /// is. Non-yielding points keep it (doc/model.md section 3.1, choice 3).
    double r = 0.;
    /// F_33 of the accepted state in plane stress (plane_stress(); 1
    /// otherwise): the start of the next step's plastic work and the first
    /// guess of the next stretch.
    double stretch = 1.;
  };

  /**
   * What every material law of this program returns for one material point
   * (neo_hooke(), degraded_neo_hooke(), plastic_update(), and
   * evaluate_material() which picks one per body): per reference volume,
   * energies in J/m^3, stresses and their derivatives in Pa. Members that a
   * law does not have (no alpha, no s, no tangent requested) stay zero.
   */
  struct MaterialResponse
  {
    /// J = det F.
    double J = 1.;
    /// Stored energy Psi^e of doc/model.md (16), degraded where the body
    /// cracks.
    double psi_elastic = 0.;
    /// Crack driving energy psi^+ of doc/model.md (27): H = -g_k'(s) psi^+.
    double psi_plus = 0.;
    /// Kirchhoff stress tau of doc/model.md (18)-(19).
    dealii::SymmetricTensor<2, material_dim> tau;
    /// First Piola-Kirchhoff stress P = tau F^{-T}.
    dealii::Tensor<2, material_dim> P;
    /// dP/dF, [a][B][c][D] = dP_aB / dF_cD; dP/dalpha, dP/ds.
    dealii::Tensor<4, material_dim> dP_dF;
    dealii::Tensor<2, material_dim> dP_dalpha, dP_ds;
    /// Local part r of the hardening equation (50) per unit volume and its
    /// derivatives (plastic bodies only).
    double                          r = 0., dr_dalpha = 0., dr_ds = 0.;
    dealii::Tensor<2, material_dim> dr_dF;
    /// chi_p used, and chi_p of the trial-state test (they differ only when
    /// a frozen switch was imposed).
    bool yielding = false, trial_yielding = false;
    /// dpsi^+/dF, dpsi^+/dalpha, dpsi^+/ds (psi^+ depends on s where chi_p
    /// = 0 and alpha != alpha_n, see plastic_update()).
    dealii::Tensor<2, material_dim> dpsi_plus_dF;
    double                          dpsi_plus_dalpha = 0., dpsi_plus_ds = 0.;
    /// (C^p)^{-1} and alpha after this step (plastic bodies only).
    PlasticHistory updated;
  };
} // namespace DuctileContact
