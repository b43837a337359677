#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/discretisation/discretisation.h>

#include <string>

namespace DuctileContact
{
  /**
   * Irreversibility of the crack and its upper bound as a box on the
   * phase-field DoFs, s_n,i <= s_i <= 1 (doc/model.md section 4.2), by a
   * primal-dual active set, i.e. semismooth Newton (Hintermueller, Ito,
   * Kunisch 2002; for phase-field fracture as in Heister, Wheeler, Wick
   * 2015). The KKT conditions of the lower bound,
   *
   *   R_s,i = lambda_i >= 0,  s_i - s_n,i >= 0,  lambda_i (s_i - s_n,i) = 0,
   *
   * and of the upper one (R_s,i <= 0 where s_i = 1) hold exactly where the
   * complementarity residual
   *
   *   C_i = max(min(R_s,i, K_ii (s_i - s_n,i)), K_ii (s_i - 1))
   *
   * vanishes (K_ii > 0 the diagonal of the s-s tangent, a scale that makes
   * both arguments residuals). Newton on C = 0 is the active set method:
   * on A = { i : R_s,i + K_ii (s_n,i - s_i) > 0 }, the DoFs where a Newton
   * step on row i alone would end below s_n,i, the row becomes K_ii
   * delta_i = K_ii (s_n,i - s_i) (the bound reached after a full step);
   * elsewhere it is the Newton row of R; likewise on the upper set
   * { i : R_s,i + K_ii (1 - s_i) < 0 } the row holds s_i at 1. The upper
   * bound keeps the fourth-order field, which has no maximum principle,
   * from overshooting 1 at its nodes (by up to 7 % without it). The norms and the convergence
   * test use C in place of R_s, so DoFs that sit on the bound with a zero
   * multiplier (e.g. s = 0 far from a crack, where round-off decides the
   * sign of R) count as converged on either side of A. CoupledProblem
   * engages the active set once plain Newton has converged to a state
   * whose C does not meet the tolerance (from the first iteration when the
   * last step held DoFs on the bound), and in every iteration with the
   * bound refines A on the s block alone (identify_active_set()) before
   * the coupled solve.
   *
   * With Coupling/Irreversibility = history and bound (the default) the
   * history field of psi^+ (doc/model.md's default) acts as well: it keeps the
   * driving force from falling; the bound keeps s itself from falling,
   * which the history alone does not guarantee (the gradient and
   * bi-Laplacian terms of the neighbours act on s too; before g was
   * continued by 0 beyond s = 1, the negative driver of the overshoot
   * above 1 pulled the broken band down). With `bound` alone the driver
   * comes from the current psi^+.
   *
   * Indices are block-local to the phase-field block; owned DoFs only;
   * DoFs constrained in the Newton constraints (hanging nodes, Dirichlet
   * data) are left alone.
   */
  class PhaseFieldBound
  {
  public:
    explicit PhaseFieldBound(const Discretisation &discretisation);

    /// Stores K_ii of the s-s block of a freshly assembled tangent.
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
     * primal-dual active set iteration of the Newton step's linearised s
     * equation with the other fields held: K_ss delta = -R_s on the free
     * DoFs, delta_i = s_n,i - s_i on A (one sparse LU of the s-s block,
     * Amesos @p direct_solver, per sweep), then A = { i : (R_s + K_ss
     * delta)_i + K_ii (s_n,i - s_i - delta_i) > 0 }, until A repeats or
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
      const std::string                                 &direct_solver,
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

    /// Replaces R_s by C in @p residual (the state @p u).
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
    /// Replaces the rows of A in the s-s matrix @p K_ss and in @p b by the
    /// bound reached after a full step, K_ii delta_i = K_ii (s_n,i - s_i);
    /// the one definition of a held row, for constrain() and the sweeps of
    /// identify_active_set().
    void
    hold_active_rows(dealii::TrilinosWrappers::SparseMatrix      &K_ss,
                     dealii::TrilinosWrappers::MPI::Vector       &b,
                     const dealii::TrilinosWrappers::MPI::Vector &s,
                     const dealii::TrilinosWrappers::MPI::Vector &s_n) const;

    const Discretisation &discretisation;
    /// First DoF of the phase-field block in the global numbering.
    const dealii::types::global_dof_index offset;
    /// K_ii of the s-s block on the owned s DoFs.
    dealii::TrilinosWrappers::MPI::Vector diagonal;
    /// DoFs held at s_n (lower) and at 1 (upper).
    dealii::IndexSet active, upper;
  };
} // namespace DuctileContact
