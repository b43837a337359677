#include <ductile_contact/coupled/coupled_solver.h>
#include <ductile_contact/solver/anderson_acceleration.h>

#include <algorithm>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// @p r as the report of a step (one monolithic solve).
    StepReport
    as_step_report(const NewtonReport &r)
    {
      StepReport report;
      static_cast<NewtonReport &>(report) = r;
      return report;
    }
  } // namespace



  CoupledSolver::CoupledSolver(const CouplingParameters           &coupling,
                               CoupledProblem                     &problem,
                               NewtonSolver                       &newton,
                               ConditionalOStream                 &verbose_out,
                               const std::vector<PhysicsModule *> &modules)
      : coupling(coupling)
      , problem(problem)
      , newton(newton)
      , verbose_out(verbose_out)
      , modules(modules)
  {
  }



  NewtonReport
  CoupledSolver::newton_solve(TrilinosWrappers::MPI::BlockVector      &u,
                              const std::array<bool, Block::n_blocks> &frozen)
  {
    problem.freeze(frozen);
    return newton.solve(problem, u);
  }



  StepReport
  CoupledSolver::solve_step(
    const StepData                                        &step,
    TrilinosWrappers::MPI::BlockVector                    &u,
    const std::vector<TrilinosWrappers::MPI::BlockVector> &alternatives)
  {
    problem.begin_step(step, u);
    if (!alternatives.empty())
      {
        std::vector<const TrilinosWrappers::MPI::BlockVector *> starts{&u};
        for (const auto &v : alternatives)
          starts.push_back(&v);
        problem.freeze({{false, false, false}});
        if (const std::size_t best = newton.best_start(problem, starts);
            best > 0)
          u = alternatives[best - 1];
      }
    unsigned int max_updates = 0;
    for (const PhysicsModule *m : modules)
      max_updates = std::max(max_updates, m->max_outer_updates());
    if (max_updates == 0)
      return solve_fields(u);

    StepReport total;
    for (unsigned int k = 0;; ++k)
      {
        const StepReport r = solve_fields(u);
        total.iterations += r.iterations;
        total.linear_iterations += r.linear_iterations;
        total.staggered_iterations = r.staggered_iterations;
        total.residual_norms       = r.residual_norms;
        total.convergence_rate     = r.convergence_rate;
        if (std::isfinite(r.tangent_error))
          total.tangent_error = r.tangent_error;
        total.info             = r.info;
        total.branch_conflicts = r.branch_conflicts;
        if (!r.converged)
          {
            total.failure = r.failure;
            return total;
          }
        // Every module updates (not only the first that is unsettled).
        std::string reports;
        for (PhysicsModule *m : modules)
          {
            std::string report;
            if (!m->outer_update(report))
              reports +=
                (reports.empty() ? "" : "; ") + m->name() + ": " + report;
          }
        if (reports.empty())
          {
            total.converged = true;
            return total;
          }
        if (k + 1 == max_updates)
          {
            total.failure = "not settled after " + std::to_string(k + 1) +
                            " outer updates (" + reports + ")";
            return total;
          }
        verbose_out << "      outer update " << k + 1 << ": " << reports
                    << std::endl;
      }
  }



  StepReport
  CoupledSolver::solve_fields(TrilinosWrappers::MPI::BlockVector &u)
  {
    const std::array<bool, Block::n_blocks> none{{false, false, false}};
    if (coupling.strategy == CouplingStrategy::monolithic ||
        !problem.has_phase_field())
      {
        StepReport report = as_step_report(newton_solve(u, none));
        report.info       = problem.converged_info();
        return report;
      }

    StepReport total;
    if (coupling.strategy == CouplingStrategy::monolithic_staggered)
      {
        const TrilinosWrappers::MPI::BlockVector start = u;
        const NewtonReport                       r     = newton_solve(u, none);
        if (r.converged)
          {
            StepReport report           = as_step_report(r);
            report.staggered_iterations = 0; // Newton alone solved the step
            report.info                 = problem.converged_info();
            return report;
          }
        verbose_out << "      monolithic Newton failed (" << r.failure
                    << "); redoing the step staggered" << std::endl;
        u                       = start;
        total.iterations        = r.iterations;
        total.linear_iterations = r.linear_iterations;
      }
    staggered(u, total);
    if (total.converged)
      total.info = problem.converged_info();
    return total;
  }



  void
  CoupledSolver::staggered(TrilinosWrappers::MPI::BlockVector &u,
                           StepReport                         &total)
  {
    // Alternate minimisation: (u, alpha) with s fixed, then s with (u,
    // alpha) fixed. Each sub-solve checks its fields before iterating, so
    // a sub-solve that needs no iteration shows that the state it starts
    // from meets the tolerances in every block: the coupled step is done.
    // With acceleration, the phase field that the next mechanics sub-solve
    // starts from is the Anderson combination of the last phase fields, no
    // longer the one just solved for: then only a phase-field sub-solve
    // that needs no iteration ends the step.
    AndersonAcceleration          accelerate(coupling.acceleration_depth);
    TrilinosWrappers::MPI::Vector s_iterate;
    for (unsigned int k = 1; k <= coupling.max_staggered_iterations; ++k)
      {
        total.staggered_iterations = k;
        const bool s_accelerated   = k > 2 && coupling.acceleration_depth > 0;
        s_iterate                  = u.block(Block::phase_field);
        for (const bool mechanics : {true, false})
          {
            const NewtonReport r =
              newton_solve(u,
                           mechanics
                             ? std::array<bool, 3>{{false, false, true}}
                             : std::array<bool, 3>{{true, true, false}});
            total.iterations += r.iterations;
            total.linear_iterations += r.linear_iterations;
            total.branch_conflicts += r.branch_conflicts;
            if (std::isfinite(r.tangent_error))
              total.tangent_error = r.tangent_error;
            if (!r.converged)
              {
                total.failure = (mechanics ? "mechanics sub-step: "
                                           : "phase-field sub-step: ") +
                                r.failure;
                return;
              }
            total.convergence_rate = r.convergence_rate;
            if (r.iterations == 0 && (!mechanics || (k > 1 && !s_accelerated)))
              {
                total.converged = true;
                return;
              }
          }
        accelerate.update(s_iterate, u.block(Block::phase_field));
        verbose_out << "      staggered iteration " << k << " done"
                    << std::endl;
      }
    total.failure = "no staggered convergence in " +
                    std::to_string(coupling.max_staggered_iterations) +
                    " alternations";
  }
} // namespace DuctileContact
