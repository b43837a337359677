#pragma once

#include <deal.II/base/tensor.h>

#include <ductile_contact/core/types.h>

#include <array>

namespace DuctileContact
{
  /**
   * The mortar quantities of one slave node j (contact_problem.h) that its
   * contact law depends on, the "aggregates" a = (A, G, H, n):
   *
   *   A_j = sum_k D_jk                                 (nodal area) [m^2]
   *   G_j = sum_l M_jl x_l - sum_k D_jk x_k            (g_j = n_j . G_j) [m^3]
   *   H_j = sum_k D_jk (x_k - x_k,n) - sum_l M_jl (x_l - x_l,n)  [m^3]
   *   n_j                                              (unit nodal normal)
   *
   * (x_n: positions of the last accepted step).
   */
  struct NodalAggregates
  {
    double                 area = 0.;
    dealii::Tensor<1, dim> G, H, normal;
  };

  /// Enforcement parameters of a pair.
  struct NodalContactParameters
  {
    double penalty            = 0.; ///< eps_N [Pa/m]
    double tangential_penalty = 0.; ///< eps_T [Pa/m]
    double friction           = 0.; ///< mu_c
    /// Trial pressures above -threshold count as active (touching) [Pa].
    double activation_threshold = 0.;
  };

  /// State of a slave node after its contact law.
  struct NodalContactState
  {
    double gap      = 0.; ///< weighted gap g_j = n_j . G_j [m^3]
    double pressure = 0.; ///< lambda_j = max(0, trial) [Pa]
    bool   active   = false;
    /// Tangential traction t_j, its trial value [Pa] and 0 (none), 1
    /// (stick) or 2 (slip).
    dealii::Tensor<1, dim> traction, trial_traction;
    unsigned char          friction_state = 0;
    /// Slip of the slave relative to the master since the last accepted
    /// step, s_j = (I - n_j n_j) H_j / A_j [m].
    dealii::Tensor<1, dim> slip;
    /// A_j t_j . (slip_j - (t_j - t_old) / eps_T), (47) [J].
    double dissipation = 0.;
    /// The traction f_j = lambda_j n_j + t_j the slave node j transmits:
    /// the contact force is D_jk f_j on slave node k and -M_jl f_j on
    /// master node l [Pa].
    dealii::Tensor<1, dim> force_density;
    /// df_j / da (columns: A, G, H, n), exact for the branch taken.
    std::array<std::array<double, 10>, dim> jacobian{};
  };

  /**
   * Contact law of one slave node (doc/model.md section 5, KKT (44), Coulomb
   * (48)): augmented-Lagrangian pressure lambda_j = max(0, lambdahat_j -
   * eps_N g_j / A_j); where lambda_j > 0 and mu_c > 0, the slip since the
   * last accepted step s_j = (I - n_j n_j) H_j / A_j, the accepted
   * traction t_n rotated into the current tangent plane (length kept),
   * trial t_n + eps_T s_j, return map to the cone |t| <= mu_c lambda_j.
   *
   * A pure function of the aggregates; its Jacobian (forward AD over the
   * ten aggregates) is the nodal part of the consistent contact tangent.
   */
  NodalContactState
  nodal_contact(const NodalAggregates        &a,
                const double                  multiplier,
                const dealii::Tensor<1, dim> &committed_traction,
                const NodalContactParameters &parameters);
} // namespace DuctileContact
