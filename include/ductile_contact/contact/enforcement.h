#pragma once

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/contact/contact_pair.h>
#include <ductile_contact/contact/contact_parameters.h>
#include <ductile_contact/contact/mortar_operators.h>

#include <memory>
#include <vector>

namespace DuctileContact
{
  class ContactProblem;

  /**
   * How a contact pair enforces the normal contact conditions (44) and
   * Coulomb's law (48) at its slave nodes, from the mortar operators D and M
   * and the nodal aggregates (area A_j, weighted gap, slip, normal) that
   * ContactProblem computes on the current geometry, with their derivatives
   * (ContactProblem::linearise_operators()).
   *
   * An enforcement makes the nodal tractions f_j, adds the contact rows
   * (D_jk f_j on slave node k, -M_jl f_j on master node l) with their
   * tangent, and may update multipliers between Newton solves. The
   * strategies: SemiSmoothNewton (the tractions condensed from the bulk
   * rows, semi_smooth_newton.cc) and AugmentedLagrangian (a penalty on
   * fixed multipliers with Uzawa updates, augmented_lagrangian.cc), chosen
   * per pair by `Contact pair/Enforcement`.
   */
  class Enforcement
  {
  public:
    virtual ~Enforcement() = default;

    /// Whether the tractions are condensed from the complete bulk rows of
    /// the slave nodes: assemble() then needs those rows complete, D is
    /// lumped to its row's node, the master rows couple to the slave rows'
    /// columns, and a hanging slave node hands its share to its parents.
    virtual bool
    condenses() const = 0;

    /// Whether integrate() keeps the derivatives of D and M of its share of
    /// the face pairs for a tangent assembly (assemble() then uses them
    /// where they were made).
    virtual bool
    linearises_in_integration() const = 0;

    /// Throws InputError (on every rank) when @p pair cannot be enforced
    /// this way on the current mesh; after ContactProblem::setup().
    virtual void
    check(const ContactPair &pair) const;

    /// Per slave node j of @p pair, the columns its master rows take besides
    /// the contact couplings (empty: none).
    virtual std::vector<std::vector<dealii::types::global_dof_index>>
    master_row_columns(const ContactPair &pair) const;

    /// Adds the contact terms of @p pair at its current geometry to
    /// @p targets (not compressed; with condenses() the bulk terms there
    /// are complete in the slave rows) and summarises the pair.
    virtual void
    assemble(ContactPair                             &pair,
             const dealii::AffineConstraints<double> &constraints,
             const AssemblyTargets                   &targets) const = 0;

    /// After a converged Newton solve: updates the multipliers of @p pair
    /// (summarised by @p summary); returns true when it needs no update
    /// (then nothing changed).
    virtual bool
    outer_update(ContactPair &pair, const ContactPairSummary &summary) const;
  };

  /// The Enforcement of @p kind for the pairs of @p problem.
  std::unique_ptr<Enforcement>
  make_enforcement(ContactEnforcement kind, ContactProblem &problem);
} // namespace DuctileContact
