#include <ductile_contact/materials/body_material.h>
#include <ductile_contact/materials/degraded_elasticity.h>
#include <ductile_contact/materials/neo_hooke.h>

namespace DuctileContact
{
  using namespace dealii;

  PointResponse
  evaluate_material(const BodyParameters      &body,
                    const Tensor<2, dim>      &F,
                    const PlasticHistory      &history_n,
                    const double               alpha,
                    const double               s,
                    const double               dt,
                    const bool                 with_tangent,
                    const std::optional<bool> &frozen_yielding)
  {
    PointResponse r;
    if (body.plasticity)
      {
        const PlasticResponse p = plastic_update(F,
                                                 history_n,
                                                 alpha,
                                                 body.fracture ? s : 0.,
                                                 dt,
                                                 body.material(),
                                                 with_tangent,
                                                 frozen_yielding);
        r.J                     = p.J;
        r.psi_elastic           = p.psi_elastic;
        r.psi_plus              = p.psi_plus;
        r.tau                   = p.tau;
        r.P                     = p.P;
        r.dP_dF                 = p.dP_dF;
        r.dP_dalpha             = p.dP_dalpha;
        r.dP_ds                 = p.dP_ds;
        r.r                     = p.r;
        r.dr_dalpha             = p.dr_dalpha;
        r.dr_ds                 = p.dr_ds;
        r.dr_dF                 = p.dr_dF;
        r.yielding              = p.yielding;
        r.trial_yielding        = p.trial_yielding;
        r.dpsi_plus_dF          = p.dpsi_plus_dF;
        r.dpsi_plus_dalpha      = p.dpsi_plus_dalpha;
        r.dpsi_plus_ds          = p.dpsi_plus_ds;
        r.updated               = p.updated;
      }
    else if (body.fracture)
      {
        const DegradedResponse d =
          degraded_neo_hooke(F,
                             s,
                             body.shear_modulus,
                             body.bulk_modulus,
                             {body.crack.degradation_a,
                              body.crack.residual_stiffness},
                             with_tangent);
        r.J            = d.J;
        r.psi_elastic  = d.psi;
        r.psi_plus     = d.psi_plus;
        r.tau          = d.tau;
        r.P            = d.P;
        r.dP_dF        = d.A;
        r.dP_ds        = d.dP_ds;
        r.dpsi_plus_dF = d.dpsi_plus_dF;
      }
    else
      {
        const MaterialResponse m =
          neo_hooke(F, body.shear_modulus, body.bulk_modulus, with_tangent);
        r.J           = m.J;
        r.psi_elastic = m.psi;
        r.psi_plus    = m.psi;
        r.tau         = m.tau;
        r.P           = m.P;
        r.dP_dF       = m.A;
      }
    return r;
  }
} // namespace DuctileContact
