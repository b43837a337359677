#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/direct_solve.h>

#include <limits>
#include <string>

namespace DuctileContact
{
  /**
   * A box x_n,i <= x_i <= b on the DoFs of one block of the coupled system
   * by a primal-dual active set, i.e. semismooth Newton (Hintermueller, Ito,
   * Kunisch 2002; for phase-field fracture as in Heister, Wheeler, Wick
   * 2015): x_n the last accepted state, b an upper bound (or none). Used
   * for the phase field, s_n <= s <= 1 (doc/model.md section 4.2):
   * irreversibility of the crack and its upper bound (the fourth-order
   * field has no maximum principle and overshoots 1 at its nodes by up to
   * 7 % without it). With the Bernstein basis (BernsteinElement) the field
   * is a convex combination of its DoFs, so the box on the DoFs holds at
   * every point.
   *
   * The KKT conditions of the lower bound,
   *
   *   R_i = lambda_i >= 0,  x_i - x_n,i >= 0,  lambda_i (x_i - x_n,i) = 0,
   *
   * and of the upper one (R_i <= 0 where x_i = b) hold exactly where the
   * complementarity residual
   *
   *   C_i = max(min(R_i, K_ii (x_i - x_n,i)), K_ii (x_i - b))
   *
   * vanishes (K_ii > 0 the diagonal of the block's tangent, a scale that
   * makes both arguments residuals). Newton on C = 0 is the active set
   * method: on A = { i : R_i + K_ii (x_n,i - x_i) > 0 }, the DoFs where a
   * Newton step on row i alone would end below x_n,i, the row becomes
   * K_ii delta_i = K_ii (x_n,i - x_i) (the bound reached after a full
   * step); elsewhere it is the Newton row of R; likewise on the upper set
   * { i : R_i + K_ii (b - x_i) < 0 } the row holds x_i at b. The norms and
   * the convergence test use C in place of R, so DoFs that sit on the
   * bound with a zero multiplier (e.g. s = 0 far from a crack, where
   * round-off decides the sign of R) count as converged on either side of
   * A. CoupledProblem engages the bound once plain Newton has converged to
   * a state whose C does not meet the block's tolerance (from the first
   * iteration when the last step held DoFs on it), and in every iteration
   * with the bound refines A on the block alone (identify_active_set())
   * before the coupled solve.
   *
   * With Coupling/Irreversibility = history and bound (the default) the
   * history field of psi^+ (doc/model.md's default) acts as well: it keeps
   * the driving force from falling; the bound keeps s itself from falling,
   * which the history alone does not guarantee (the gradient and
   * bi-Laplacian terms of the neighbours act on s too).
   *
   * Indices are block-local; owned DoFs only; DoFs constrained in the
   * Newton constraints (hanging nodes, Dirichlet data) are left alone.
   */
  class FieldBound
  {
  public:
    /// The bound on @p block (Block::phase_field; Block::hardening would
    /// do as well) with the upper bound @p upper (infinity: none).
    FieldBound(const Discretisation &discretisation,
               const unsigned int    block,
               const double upper = std::numeric_limits<double>::infinity());

    /// The block this bound acts on.
    unsigned int
    block() const
    {
      return block_index;
    }

    /// The field's name in messages ("s", "alpha").
    std::string
    field_name() const;

    /// Stores K_ii of the block's diagonal block of a freshly assembled
    /// tangent.
    void
    record_diagonal(const dealii::TrilinosWrappers::BlockSparseMatrix &K);

    /// A at the state @p u with residual @p residual (R, before
    /// to_complementarity()); returns |A| summed over ranks.
    dealii::types::global_dof_index
    update_active_set(
      const dealii::TrilinosWrappers::MPI::BlockVector &u,
      const dealii::TrilinosWrappers::MPI::BlockVector &old,
      const dealii::TrilinosWrappers::MPI::BlockVector &residual,
      const dealii::AffineConstraints<double>          &constraints);

    /**
     * Refines A, starting from the A of update_active_set(), by the
     * primal-dual active set iteration of the Newton step's linearised
     * equation of the block with the other fields held: K_xx delta = -R_x
     * on the free DoFs, delta_i = x_n,i - x_i on A (one sparse LU of the
     * block per sweep by @p direct_solver, whose analysis of the block's
     * pattern carries over between calls), then A = { i : (R_x + K_xx
     * delta)_i + K_ii (x_n,i - x_i - delta_i) > 0 }, until A repeats or
     * after @p max_sweeps sweeps. Without it the coupled Newton iteration
     * learns A one coupled solve at a time: the C0IP operator has no
     * maximum principle, so holding a few DoFs lifts their neighbours above
     * s_n, and the first A (all DoFs below s_n) is much larger than the
     * final one (benchmarks/phase_field/energy_balance). @p K and
     * @p newton_rhs (= -R, Newton constraints applied) are the fresh
     * tangent and right-hand side, before constrain(). Returns the sweeps
     * done (0 if the sparse LU failed: A stays that of update_active_set());
     * active_size() is |A| after them.
     */
    unsigned int
    identify_active_set(
      const dealii::TrilinosWrappers::BlockSparseMatrix &K,
      const dealii::TrilinosWrappers::MPI::BlockVector  &newton_rhs,
      const dealii::TrilinosWrappers::MPI::BlockVector  &u,
      const dealii::TrilinosWrappers::MPI::BlockVector  &old,
      const dealii::AffineConstraints<double>           &constraints,
      DirectSolve                                       &direct_solver,
      const unsigned int                                 max_sweeps);

    /// |A| summed over ranks.
    dealii::types::global_dof_index
    active_size() const;

    /// Replaces the rows of A in @p K and @p newton_rhs by the bound.
    void
    constrain(dealii::TrilinosWrappers::BlockSparseMatrix      &K,
              dealii::TrilinosWrappers::MPI::BlockVector       &newton_rhs,
              const dealii::TrilinosWrappers::MPI::BlockVector &u,
              const dealii::TrilinosWrappers::MPI::BlockVector &old) const;

    /**
     * For a chord step (Newton/Tangent update), which keeps the last
     * tangent with this bound's rows: the active set of
     * update_active_set() at the state @p u with residual @p residual (R,
     * the diagonal recorded from the kept tangent); if it is the one the
     * tangent holds, on every rank, writes the bound's rows into @p rhs
     * and returns true. Otherwise the new set is kept and false tells the
     * caller that the tangent must be assembled again.
     */
    bool
    keep_active_set(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                    const dealii::TrilinosWrappers::MPI::BlockVector &old,
                    const dealii::TrilinosWrappers::MPI::BlockVector &residual,
                    const dealii::AffineConstraints<double>    &constraints,
                    dealii::TrilinosWrappers::MPI::BlockVector &rhs);

    /// Replaces R_x by C in @p residual (the state @p u).
    void
    to_complementarity(
      dealii::TrilinosWrappers::MPI::BlockVector       &residual,
      const dealii::TrilinosWrappers::MPI::BlockVector &u,
      const dealii::TrilinosWrappers::MPI::BlockVector &old,
      const dealii::AffineConstraints<double>          &constraints) const;

    /// Zeroes the rows of A in @p v (the tangent check compares R, whose
    /// rows of A the Newton system does not hold).
    void
    remove_active_rows(dealii::TrilinosWrappers::MPI::BlockVector &v) const;

  private:
    /// The lower bound at a DoF whose accepted value is @p x_n: x_n, but at
    /// most the upper bound (an accepted value above it, from a run without
    /// the bound, must not empty the box).
    double
    lower(const double x_n) const
    {
      return std::min(x_n, upper_bound);
    }

    /// Replaces the rows of A in the block's matrix @p K_xx and in @p b by
    /// the bound reached after a full step, K_ii delta_i = K_ii (x_n,i -
    /// x_i); the one definition of a held row, for constrain() and the
    /// sweeps of identify_active_set() (its right-hand side:
    /// hold_active_rhs(), also for the chord steps of keep_active_set()).
    void
    hold_active_rows(dealii::TrilinosWrappers::SparseMatrix      &K_xx,
                     dealii::TrilinosWrappers::MPI::Vector       &b,
                     const dealii::TrilinosWrappers::MPI::Vector &x,
                     const dealii::TrilinosWrappers::MPI::Vector &x_n) const;

    /// The right-hand side of the held rows of hold_active_rows().
    void
    hold_active_rhs(dealii::TrilinosWrappers::MPI::Vector       &b,
                    const dealii::TrilinosWrappers::MPI::Vector &x,
                    const dealii::TrilinosWrappers::MPI::Vector &x_n) const;

    const Discretisation &discretisation;
    const unsigned int    block_index;
    const double          upper_bound;
    /// Whether the upper bound is finite.
    const bool has_upper;
    /// First DoF of the block in the global numbering.
    const dealii::types::global_dof_index offset;
    /// K_ii of the block's diagonal block on its owned DoFs.
    dealii::TrilinosWrappers::MPI::Vector diagonal;
    /// DoFs held at x_n (lower) and at the upper bound.
    dealii::IndexSet active, upper;
  };
} // namespace DuctileContact
