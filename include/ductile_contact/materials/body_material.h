#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/materials/plasticity.h>

#include <optional>

namespace DuctileContact
{
  /**
   * Everything the assembly needs from one material point of a body, in
   * one form whatever physics the body carries. Derivatives that do not
   * apply (no alpha or no s in the body) are zero.
   */
  struct PointResponse
  {
    double                          J           = 1.;
    double                          psi_elastic = 0.; ///< Psi^e (16), degraded
    double                          psi_plus    = 0.; ///< psi^+ (27)
    dealii::SymmetricTensor<2, dim> tau;
    dealii::Tensor<2, dim>          P;
    dealii::Tensor<4, dim>          dP_dF;
    dealii::Tensor<2, dim>          dP_dalpha, dP_ds;

    /// Local part of the hardening equation (50) per unit volume and its
    /// derivatives (plastic bodies only).
    double                 r = 0., dr_dalpha = 0., dr_ds = 0.;
    dealii::Tensor<2, dim> dr_dF;
    bool                   yielding = false, trial_yielding = false;

    dealii::Tensor<2, dim> dpsi_plus_dF;
    double                 dpsi_plus_dalpha = 0., dpsi_plus_ds = 0.;

    /// (C^p)^{-1} and alpha after this step (plastic bodies only).
    PlasticHistory updated;
  };

  /**
   * The material law of a body as a pure function of the kinematics and
   * the history (model.md sections 2-3): neo-Hooke (16) for an elastic
   * body, the degraded neo-Hooke law with the split (17) for an elastic
   * body that cracks, the visco-plastic update of section 3 (steps 1-3) for
   * a body that yields (degraded when it also cracks).
   *
   * @param alpha  the hardening field at the point (ignored without
   *               plasticity)
   * @param s      the phase field at the point (0 without fracture)
   * @param dt     the load step (the viscous terms are backward Euler)
   */
  PointResponse
  evaluate_material(const BodyParameters         &body,
                    const dealii::Tensor<2, dim> &F,
                    const PlasticHistory         &history_n,
                    const double                  alpha,
                    const double                  s,
                    const double                  dt,
                    const bool                    with_tangent,
                    const std::optional<bool>    &frozen_yielding = {});
} // namespace DuctileContact
