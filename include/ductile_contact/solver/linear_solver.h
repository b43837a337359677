#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/solve_strategy.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <ostream>
#include <string>
#include <utility>

namespace DuctileContact
{
  /**
   * Solves the Newton system K delta = b by the strategy that the `Linear
   * solver` section and the blocks ask for:
   *
   * | blocks with DoFs | direct                   | cg-amg, gmres-amg       |
   * |------------------|--------------------------|-------------------------|
   * | u only           | DisplacementDirectSolve  | DisplacementKrylovSolve |
   * | u, alpha and/or s| CoupledDirectSolve       | CoupledKrylovSolve      |
   *
   * (cg-amg on the coupled system is GMRES: its tangent is not symmetric).
   * Type = automatic is direct up to Direct solver limit unknowns and
   * gmres-amg above, decided at every solve.
   * The strategies share one SolveContext: the near-null spaces of the AMGs
   * and one DirectSolve, whose analysis and factors carry over from solve
   * to solve.
   */
  class LinearSolver
  {
  public:
    LinearSolver(const LinearSolverParameters &parameters,
                 const Discretisation         &discretisation);

    /**
     * Recomputes the near-null spaces and forgets the monolithic pattern
     * and the direct solver's analysis; call after every DoF distribution.
     */
    void
    setup();

    /// Returns the number of iterations (1 for the direct solver).
    /// @p same_matrix: K is the matrix of the last solve, values unchanged
    /// (a chord step): its copy for the direct solver and the check of the
    /// factors' pattern are skipped. @p constrained: the rows of K that
    /// hold constraints (null: none), for the iterative solvers.
    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy = {},
          bool                    same_matrix                         = false,
          const ConstrainedNodes *constrained = nullptr);

    /// The type that solves the current system: Type, or what automatic
    /// picks for the current number of unknowns.
    LinearSolverType
    type() const;

    /// The type with the reason for an automatic choice, for the log.
    std::string
    describe() const;

    /// One line on the direct solver's work so far (analyses,
    /// factorisations, solves and their times), if it kept any.
    void
    print_summary(std::ostream &out) const;

    /// Factorisations in double precision because single-precision factors
    /// of the same matrix did not bring GMRES to the tolerance.
    unsigned int
    fallback_factorisations() const;

    /// GMRES runs on old factors that missed the tolerance or gave up
    /// early, and the triangular solves they spent.
    std::pair<unsigned int, unsigned int>
    failed_reuse_counts() const;

  private:
    /// The strategy for the current parameters and blocks.
    SolveStrategy &
    strategy();

    SolveContext            context;
    DisplacementDirectSolve displacement_direct;
    DisplacementKrylovSolve displacement_krylov;
    CoupledDirectSolve      coupled_direct;
    CoupledKrylovSolve      coupled_krylov;
  };
} // namespace DuctileContact
