#pragma once

#include <deal.II/lac/affine_constraints.h>

#include <ductile_contact/contact/enforcement.h>
#include <ductile_contact/discretisation/discretisation.h>

namespace DuctileContact
{
  /**
   * Augmented-Lagrangian enforcement of a contact pair (nodal_contact()):
   * lambda_j = max(0, lambdahat_j - eps_N g_j / A_j), Coulomb friction with
   * a tangential penalty and the return map on the slip since the last
   * accepted step; node j transmits f_j = lambda_j n_j + t_j, i.e. D_jk f_j
   * on slave node k and -M_jl f_j on master node l. Newton iterates with
   * lambdahat fixed; outer_update() then sets lambdahat <- lambda until the
   * largest penetration max_j (-g_j / A_j) is below the pair's tolerance.
   * The tangent d(D_jk f_j) = dD_jk f_j + D_jk (df_j/da)(da/dx) takes dD
   * and dM from ContactProblem::linearise_operators() and df_j/da from AD
   * of the nodal law.
   */
  class AugmentedLagrangian : public Enforcement
  {
  public:
    explicit AugmentedLagrangian(ContactProblem &problem);

    bool
    condenses() const override
    {
      return false;
    }

    bool
    linearises_in_integration() const override
    {
      return false;
    }

    /// The nodal law at every node of @p pair with its multipliers, then
    /// the contact rows and their tangent into @p targets (not compressed).
    void
    assemble(ContactPair                             &pair,
             const dealii::AffineConstraints<double> &constraints,
             const AssemblyTargets                   &targets) const override;

    /// lambdahat_j <- lambda_j at every node when the largest penetration
    /// exceeds the pair's tolerance.
    bool
    outer_update(ContactPair              &pair,
                 const ContactPairSummary &summary) const override;

  private:
    /// The nodal contact law of every node of @p pair, and its summary.
    void
    apply_law(ContactPair &pair) const;

    ContactProblem       &problem;
    const Discretisation &discretisation;
  };
} // namespace DuctileContact
