#pragma once

/**
 * @file
 * The default of every material parameter, defined once: the in-class
 * defaults of BodyParameters, FractureParameters and PlasticityParameters
 * (and so the defaults --print-parameters shows) all refer to these.
 * The hardening values are the paper's aluminium (doc/model.md section 7).
 */
namespace DuctileContact
{
  namespace MaterialDefaults
  {
    constexpr double shear_modulus       = 80.e9;  ///< mu [Pa]
    constexpr double bulk_modulus        = 160.e9; ///< kappa [Pa]
    constexpr double initial_yield       = 95.e6;  ///< y_0 [Pa]
    constexpr double saturation_yield    = 110.e6; ///< y_inf [Pa]
    constexpr double saturation_exponent = 25.4;   ///< eta of (21)
    constexpr double linear_hardening    = 0.;     ///< h of (21) [Pa]
    constexpr double plastic_viscosity   = 1.e6;   ///< eta_p of (34) [Pa t]
    constexpr double degradation_a       = 2.;     ///< a_g of g(s)
    constexpr double residual_stiffness  = 1.e-8;  ///< k of g_k(s)
    /// delta of the smoothed switch of (17) [J]; 0: sharp.
    constexpr double volumetric_switch_width = 0.;
  } // namespace MaterialDefaults
} // namespace DuctileContact
