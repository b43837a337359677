#include <ductile_contact/materials/degraded_elasticity.h>
#include <ductile_contact/materials/neo_hooke.h>

namespace DuctileContact
{
  using namespace dealii;

  MaterialResponse
  degraded_neo_hooke(const Tensor<2, material_dim> &F,
                     const double                   s,
                     const double                   mu,
                     const double                   kappa,
                     const DegradationParameters   &degradation,
                     const bool                     with_tangent,
                     const bool                     split)
  {
    const double g  = degradation_value(s, degradation);
    const double dg = degradation_derivative(s, degradation);

    MaterialResponse r;
    // neo_hooke() is linear in (mu, kappa) in psi, tau, P and A, so the
    // degraded law is the undegraded one with scaled moduli: one tangent
    // evaluation instead of one per part.
    if (!split || determinant(F) > 1.)
      {
        // Tension, or no split: g_vol = g_dev = g, psi^+ is the whole
        // undegraded energy.
        const MaterialResponse full = neo_hooke(F, mu, kappa, with_tangent);

        r.J            = full.J;
        r.psi_elastic  = g * full.psi_elastic;
        r.psi_plus     = full.psi_elastic;
        r.tau          = g * full.tau;
        r.P            = g * full.P;
        r.dP_ds        = dg * full.P;
        r.dpsi_plus_dF = full.P;

        if (with_tangent)
          r.dP_dF = g * full.dP_dF;
      }
    else
      {
        // Compression: only the deviatoric part degrades and drives cracks.
        const MaterialResponse degraded =
          neo_hooke(F, g * mu, kappa, with_tangent);
        const MaterialResponse deviatoric = neo_hooke(F, mu, 0., false);

        r.J            = degraded.J;
        r.psi_elastic  = degraded.psi_elastic;
        r.psi_plus     = deviatoric.psi_elastic;
        r.tau          = degraded.tau;
        r.P            = degraded.P;
        r.dP_ds        = dg * deviatoric.P;
        r.dpsi_plus_dF = deviatoric.P;

        if (with_tangent)
          r.dP_dF = degraded.dP_dF;
      }
    return r;
  }
} // namespace DuctileContact
