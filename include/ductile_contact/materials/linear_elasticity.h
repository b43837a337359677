#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/material_response.h>
#include <ductile_contact/phase_field/regularisation.h>

namespace DuctileContact
{
  /**
   * Degraded small-strain linear elasticity of an elastic body (Body k/
   * Elastic law = linear), doc/model.md section 2.3: with eps = sym(F) - I,
   * lambda = kappa - 2 mu/3,
   *
   *   psi(eps)  = lambda/2 (tr eps)^2 + mu eps : eps = psi^+ + psi^-,
   *   Psi^e     = g_k(s) psi^+ + psi^-,    P = tau = g_k(s) sigma^+ + sigma^-,
   *
   * sigma^+- = d psi^+- / d eps, with the split of Fracture/Energy split:
   *  - none: psi^+ = psi;
   *  - volumetric-deviatoric (Amor, Marigo & Maurini 2009):
   *    psi^+ = kappa/2 <tr eps>_+^2 + mu |dev eps|^2;
   *  - spectral (Miehe, Welschinger & Hofacker 2010):
   *    psi^+ = lambda/2 <tr eps>_+^2 + mu tr(eps_+^2), eps_+ = sum_i
   *    <e_i>_+ n_i x n_i over the principal strains e_i.
   *
   * The tangent is exact: d eps_+/d eps by the Daleckii-Krein formula,
   * theta_ij (n_i x n_j) x (n_i x n_j) with theta_ii = H(e_i) and theta_ij
   * the divided difference of <.>_+ (H(0) = 0: at a kink the one-sided
   * derivative of the tension side). dP/dF = dP/d eps (minor-symmetric),
   * dP/ds = g_k'(s) sigma^+, dpsi^+/dF = sigma^+.
   *
   * Small strain: not frame-indifferent, for the comparisons with codes at
   * small strain (pfm-cracks' notched tension and shear).
   *
   * @param F      deformation gradient (3 x 3; F_33 = 1 in plane strain)
   * @param s      crack phase field, 0 intact, 1 broken (s = 0 and the
   *               split none for an intact elastic body)
   * @param mu     shear modulus [Pa]
   * @param kappa  bulk modulus [Pa]
   * @param with_tangent compute dP/dF (otherwise it is left zero)
   */
  MaterialResponse
  degraded_linear_elasticity(const dealii::Tensor<2, material_dim> &F,
                             const double                           s,
                             const double                           mu,
                             const double                           kappa,
                             const DegradationParameters           &degradation,
                             const EnergySplit                      split,
                             const bool with_tangent);

  /**
   * The positive part X_+ = sum_i <x_i>_+ n_i x n_i of a symmetric tensor
   * and, if @p derivative is given, dX_+/dX (minor-symmetric, the
   * Daleckii-Krein formula of degraded_linear_elasticity()).
   */
  dealii::SymmetricTensor<2, material_dim>
  positive_part(const dealii::SymmetricTensor<2, material_dim> &X,
                dealii::Tensor<4, material_dim> *derivative = nullptr);
} // namespace DuctileContact
