// The strategies for the coupled [u | alpha | s] system: the direct solver
// on its monolithic copy, or GMRES with the block preconditioner.
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <ductile_contact/solver/amg.h>
#include <ductile_contact/solver/block_preconditioner.h>
#include <ductile_contact/solver/displacement_preconditioner.h>
#include <ductile_contact/solver/solve_strategy.h>

namespace DuctileContact
{
  using namespace dealii;



  CoupledDirectSolve::CoupledDirectSolve(SolveContext &context)
      : SolveStrategy(context)
      , copy(context.discretisation)
  {
  }



  void
  CoupledDirectSolve::reset()
  {
    copy.reset();
  }



  unsigned int
  CoupledDirectSolve::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                            TrilinosWrappers::MPI::BlockVector        &x,
                            const TrilinosWrappers::MPI::BlockVector  &b,
                            const SolveAccuracy                       &accuracy,
                            const bool same_matrix)
  {
    const bool same_pattern = copy.update(K, same_matrix);
    copy.set_right_hand_side(b);
    const bool weighted = !accuracy.block_weights.empty();
    if (weighted)
      copy.set_weights(accuracy.block_weights);
    const unsigned int n_solves =
      context.direct.solve(copy.matrix,
                           copy.x,
                           copy.b,
                           weighted ? &copy.weights : nullptr,
                           accuracy.enough,
                           same_matrix && same_pattern);
    copy.get_solution(x);
    return n_solves;
  }



  void
  CoupledKrylovSolve::reset()
  {
    phase_field_factors.reset();
  }



  unsigned int
  CoupledKrylovSolve::solve(const TrilinosWrappers::BlockSparseMatrix &K,
                            TrilinosWrappers::MPI::BlockVector        &x,
                            const TrilinosWrappers::MPI::BlockVector  &b,
                            const SolveAccuracy                       &accuracy,
                            const bool /*same_matrix*/)
  {
    const LinearSolverParameters &parameters     = context.parameters;
    const Discretisation         &discretisation = context.discretisation;
    using Inverse = BlockTriangularPreconditioner::BlockInverse;
    std::vector<Inverse> inverses(Block::n_blocks);

    // u: the preconditioner of the displacement-only solver.
    DisplacementPreconditioner amg_u;
    amg_u.initialize(K.block(Block::displacement, Block::displacement),
                     context.constrained,
                     parameters,
                     discretisation.degree,
                     context.rigid_body_modes.get());
    inverses[Block::displacement] = [&](auto &y, const auto &r) {
      amg_u.vmult(y, r);
    };

    // alpha, s: scalar elliptic blocks (mass + Laplacian, + C0IP for s).
    TrilinosWrappers::PreconditionAMG amg_alpha;
    if (discretisation.dofs_per_block[Block::hardening] > 0)
      {
        // The constant is its near-null space, ML's default.
        initialize_amg(K.block(Block::hardening, Block::hardening),
                       amg_alpha,
                       parameters,
                       discretisation.degree,
                       parameters.aggregation_threshold);
        inverses[Block::hardening] = [&](auto &y, const auto &r) {
          amg_alpha.vmult(y, r);
        };
      }

    TrilinosWrappers::PreconditionAMG amg_s;
    if (discretisation.dofs_per_block[Block::phase_field] > 0)
      {
        const auto &A = K.block(Block::phase_field, Block::phase_field);
        if (parameters.phase_field_preconditioner ==
            PhaseFieldPreconditioner::direct)
          {
            const DirectSolveSettings settings =
              DirectSolveSettings::exact_block_factors(parameters);
            if (!phase_field_factors)
              phase_field_factors = std::make_unique<DirectSolve>(
                discretisation.dof_handler.get_communicator(), settings);
            phase_field_factors->configure(settings);
            phase_field_factors->factorize(A);
            inverses[Block::phase_field] = [&](auto &y, const auto &r) {
              phase_field_factors->apply(y, r);
            };
          }
        else
          {
            // 0.02 beats 1e-4 for the C0IP block (shared docs,
            // performance.md). Near-null space: the constant and the
            // coordinates, which the fourth-order part does not see. With
            // the constant alone the aggregates interpolate the linear
            // functions badly: in the plane-strain paper scene the
            // iterations grew 12-fold from the mesh refined once to three
            // times, against 3-fold (benchmarks/iterative_solver).
            initialize_amg(A,
                           amg_s,
                           parameters,
                           discretisation.degree,
                           0.02,
                           context.phase_field_modes.get());
            inverses[Block::phase_field] = [&](auto &y, const auto &r) {
              amg_s.vmult(y, r);
            };
          }
      }

    const BlockTriangularPreconditioner preconditioner(K, inverses);

    // Right preconditioning: the stopping test is on the true residual
    // ||b - K x||, as the relative tolerance promises.
    SolverControl control(
      parameters.max_iterations,
      accuracy.plain_tolerance(b.l2_norm(), parameters.relative_tolerance));
    SolverGMRES<TrilinosWrappers::MPI::BlockVector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::BlockVector>::AdditionalData(
        parameters.gmres_restart, true));
    gmres.solve(K, x, b, preconditioner);
    return control.last_step();
  }
} // namespace DuctileContact
