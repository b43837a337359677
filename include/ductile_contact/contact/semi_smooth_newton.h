#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>

#include <ductile_contact/contact/enforcement.h>
#include <ductile_contact/contact/nodal_complementarity.h>
#include <ductile_contact/discretisation/discretisation.h>

#include <array>
#include <map>
#include <vector>

namespace DuctileContact
{
  /**
   * Semi-smooth Newton enforcement of a contact pair (Popp, Gee & Wall
   * 2009; doc/contact.md). With the dual basis the slave row of node j reads
   * R_j + A_j f_j = 0 (D lumped to its row sum A_j), so the traction is
   * condensed as f_j(u) = -R_j(u) / A_j from the bulk residual; the slave
   * rows become the complementarity function -C_j(a_j, f_j)
   * (nodal_complementarity.h) and the master rows R_l - sum_j M_jl f_j.
   * The linearised system is the bulk one with the slave rows combined
   * into C_f / A_j K_j and added, as M_jl / A_j K_j, to the master rows,
   * plus the terms of dD, dM and dn (ContactProblem::linearise_operators(),
   * each rank's share of them added where it was made: they are linear in
   * them). The active set and stick/slip follow from the iterate, with no
   * state and no outer loop; a DoF of a slave node fixed by a Dirichlet
   * condition carries no traction (f_j,c = 0). A hanging slave node hands
   * its area, gap, slip and master weights to its parents
   * (ContactProblem::fold_hanging_nodes()).
   */
  class SemiSmoothNewton : public Enforcement
  {
  public:
    explicit SemiSmoothNewton(ContactProblem &problem);

    bool
    condenses() const override
    {
      return true;
    }

    bool
    linearises_in_integration() const override
    {
      return true;
    }

    /// Throws InputError (on every rank) when a slave node of @p pair
    /// hangs on a node off the slave surface or belongs to another pair
    /// too.
    void
    check(const ContactPair &pair) const override;

    /// The columns of the bulk rows of the owned slave nodes (DoFs of the
    /// cells around them): the master rows take those rows.
    std::vector<std::vector<dealii::types::global_dof_index>>
    master_row_columns(const ContactPair &pair) const override;

    /// Condenses the tractions from the compressed bulk system in
    /// @p targets and adds the rows (not compressed).
    void
    assemble(ContactPair                             &pair,
             const dealii::AffineConstraints<double> &constraints,
             const AssemblyTargets                   &targets) const override;

  private:
    using Matrix3 = std::array<std::array<double, dim>, dim>;


    /// What assemble() knows of the slave nodes: which this rank
    /// condenses, which of their DoFs are free, their complementarity.
    struct CondensedNodes
    {
      std::vector<bool>                  owned;
      std::vector<std::array<bool, dim>> free;
      std::vector<NodalComplementarity>  law;

      /// S = (dC/df) P / A_j, the weights of the bulk rows of node @p j in
      /// its new rows (identity in a row fixed by a Dirichlet condition).
      Matrix3
      row_weights(const unsigned int j, const double area) const;
    };

    /// The tractions f_j = -R_j / A_j (from the compressed residual of
    /// @p targets), the complementarity and free DoFs of every node that
    /// carries contact, the summary.
    void
    condensed_states(ContactPair                             &pair,
                     const dealii::AffineConstraints<double> &constraints,
                     const AssemblyTargets                   &targets,
                     CondensedNodes                          &nodes) const;


    /// pair.constrained_rows: the nodes of @p nodes that are active, in
    /// the frame (n, t...) of their normal; the normal row is a constraint,
    /// and so are the tangential ones where the node sticks. Nodes with a
    /// fixed component or hanging on others are left out.
    static void
    record_constrained_rows(ContactPair &pair, const CondensedNodes &nodes);


    /// Residual, right-hand side and internal force of the slave rows of
    /// node @p j and of the master rows it couples to.
    void
    add_condensed_vectors(const ContactPair                       &pair,
                          const unsigned int                       j,
                          const CondensedNodes                    &nodes,
                          const dealii::AffineConstraints<double> &constraints,
                          const AssemblyTargets &targets) const;


    /// Weighted sums of tangent rows per target row.
    class RowSums;


    /// The bulk tangent rows of node @p j: S K_j in its own rows, M_jl /
    /// A_j K_j into @p master_rows (added to the master rows once all slave
    /// nodes are done: a master row takes the rows of many of them).
    void
    combine_rows(const ContactPair                           &pair,
                 const unsigned int                           j,
                 const CondensedNodes                        &nodes,
                 const dealii::AffineConstraints<double>     &constraints,
                 dealii::TrilinosWrappers::BlockSparseMatrix &tangent,
                 RowSums &master_rows) const;


    /// The tangent terms of node @p j through its aggregates (@p g holds
    /// their derivatives through dD and dM, all of them or this rank's
    /// share: the terms are linear in them); with @p direct also those
    /// through the positions and the normal (add_direct_gradients(): once,
    /// on the rank that owns j).
    void
    add_aggregate_terms(const ContactPair                              &pair,
                        const unsigned int                              j,
                        const CondensedNodes                           &nodes,
                        std::map<unsigned int, std::array<double, 10>> &g,
                        const bool                                      direct,
                        const dealii::AffineConstraints<double> &constraints,
                        const AssemblyTargets                   &targets) const;


    /// A row of the tangent, read before any change.
    struct MatrixRow
    {
      /// Per block column b: block-local columns and values.
      std::vector<std::vector<dealii::types::global_dof_index>> columns;
      std::vector<std::vector<double>>                          values;
    };

    /// Adds @p weight times @p row to the row of @p dof, through
    /// @p constraints (a Dirichlet row takes nothing, a hanging row goes
    /// to its parents).
    static void
    add_row(const MatrixRow                             &row,
            const double                                 weight,
            const dealii::types::global_dof_index        dof,
            const dealii::AffineConstraints<double>     &constraints,
            dealii::TrilinosWrappers::BlockSparseMatrix &tangent);


    /// Semi-smooth Newton: adds the aggregate derivatives of every hanging
    /// slave node (this rank's share of them), times its weight, to its
    /// parents' (fold_hanging_nodes()), and those through its positions to
    /// the parents in @p owned.
    static void
    fold_hanging_gradients(
      const ContactPair                                           &pair,
      const std::vector<bool>                                     &owned,
      std::vector<std::map<unsigned int, std::array<double, 10>>> &gradients);



    ContactProblem       &problem;
    const Discretisation &discretisation;
  };
} // namespace DuctileContact
