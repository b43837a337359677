#pragma once

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/materials/material_response.h>
#include <ductile_contact/materials/plasticity.h>

#include <optional>

namespace DuctileContact
{
  /**
   * The material law of a body as a pure function of the kinematics and
   * the history (doc/model.md sections 2-3): neo-Hooke (16) for an elastic
   * body, the degraded neo-Hooke law with the split (17) for an elastic
   * body that cracks, the visco-plastic update of section 3 (steps 1-3) for
   * a body that yields (degraded when it also cracks).
   *
   * @param alpha  the hardening field at the point (ignored without
   *               plasticity)
   * @param s      the phase field at the point (0 without fracture)
   * @param dt     the load step (the viscous terms are backward Euler)
   */
  MaterialResponse
  evaluate_material(const BodyParameters                  &body,
                    const dealii::Tensor<2, material_dim> &F,
                    const PlasticHistory                  &history_n,
                    const double                           alpha,
                    const double                           s,
                    const double                           dt,
                    const bool                             with_tangent,
                    const std::optional<bool> &frozen_yielding = {});
} // namespace DuctileContact
