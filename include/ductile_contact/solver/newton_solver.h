#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/solver/coupling_parameters.h>
#include <ductile_contact/solver/linear_solver.h>
#include <ductile_contact/solver/phase_field_bound.h>
#include <ductile_contact/solver/solver_parameters.h>
#include <ductile_contact/solver/system_assembler.h>

#include <deque>
#include <string>
#include <vector>

namespace DuctileContact
{
  class ContactProblem;

  /// Outcome of one Newton solve (one load step).
  struct NewtonReport
  {
    bool         converged         = false;
    unsigned int iterations        = 0;
    unsigned int linear_iterations = 0;
    /// Alternations of the staggered scheme (1 for monolithic; 0 for a
    /// monolithic-staggered step that Newton solved without alternating).
    unsigned int staggered_iterations = 1;
    /// Contact multiplier updates (Newton solves - 1) of the step.
    unsigned int augmentations = 0;
    /// Merit of the iterations whose Dirichlet data were reached (since the
    /// irreversibility bound was engaged, if it was).
    std::vector<double> residual_norms;
    /// Observed order log(r_k+1/r_k)/log(r_k/r_k-1) of the last three
    /// residuals (2 = quadratic); NaN if fewer than three are meaningful.
    double convergence_rate = std::numeric_limits<double>::quiet_NaN();
    /// Relative tangent error of the last Newton update of the step that
    /// was checked (Newton/Check tangent): the one nearest the solution.
    double       tangent_error = std::numeric_limits<double>::quiet_NaN();
    std::string  failure;
    AssemblyInfo info;
  };

  /**
   * Newton's method for R(u, alpha, s) = 0 at one load step, with the
   * Dirichlet data imposed through the update (so a shortened step still
   * reaches them) and a backtracking line search on the merit
   *
   *   m = sqrt(||R_u||^2 + sum_{b = alpha, s} (||R_b|| S_u / S_b)^2),
   *
   * S_b the residual scales of AssemblyInfo (m = ||R_u|| without alpha and
   * s). A trial state that inverts an element (J <= 0) is always shortened.
   *
   * Converged when the Dirichlet values are reached and ||R_u|| <= rtol
   * ||f_int,u|| + atol * force_scale (f_int holds the reactions, so the test
   * is relative to the load carried) and ||R_b|| <= rtol S_b for alpha and
   * s (S_b: the local terms at alpha = 1 or s = 1).
   *
   * With Coupling/Irreversibility = bound, the phase-field DoFs are kept at
   * or above their values of the last accepted step by an active set
   * (PhaseFieldBound): its rows carry the bound, and R_s is replaced by
   * the complementarity residual min(R_s,i, K_ii (s_i - s_n,i)) in the
   * norms, the merit and the test above.
   *
   * solve_step() applies the coupling strategy: monolithic, staggered, or
   * monolithic with a staggered retry of a failed step (CouplingParameters).
   * With contact it first searches for candidate pairs (rebuilding the
   * sparsity pattern when they change), and repeats the solve with updated
   * contact multipliers until the penetration tolerance is met
   * (ContactProblem::augment()).
   */
  class NewtonSolver
  {
  public:
    NewtonSolver(const NewtonParameters              &parameters,
                 const CouplingParameters            &coupling,
                 const Discretisation                &discretisation,
                 const SystemAssembler               &assembler,
                 LinearSolver                        &linear_solver,
                 const std::deque<BoundaryCondition> &boundary_conditions,
                 const double                         force_scale,
                 dealii::ConditionalOStream          &verbose_out,
                 dealii::TimerOutput                 &timer,
                 ContactProblem                      *contact = nullptr);

    /// Sparsity pattern and vectors; call after every DoF distribution.
    void
    setup();

    /**
     * Solves the load step @p step starting from @p u (owned entries); on
     * success @p u is the solution and @p internal_force holds f_int there.
     * On failure @p u is unspecified: the caller restores its copy.
     */
    NewtonReport
    solve_step(const StepData                             &step,
               dealii::TrilinosWrappers::MPI::BlockVector &u,
               dealii::TrilinosWrappers::MPI::BlockVector &internal_force);

    /// Newton on the blocks not marked in @p frozen (the others keep their
    /// values).
    NewtonReport
    solve(const StepData                             &step,
          dealii::TrilinosWrappers::MPI::BlockVector &u,
          dealii::TrilinosWrappers::MPI::BlockVector &internal_force,
          const std::array<bool, Block::n_blocks>    &frozen);

  private:
    /// solve_step() without the contact augmentation loop.
    NewtonReport
    solve_coupled(const StepData                             &step,
                  dealii::TrilinosWrappers::MPI::BlockVector &u,
                  dealii::TrilinosWrappers::MPI::BlockVector &internal_force);

    /// Bulk and contact terms at u_ghosted into @p targets (the contact
    /// under the timer "contact: integration, tangent" or ", residual").
    AssemblyInfo
    assemble(const StepData                          &step,
             const dealii::AffineConstraints<double> &constraints,
             const AssemblyTargets                   &targets);

    /// Newton/Check tangent: |K delta - (R(u + e delta) - R(u - e delta)) /
    /// 2e| / |K delta| on the free DoFs, e delta of 1e-6 the size of u; the
    /// tangent and delta of the current iteration, @p residual overwritten;
    /// the rows of the irreversibility bound's active set (if @p bound)
    /// are left out.
    double
    tangent_error(const StepData                                   &step,
                  const dealii::TrilinosWrappers::MPI::BlockVector &u,
                  const dealii::AffineConstraints<double>          &constraints,
                  const PhaseFieldBound                            *bound);

    const NewtonParameters              &parameters;
    const CouplingParameters            &coupling;
    const Discretisation                &discretisation;
    const SystemAssembler               &assembler;
    LinearSolver                        &linear_solver;
    const std::deque<BoundaryCondition> &boundary_conditions;
    const double                         force_scale;
    dealii::ConditionalOStream          &verbose_out;
    dealii::TimerOutput                 &timer;
    ContactProblem                      *contact;

    dealii::TrilinosWrappers::BlockSparseMatrix tangent;
    dealii::TrilinosWrappers::MPI::BlockVector  newton_rhs, residual, delta,
      u_ghosted;
  };
} // namespace DuctileContact
