#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/constrained_rows.h>
#include <ductile_contact/solver/direct_solve.h>
#include <ductile_contact/solver/monolithic_copy.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_MultiVector.h>
#include <memory>
#include <vector>

namespace DuctileContact
{
  /**
   * How accurate a solve needs to be for its caller, besides `Relative
   * tolerance`: with weights w_b per block b of the coupled vector, an
   * iterative solve may also stop once its residual r = b - K x meets
   *
   *   sqrt(sum_b (w_b |r_b|)^2) <= enough.
   *
   * GMRES on the direct solver's factors then measures its residual in
   * that weighted norm (the relative tolerance too); the AMG solvers,
   * which see the plain norm, stop at |r| <= enough / max_b w_b. Empty
   * weights: the relative tolerance alone. Every block with DoFs needs a
   * positive weight.
   */
  struct SolveAccuracy
  {
    std::vector<double> block_weights;
    double              enough = 0.;

    /// Stopping tolerance of a solver that sees the plain residual norm:
    /// @p relative_tolerance times @p rhs_norm, or the weighted bound if
    /// looser.
    double
    plain_tolerance(double rhs_norm, double relative_tolerance) const;
  };

  /**
   * What the strategies share: the `Linear solver` section, the DoFs, the
   * near-null spaces of the AMGs (remade by LinearSolver::setup()) and the
   * direct solver with its kept analysis and factors.
   */
  struct SolveContext
  {
    const LinearSolverParameters &parameters;
    const Discretisation         &discretisation;
    /// Rigid-body modes on the locally owned displacement DoFs.
    std::unique_ptr<Epetra_MultiVector> rigid_body_modes;
    /// The constant and the coordinates on the owned s DoFs (null without).
    std::unique_ptr<Epetra_MultiVector> phase_field_modes;
    DirectSolve                         direct;
    /// The constraint rows of the matrix being solved (null: none).
    const ConstrainedNodes *constrained = nullptr;
  };

  /**
   * One way of solving the Newton system K x = b on the [u | alpha | s]
   * blocks; returns the iterations (1 for exact factors). @p same_matrix:
   * K is the matrix of the last solve, values unchanged (a chord step).
   */
  class SolveStrategy
  {
  public:
    explicit SolveStrategy(SolveContext &context)
        : context(context)
    {
    }

    virtual ~SolveStrategy() = default;

    virtual unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy,
          bool                                               same_matrix) = 0;

    /// The DoFs changed: forget what depends on them.
    virtual void
    reset()
    {
    }

  protected:
    SolveContext &context;
  };

  /// The displacement block alone (alpha and s empty) by the direct solver.
  class DisplacementDirectSolve : public SolveStrategy
  {
  public:
    using SolveStrategy::SolveStrategy;

    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy,
          bool same_matrix) override;
  };

  /**
   * The displacement block alone by CG or right-preconditioned GMRES with
   * ML smoothed-aggregation AMG, the rigid-body modes as its near-null
   * space.
   */
  class DisplacementKrylovSolve : public SolveStrategy
  {
  public:
    using SolveStrategy::SolveStrategy;

    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy,
          bool same_matrix) override;
  };

  /**
   * The coupled system by the direct solver: the nine blocks copied into
   * one matrix over the global DoF indices (MonolithicCopy, pattern kept
   * while the tangent keeps its own), the row weights of the accuracy on
   * the flat rows.
   */
  class CoupledDirectSolve : public SolveStrategy
  {
  public:
    explicit CoupledDirectSolve(SolveContext &context);

    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy,
          bool same_matrix) override;

    void
    reset() override;

  private:
    MonolithicCopy copy;
  };

  /**
   * The coupled system, which is not symmetric in general, by
   * right-preconditioned GMRES with BlockTriangularPreconditioner: the
   * diagonal blocks approximately inverted by the displacement AMG (u), a
   * scalar AMG (alpha), and a scalar AMG with the constant and coordinates
   * as near-null space or exact factors (s, `Phase-field preconditioner`).
   * The preconditioner is rebuilt on every solve.
   */
  class CoupledKrylovSolve : public SolveStrategy
  {
  public:
    using SolveStrategy::SolveStrategy;

    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy,
          bool same_matrix) override;

    void
    reset() override;

  private:
    /// Exact factors of the s block (`Phase-field preconditioner = direct`),
    /// whose analysis is kept while the pattern is.
    std::unique_ptr<DirectSolve> phase_field_factors;
  };
} // namespace DuctileContact
