#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <ductile_contact/core/option.h>

#include <string>

namespace DuctileContact
{
  /// Contact pair/Multiplier basis on the slave faces.
  enum class MultiplierBasis
  {
    dual,
    standard
  };

  inline const NameTable<MultiplierBasis> &
  multiplier_basis_names()
  {
    static const NameTable<MultiplierBasis> t{{MultiplierBasis::dual, "dual"},
                                              {MultiplierBasis::standard,
                                               "standard"}};
    return t;
  }

  /// Contact pair/Enforcement of the non-penetration and friction
  /// conditions.
  enum class ContactEnforcement
  {
    augmented_lagrangian,
    semi_smooth_newton
  };

  inline const NameTable<ContactEnforcement> &
  contact_enforcement_names()
  {
    static const NameTable<ContactEnforcement> t{
      {ContactEnforcement::augmented_lagrangian, "augmented Lagrangian"},
      {ContactEnforcement::semi_smooth_newton, "semi-smooth Newton"}};
    return t;
  }

  /**
   * One contact pair, subsection `Contact pair <n>` (doc/model.md section 5,
   * doc/contact.md). The slave side carries the nodal contact pressures and the
   * integration; make it the finer of the two meshes. Both surfaces must be
   * boundaries of FE_Q(2) bodies (quad9 faces; line3 in plane strain).
   *
   * Enforcement (ContactEnforcement):
   * - augmented Lagrangian on the nodal weighted gaps: lambda_j = max(0,
   *   lambdahat_j - eps_N g_j / A_j), Newton for fixed multipliers
   *   lambdahat, then lambdahat <- lambda (Uzawa) until the largest
   *   penetration is below the tolerance. Coulomb friction (48): trial
   *   traction t_n (rotated into the current tangent plane) + eps_T s_j
   *   with the nodal slip increment s_j, return map to mu_c lambda_j.
   * - semi-smooth Newton: the dual multipliers are condensed from the
   *   slave rows and the active set and stick/slip are found in the one
   *   Newton loop through nodal complementarity functions
   *   (nodal_complementarity.h); eps_N and eps_T are then only the
   *   complementarity parameters c_N and c_T (they do not change the
   *   answer): the weighted gap is zero on the active set and sticking
   *   nodes do not slip.
   */
  struct ContactPairParameters
  {
    unsigned int               number             = 1;
    dealii::types::boundary_id slave_boundary_id  = 0;
    dealii::types::boundary_id master_boundary_id = 1;
    /// Coulomb coefficient mu_c.
    double friction_coefficient = 0.;
    /// eps_T = tangential_penalty_factor * E_slave / h_slave [Pa/m].
    double tangential_penalty_factor = 1.;
    /// eps_N = penalty_factor * E_slave / h_slave [Pa/m].
    double penalty_factor = 10.;
    /// Broad-phase enlargement of the face boxes [m]; 0: the largest face
    /// diameter of the two surfaces.
    double search_radius = 0.;
    /// Largest allowed penetration, relative to the smallest slave face
    /// size.
    double penetration_tolerance = 1e-6;
    /// Multiplier basis on the slave faces: dual (biorthogonal, D
    /// diagonal) or standard (Phi_j = N_j).
    MultiplierBasis multiplier_basis = MultiplierBasis::dual;
    /// Uzawa updates per load step before the step counts as failed.
    unsigned int       max_augmentations = 30;
    ContactEnforcement enforcement = ContactEnforcement::semi_smooth_newton;

    void
    declare(dealii::ParameterHandler &prm);

    /// Throws InputError for inconsistent entries.
    void
    check() const;

    std::string
    subsection() const;
  };
} // namespace DuctileContact
