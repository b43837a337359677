#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/degraded_elasticity.h>
#include <ductile_contact/materials/linear_elasticity.h>
#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/materials/plane_stress.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The 3-D law of the body at F.
    MaterialResponse
    three_dimensional(const BodyParameters          &body,
                      const Tensor<2, material_dim> &F,
                      const PlasticHistory          &history_n,
                      const double                   alpha,
                      const double                   s,
                      const double                   dt,
                      const bool                     with_tangent,
                      const std::optional<bool>     &frozen_yielding)
    {
      if (body.plasticity)
        return plastic_update(F,
                              history_n,
                              alpha,
                              body.fracture ? s : 0.,
                              dt,
                              body.material(),
                              with_tangent,
                              frozen_yielding);
      if (body.elastic_law == ElasticLaw::linear)
        // Intact: s = 0 and the whole energy drives a crack.
        return degraded_linear_elasticity(F,
                                          body.fracture ? s : 0.,
                                          body.shear_modulus,
                                          body.bulk_modulus,
                                          {body.crack.degradation_a,
                                           body.crack.residual_stiffness},
                                          body.fracture ? body.crack.split
                                                        : EnergySplit::none,
                                          with_tangent);
      if (body.fracture)
        return degraded_neo_hooke(F,
                                  s,
                                  body.shear_modulus,
                                  body.bulk_modulus,
                                  {body.crack.degradation_a,
                                   body.crack.residual_stiffness},
                                  with_tangent,
                                  body.crack.split ==
                                    EnergySplit::volumetric_deviatoric);
      // An intact elastic body: its whole energy would drive a crack.
      MaterialResponse r =
        neo_hooke(F, body.shear_modulus, body.bulk_modulus, with_tangent);
      r.psi_plus = r.psi_elastic;
      return r;
    }
  } // namespace



  MaterialResponse
  evaluate_material(const BodyParameters          &body,
                    const Tensor<2, material_dim> &F,
                    const PlasticHistory          &history_n,
                    const double                   alpha,
                    const double                   s,
                    const double                   dt,
                    const bool                     with_tangent,
                    const std::optional<bool>     &frozen_yielding)
  {
    if (!body.plane_stress)
      return three_dimensional(
        body, F, history_n, alpha, s, dt, with_tangent, frozen_yielding);
    // The stretch lambda_3 needs the law's dP_33/dF_33 at every evaluation.
    return plane_stress(
      [&](const Tensor<2, material_dim> &F3) {
        return three_dimensional(
          body, F3, history_n, alpha, s, dt, true, frozen_yielding);
      },
      F,
      history_n.stretch);
  }
} // namespace DuctileContact
