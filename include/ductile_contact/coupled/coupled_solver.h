#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <ductile_contact/coupled/coupled_problem.h>
#include <ductile_contact/coupled/coupling_parameters.h>
#include <ductile_contact/solver/newton_solver.h>

namespace DuctileContact
{
  /// Outcome of one load step: Newton's report summed over the solves of
  /// the step, and what the coupling strategies did.
  struct StepReport : NewtonReport
  {
    /// Alternations of the staggered scheme (1 for monolithic; 0 for a
    /// monolithic-staggered step that Newton solved without alternating).
    unsigned int staggered_iterations = 1;
    /// What the assembly found at the converged state.
    AssemblyInfo info;
  };

  /**
   * One load step of the CoupledProblem by the strategies around Newton:
   *
   *  - the coupling of the fields (CouplingParameters): monolithic (Newton
   *    on all blocks), staggered (alternate minimisation, Newton on (u,
   *    alpha) with s frozen, then on s with (u, alpha) frozen, optionally
   *    with Anderson acceleration of s), or monolithic with a staggered
   *    retry of a failed step;
   *  - the modules' outer loop (PhysicsModule::outer_update(), e.g. the
   *    augmented Lagrangian of contact): the coupled solve is repeated
   *    until every module's equations hold as they are (for contact: every
   *    pair meets its penetration tolerance).
   */
  class CoupledSolver
  {
  public:
    CoupledSolver(const CouplingParameters           &coupling,
                  CoupledProblem                     &problem,
                  NewtonSolver                       &newton,
                  dealii::ConditionalOStream         &verbose_out,
                  const std::vector<PhysicsModule *> &modules = {});

    /// Solves the load step @p step from @p u (owned entries), or from the
    /// one of @p alternatives whose residual is smaller than u's and
    /// theirs (NewtonSolver::best_start(); they must reach the same
    /// prescribed values as u); on success @p u is the solution. On failure
    /// @p u is unspecified: the caller restores its copy.
    StepReport
    solve_step(const StepData                             &step,
               dealii::TrilinosWrappers::MPI::BlockVector &u,
               const std::vector<dealii::TrilinosWrappers::MPI::BlockVector>
                 &alternatives = {});

  private:
    /// The coupling strategy, without the modules' outer loop.
    StepReport
    solve_fields(dealii::TrilinosWrappers::MPI::BlockVector &u);

    /// Alternate minimisation, adding to @p total.
    void
    staggered(dealii::TrilinosWrappers::MPI::BlockVector &u, StepReport &total);

    /// Newton with the blocks marked in @p frozen kept.
    NewtonReport
    newton_solve(dealii::TrilinosWrappers::MPI::BlockVector &u,
                 const std::array<bool, Block::n_blocks>    &frozen);

    const CouplingParameters          &coupling;
    CoupledProblem                    &problem;
    NewtonSolver                      &newton;
    dealii::ConditionalOStream        &verbose_out;
    const std::vector<PhysicsModule *> modules;
  };
} // namespace DuctileContact
