#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/discretisation/constraints.h>
#include <ductile_contact/solver/newton_solver.h>

#include <cmath>
#include <iomanip>
#include <limits>

namespace DuctileContact
{
  using namespace dealii;

  NewtonSolver::NewtonSolver(
    const NewtonParameters              &parameters,
    const Discretisation                &discretisation,
    const SystemAssembler               &assembler,
    LinearSolver                        &linear_solver,
    const std::deque<BoundaryCondition> &boundary_conditions,
    const double                         force_scale,
    ConditionalOStream                  &verbose_out,
    TimerOutput                         &timer)
      : parameters(parameters)
      , discretisation(discretisation)
      , assembler(assembler)
      , linear_solver(linear_solver)
      , boundary_conditions(boundary_conditions)
      , force_scale(force_scale)
      , verbose_out(verbose_out)
      , timer(timer)
  {
  }



  void
  NewtonSolver::setup()
  {
    TimerOutput::Scope scope(timer, "setup: sparsity");
    const MPI_Comm     comm = discretisation.dof_handler.get_communicator();

    // Same constrained DoF set as every Newton iteration (values differ).
    AffineConstraints<double> constraints;
    make_newton_constraints(
      discretisation, boundary_conditions, 0., nullptr, constraints);

    // Every field couples with every other within a cell (the coupled
    // [u | alpha | s] tangent); empty blocks cost nothing.
    TrilinosWrappers::BlockSparsityPattern sp(
      discretisation.owned_partitioning,
      discretisation.owned_partitioning,
      discretisation.relevant_partitioning,
      comm);
    DoFTools::make_sparsity_pattern(discretisation.dof_handler,
                                    sp,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(comm));
    sp.compress();
    tangent.reinit(sp);

    for (auto *v : {&newton_rhs, &residual, &delta})
      v->reinit(discretisation.owned_partitioning, comm);
    u_ghosted.reinit(discretisation.owned_partitioning,
                     discretisation.relevant_partitioning,
                     comm);
  }



  NewtonReport
  NewtonSolver::solve(const double                        t,
                      TrilinosWrappers::MPI::BlockVector &u,
                      TrilinosWrappers::MPI::BlockVector &internal_force)
  {
    NewtonReport              report;
    AffineConstraints<double> constraints;
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();

    const auto dirichlet_pending = [&]() {
      double largest = 0;
      for (const auto &line : constraints.get_lines())
        largest = std::max(largest, std::abs(line.inhomogeneity));
      return Utilities::MPI::max(largest, comm) > 0.;
    };

    // Records ||R|| of a state whose Dirichlet data are reached and returns
    // whether it is converged; if so, also the observed order from the last
    // three residuals above the round-off floor (eps times the size of the
    // terms summed into f_int, see AssemblyInfo::force_magnitude): a residual
    // at that floor says nothing about the rate, so the rate stays undefined
    // (nan) when fewer than three residuals lie above it.
    const auto converged =
      [&](const double r, const double scale, const AssemblyInfo &info) {
        report.residual_norms.push_back(r);
        if (r > parameters.relative_tolerance * scale +
                  parameters.absolute_tolerance * force_scale)
          return false;
        report.converged = true;
        const double floor =
          std::numeric_limits<double>::epsilon() * info.force_magnitude;
        const auto &h = report.residual_norms;
        std::size_t n = h.size();
        while (n >= 3 && h[n - 1] <= floor)
          --n;
        if (n >= 3 && h[n - 1] > 0 && h[n - 2] > 0 && h[n - 3] > 0 &&
            h[n - 2] != h[n - 3])
          report.convergence_rate =
            std::log(h[n - 1] / h[n - 2]) / std::log(h[n - 2] / h[n - 3]);
        return true;
      };

    const auto print = [&](const unsigned int it,
                           const double       r,
                           const double       scale,
                           const bool         pending) {
      verbose_out << "      Newton " << std::setw(2) << it
                  << ": |R| = " << std::scientific << std::setprecision(3) << r
                  << ", |R|/|f_int| = " << (scale > 0 ? r / scale : 0.)
                  << (pending ? ", Dirichlet data pending" : "")
                  << std::defaultfloat << std::endl;
    };

    for (unsigned int it = 0;; ++it)
      {
        u_ghosted = u;
        make_newton_constraints(
          discretisation, boundary_conditions, t, &u_ghosted, constraints);
        const bool pending = dirichlet_pending();

        {
          TimerOutput::Scope scope(timer, "assembly");
          report.info = assembler.assemble(
            u_ghosted,
            t,
            constraints,
            {&tangent, &newton_rhs, &residual, &internal_force});
        }
        const double r     = residual.l2_norm();
        const double scale = internal_force.l2_norm();
        report.iterations  = it;
        if (it == 0)
          print(it, r, scale, pending);
        if (!std::isfinite(r))
          {
            report.failure = "residual is not finite";
            return report;
          }
        // From the second iteration on, convergence is decided right after
        // the line search; only the start of a step is checked here.
        if (it == 0 && !pending && converged(r, scale, report.info))
          return report;

        unsigned int n_linear = 0;
        try
          {
            TimerOutput::Scope scope(timer, "linear solve");
            delta    = 0;
            n_linear = linear_solver.solve(tangent, delta, newton_rhs);
          }
        catch (const std::exception &e)
          {
            report.failure = std::string("linear solver failed: ") + e.what();
            return report;
          }
        constraints.distribute(delta);
        report.linear_iterations += n_linear;

        // Backtracking: shorten while an element inverts or, once the
        // Dirichlet data are reached, while ||R|| does not decrease. The
        // residual of the accepted state also decides convergence, so a
        // converged step never assembles a tangent it does not use.
        double       step     = 1.;
        bool         accepted = false;
        double       trial_r = 0, trial_scale = 0;
        AssemblyInfo trial_info;
        for (unsigned int ls = 0; ls <= parameters.max_line_search_steps;
             ++ls, step *= 0.5)
          {
            TrilinosWrappers::MPI::BlockVector trial = u;
            trial.add(step, delta);
            u_ghosted = trial;
            {
              TimerOutput::Scope scope(timer, "assembly (line search)");
              trial_info = assembler.assemble(
                u_ghosted,
                t,
                constraints,
                {nullptr, nullptr, &residual, &internal_force});
              trial_r     = residual.l2_norm();
              trial_scale = internal_force.l2_norm();
            }
            const bool decreases = pending || !parameters.line_search ||
                                   trial_r <= (1. - 1e-4 * step) * r;
            if (!trial_info.inverted && std::isfinite(trial_r) && decreases)
              {
                u        = trial;
                accepted = true;
                break;
              }
            verbose_out << "        line search: step " << step
                        << (trial_info.inverted ? " inverts an element"
                                                : " does not reduce |R|")
                        << std::endl;
          }
        if (!accepted)
          {
            report.failure = "line search found no admissible step";
            return report;
          }
        verbose_out << "        linear iterations " << n_linear
                    << (step < 1 ? ", step length " + std::to_string(step)
                                 : std::string())
                    << std::endl;

        const bool still_pending = pending && step < 1.;
        print(it + 1, trial_r, trial_scale, still_pending);
        report.iterations = it + 1;
        if (!still_pending && converged(trial_r, trial_scale, trial_info))
          {
            report.info = trial_info;
            return report;
          }
        if (it + 1 == parameters.max_iterations)
          {
            report.failure = "no convergence in " + std::to_string(it + 1) +
                             " Newton iterations";
            return report;
          }
      }
  }
} // namespace DuctileContact
