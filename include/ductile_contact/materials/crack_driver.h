#pragma once

#include <deal.II/base/tensor.h>

#include <ductile_contact/core/option.h>
#include <ductile_contact/core/types.h>
#include <ductile_contact/materials/material_response.h>
#include <ductile_contact/materials/plasticity.h>

namespace DuctileContact
{
  /// Fracture/Crack driver: which energy density drives the phase field.
  enum class CrackDriverType
  {
    /// psi^+ of doc/model.md (27), the paper's driver.
    elastic,
    /// zeta <psi^+ + W_p(alpha) - w_c>, plastic work drives the crack too
    /// (not derived from the free energy).
    elastic_plastic,
    /// psi^+ + phi(W_p(alpha)): -dPsi/ds of the elastic energy and of the
    /// degraded plastic energy (plastic_energy_density()), variational.
    elastic_plastic_energy
  };

  inline const NameTable<CrackDriverType> &
  crack_driver_names()
  {
    static const NameTable<CrackDriverType> t{
      {CrackDriverType::elastic, "elastic"},
      {CrackDriverType::elastic_plastic, "elastic plus plastic work"},
      {CrackDriverType::elastic_plastic_energy, "elastic and plastic energy"}};
    return t;
  }

  /// A crack driving energy density psi_D [J/m^3] at a material point and
  /// its derivatives with respect to F, alpha and s.
  struct DrivingEnergy
  {
    double value = 0.;
    /// The part of value that is -dPsi/ds / (-g_k'(s)) of the free energy:
    /// psi^+, and with 'elastic and plastic energy' all of it. The history
    /// driving work counts the work of the driver beyond it.
    double                          variational = 0.;
    dealii::Tensor<2, material_dim> d_dF;
    double                          d_dalpha = 0., d_ds = 0.;
  };

  /// The parameters of the plastic work driver.
  struct PlasticWorkDriver
  {
    /// w_c: critical work density [J/m^3].
    double critical_work_density = 0.;
    /// zeta: driver factor [-].
    double factor = 1.;
  };

  /**
   * The energy density psi_D that drives the crack in (51), H =
   * -g_k'(s) max_t psi_D, a pure function of the material point's
   * response @p m (psi^+ and its derivatives) and of alpha:
   *
   *  - elastic (doc/model.md (27), the paper): psi_D = psi^+;
   *  - elastic plus plastic work (after Miehe, Hofacker, Schaenzel &
   *    Aldakheel 2015, CMAME 294, and Miehe, Aldakheel & Raina 2016, IJP
   *    84: a crack driving state function of the elastic and the plastic
   *    energy above a critical work density):
   *      psi_D = zeta < psi^+ + W_p(alpha) - w_c >,   <x> = max(x, 0),
   *    with W_p of plastic_work_density(), w_c = Critical work density and
   *    zeta = Driver factor (Miehe's zeta g_c/(l_f psi_c) in our units:
   *    it sets how fast the crack grows once the work exceeds w_c,
   *    independently of the crack energy g_c). Below w_c nothing drives
   *    the crack; a metal that has dissipated zeta W_p ~ g_c/(2 l_f) per
   *    unit volume tears, whatever its elastic energy (which yield-limited
   *    stresses keep small).
   *
   *  - elastic and plastic energy (variational; doc/model.md section 4.3,
   *    after Borden, Hughes, Landis, Anvari & Lee 2016, CMAME 312, and
   *    Miehe, Aldakheel & Raina 2016): the plastic energy above w_c is
   *    degraded with the phase field, Psi^p_loc = W_p - (1 - g_k(s))
   *    phi(W_p) (plastic_energy_density()), and
   *      psi_D = psi^+ + phi(W_p(alpha)),
   *    so that H = -g_k'(s) psi_D = -dPsi/ds: the crack is paid by the
   *    elastic and plastic energy the solid gives up, and the flow
   *    resistance falls with it (plastic_update()). zeta is not used.
   *
   * The derivatives are exact (those of psi^+ come from the material law's
   * automatic differentiation; dW_p/dalpha = yhat(alpha)); where the
   * bracket is closed they are zero. The second driver does not derive
   * from the free energy: the work it does on s beyond the elastic energy
   * appears in the energy balance as history driving work.
   */
  DrivingEnergy
  crack_driving_energy(const MaterialResponse     &m,
                       const double                alpha,
                       const CrackDriverType       driver,
                       const PlasticWorkDriver    &work_driver,
                       const PlasticityParameters &plastic);
} // namespace DuctileContact
