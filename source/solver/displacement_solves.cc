// The strategies for the displacement block alone: the direct solver, or
// CG / GMRES with the displacement AMG.
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <ductile_contact/solver/displacement_preconditioner.h>
#include <ductile_contact/solver/solve_strategy.h>

#include <algorithm>

namespace DuctileContact
{
  using namespace dealii;



  double
  SolveAccuracy::plain_tolerance(const double rhs_norm,
                                 const double relative_tolerance) const
  {
    double tolerance = relative_tolerance * rhs_norm;
    if (!block_weights.empty())
      tolerance = std::max(tolerance,
                           enough / *std::max_element(block_weights.begin(),
                                                      block_weights.end()));
    return tolerance;
  }



  unsigned int
  DisplacementDirectSolve::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                                 TrilinosWrappers::MPI::BlockVector        &x,
                                 const TrilinosWrappers::MPI::BlockVector  &b,
                                 const SolveAccuracy &accuracy,
                                 const bool           same_matrix)
  {
    // One block, one weight: the weighted bound is a plain one.
    return context.direct.solve(
      K.block(Block::displacement, Block::displacement),
      x.block(Block::displacement),
      b.block(Block::displacement),
      nullptr,
      accuracy.block_weights.empty()
        ? 0.
        : accuracy.enough / accuracy.block_weights[Block::displacement],
      same_matrix);
  }



  unsigned int
  DisplacementKrylovSolve::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                                 TrilinosWrappers::MPI::BlockVector        &x,
                                 const TrilinosWrappers::MPI::BlockVector  &b,
                                 const SolveAccuracy &accuracy,
                                 const bool /*same_matrix*/)
  {
    const LinearSolverParameters &parameters = context.parameters;
    const auto &A  = K.block(Block::displacement, Block::displacement);
    auto       &xu = x.block(Block::displacement);
    const auto &bu = b.block(Block::displacement);

    DisplacementPreconditioner amg;
    amg.initialize(A,
                   context.constrained,
                   parameters,
                   context.discretisation.degree,
                   context.rigid_body_modes.get());

    SolverControl control(
      parameters.max_iterations,
      accuracy.plain_tolerance(bu.l2_norm(), parameters.relative_tolerance));
    if (parameters.type == LinearSolverType::cg_amg)
      {
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(A, xu, bu, amg);
      }
    else
      {
        // Right preconditioning, so that the stopping test is on the true
        // residual ||b - A x|| (left preconditioning tests ||P^-1 (b - A x)||,
        // which the AMG scales by ~1/E: the solve stopped far too early and
        // Newton converged linearly).
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
            parameters.gmres_restart, true));
        gmres.solve(A, xu, bu, amg);
      }
    return control.last_step();
  }
} // namespace DuctileContact
