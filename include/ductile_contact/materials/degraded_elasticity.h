#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/materials/degradation.h>
#include <ductile_contact/materials/material_response.h>

namespace DuctileContact
{
  /**
   * Degraded compressible neo-Hooke law of an elastic body that can crack
   * (no plasticity, C^p = I, so b^e = F F^T), doc/model.md (16)-(19) and (27):
   *
   *   Psi^e = g_vol(s) kappa/2 (J - 1)^2 + g_dev(s) mu/2 (tr bbar - 3),   (16)
   *   g_vol(s) = g_k(s) if J > 1, else 1;   g_dev(s) = g_k(s),            (17)
   *   tau = kappa g_vol(s) (J^2 - J) I + mu g_dev(s) dev[bbar],           (19)
   *   psi^+ = kappa/2 (J - 1)^2 [J > 1] + mu/2 (tr bbar - 3),             (27)
   *
   * with bbar = J^{-2/3} F F^T and g_k of degradation_value(). Compression
   * is never degraded, so a crack cannot interpenetrate.
   *
   * Built on neo_hooke(), which is linear in (mu, kappa): with P_vol, A_vol
   * its result for (0, kappa) and P_dev, A_dev for (mu, 0),
   *
   *   P = g_vol P_vol + g_dev P_dev,    A = g_vol A_vol + g_dev A_dev,
   *   dP/ds = g_vol' P_vol + g_dev' P_dev  (g_vol' = 0 for J <= 1),
   *   dpsi^+/dF = [J > 1] P_vol + P_dev.
   *
   * Each call evaluates the tangent of neo_hooke() once: for J > 1 both parts
   * carry the same factor g_k(s), so P, A = g_k(s) times the undegraded law;
   * for J <= 1 the law with (g_k(s) mu, kappa) gives P and A, and only
   * P_dev is evaluated on its own, without tangent. The jump of g_vol at
   * J = 1 is harmless: P_vol and psi_vol vanish there.
   *
   * dP_ds and dpsi_plus_dF are always filled (they cost nothing extra); A
   * only if @p with_tangent.
   *
   * @param F      deformation gradient, J = det F > 0 (the caller checks)
   * @param s      crack phase field, 0 intact, 1 broken
   * @param mu     shear modulus [Pa]
   * @param kappa  bulk modulus [Pa]
   * @param degradation  a_g and k of g_k(s)
   * @param with_tangent compute A (otherwise A is left zero)
   * @param split  the split (17); false: g_vol = g_dev = g_k(s) at every J
   *               and psi^+ the whole energy (Fracture/Energy split = none)
   */
  MaterialResponse
  degraded_neo_hooke(const dealii::Tensor<2, material_dim> &F,
                     const double                           s,
                     const double                           mu,
                     const double                           kappa,
                     const DegradationParameters           &degradation,
                     const bool                             with_tangent,
                     const bool                             split = true);
} // namespace DuctileContact
