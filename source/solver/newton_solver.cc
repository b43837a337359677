#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/discretisation/constraints.h>
#include <ductile_contact/solver/anderson_acceleration.h>
#include <ductile_contact/solver/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// Sweeps of PhaseFieldBound::identify_active_set() per Newton
    /// iteration; the coupled iteration goes on from the last set if the
    /// sweeps have not settled (a set that cycles).
    constexpr unsigned int max_active_set_sweeps = 20;
  } // namespace

  NewtonSolver::NewtonSolver(
    const NewtonParameters              &parameters,
    const CouplingParameters            &coupling,
    const Discretisation                &discretisation,
    const SystemAssembler               &assembler,
    LinearSolver                        &linear_solver,
    const std::deque<BoundaryCondition> &boundary_conditions,
    const double                         force_scale,
    ConditionalOStream                  &verbose_out,
    TimerOutput                         &timer,
    ContactProblem                      *contact)
      : parameters(parameters)
      , coupling(coupling)
      , discretisation(discretisation)
      , assembler(assembler)
      , linear_solver(linear_solver)
      , boundary_conditions(boundary_conditions)
      , force_scale(force_scale)
      , verbose_out(verbose_out)
      , timer(timer)
      , contact(contact)
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
    // [u | alpha | s] tangent); empty blocks cost nothing. Contact writes
    // rows of every surface DoF (master rows of other ranks).
    std::vector<IndexSet> writable_rows = discretisation.relevant_partitioning;
    if (contact)
      {
        const IndexSet surface = contact->surface_dofs();
        writable_rows[Block::displacement].add_indices(
          surface.get_view(0, discretisation.dofs_per_block[0]));
      }
    TrilinosWrappers::BlockSparsityPattern sp(discretisation.owned_partitioning,
                                              discretisation.owned_partitioning,
                                              writable_rows,
                                              comm);
    if (discretisation.dofs_per_block[Block::phase_field] == 0)
      DoFTools::make_sparsity_pattern(discretisation.dof_handler,
                                      sp,
                                      constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(comm));
    else
      {
        // The C0IP terms couple s across interior faces, nothing else does.
        Table<2, DoFTools::Coupling> cell_coupling(Component::n_components,
                                                   Component::n_components);
        Table<2, DoFTools::Coupling> face_coupling(Component::n_components,
                                                   Component::n_components);
        cell_coupling.fill(DoFTools::always);
        face_coupling.fill(DoFTools::none);
        face_coupling(Component::phase_field, Component::phase_field) =
          DoFTools::always;
        DoFTools::make_flux_sparsity_pattern(discretisation.dof_handler,
                                             sp,
                                             constraints,
                                             false,
                                             cell_coupling,
                                             face_coupling,
                                             Utilities::MPI::this_mpi_process(
                                               comm));
      }
    // Constrained rows get a diagonal entry in distribute_local_to_global(),
    // also from face terms assembled on a ghost neighbour's DoFs, whose
    // diagonal the flux pattern of this rank does not hold.
    for (const auto i : discretisation.locally_relevant_dofs)
      sp.add(i, i);
    if (contact)
      contact->add_couplings(sp, constraints);
    sp.compress();
    tangent.reinit(sp);

    for (auto *v : {&newton_rhs, &residual, &delta})
      v->reinit(discretisation.owned_partitioning, comm);
    u_ghosted.reinit(discretisation.owned_partitioning,
                     discretisation.relevant_partitioning,
                     comm);
  }



  NewtonReport
  NewtonSolver::solve_step(const StepData                     &step,
                           TrilinosWrappers::MPI::BlockVector &u,
                           TrilinosWrappers::MPI::BlockVector &internal_force)
  {
    if (!contact)
      return solve_coupled(step, u, internal_force);

    u_ghosted = u;
    bool new_couplings;
    {
      TimerOutput::Scope scope(timer, "contact: search");
      new_couplings = contact->begin_step(u_ghosted);
    }
    if (new_couplings)
      setup(); // the candidate pairs changed: new couplings
    NewtonReport       total;
    const unsigned int max_augmentations =
      std::max_element(contact->pairs.begin(),
                       contact->pairs.end(),
                       [](const auto &a, const auto &b) {
                         return a.max_augmentations < b.max_augmentations;
                       })
        ->max_augmentations;
    for (unsigned int k = 0;; ++k)
      {
        const NewtonReport r = solve_coupled(step, u, internal_force);
        total.iterations += r.iterations;
        total.linear_iterations += r.linear_iterations;
        total.staggered_iterations = r.staggered_iterations;
        total.residual_norms       = r.residual_norms;
        total.convergence_rate     = r.convergence_rate;
        if (std::isfinite(r.tangent_error))
          total.tangent_error = r.tangent_error;
        total.info          = r.info;
        total.augmentations = k;
        if (!r.converged)
          {
            total.failure = r.failure;
            return total;
          }
        if (contact->augment())
          {
            total.converged = true;
            return total;
          }
        if (k + 1 == max_augmentations)
          {
            total.failure = "contact penetration above the tolerance after " +
                            std::to_string(k + 1) + " multiplier updates";
            return total;
          }
        verbose_out << "      contact multipliers updated (" << k + 1
                    << "); largest penetration before the update:";
        for (const ContactPairSummary &summary : contact->summary())
          verbose_out << " " << summary.max_penetration << " m";
        verbose_out << std::endl;
      }
  }



  AssemblyInfo
  NewtonSolver::assemble(const StepData                  &step,
                         const AffineConstraints<double> &constraints,
                         const AssemblyTargets           &targets)
  {
    const AssemblyInfo info =
      assembler.assemble(u_ghosted, step, constraints, targets);
    if (contact)
      {
        TimerOutput::Scope scope(timer,
                                 targets.tangent
                                   ? "contact: integration, tangent"
                                   : "contact: integration, residual");
        contact->assemble(u_ghosted, constraints, targets);
      }
    return info;
  }



  double
  NewtonSolver::tangent_error(const StepData                           &step,
                              const TrilinosWrappers::MPI::BlockVector &u,
                              const AffineConstraints<double> &constraints,
                              const PhaseFieldBound           *bound)
  {
    TrilinosWrappers::MPI::BlockVector k_delta = residual;
    tangent.vmult(k_delta, delta);
    constraints.set_zero(k_delta);
    if (bound)
      bound->remove_active_rows(k_delta);
    const double size = delta.linfty_norm();
    if (!(size > 0.) || !(k_delta.l2_norm() > 0.))
      return std::numeric_limits<double>::quiet_NaN();
    const double e = 1e-6 * std::max(u.linfty_norm(), size) / size;
    TrilinosWrappers::MPI::BlockVector difference = residual;
    for (const double sign : {1., -1.})
      {
        TrilinosWrappers::MPI::BlockVector trial = u;
        trial.add(sign * e, delta);
        u_ghosted = trial;
        AssemblyTargets targets{nullptr, nullptr, &residual, nullptr};
        targets.switches = AssemblyTargets::Switches::frozen;
        assemble(step, constraints, targets);
        if (bound)
          bound->remove_active_rows(residual);
        if (sign > 0.)
          difference = residual;
        else
          difference -= residual;
      }
    difference /= 2. * e;
    difference -= k_delta;
    const double       error = difference.l2_norm() / k_delta.l2_norm();
    std::ostringstream text;
    text << std::scientific << std::setprecision(2) << error;
    // By block as well: the rows of alpha and s are small in absolute terms
    // next to those of u, so their errors hide in the global ratio.
    const char *names[Block::n_blocks] = {"u", "alpha", "s"};
    text << " (by block:";
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      if (k_delta.block(b).size() > 0)
        text << " " << names[b] << " "
             << difference.block(b).l2_norm() /
                  std::max(k_delta.block(b).l2_norm(),
                           std::numeric_limits<double>::min());
    text << ")";
    verbose_out << "        tangent check: |K d - dR/de| / |K d| = "
                << text.str() << std::endl;
    return error;
  }



  NewtonReport
  NewtonSolver::solve_coupled(
    const StepData                     &step,
    TrilinosWrappers::MPI::BlockVector &u,
    TrilinosWrappers::MPI::BlockVector &internal_force)
  {
    const bool has_s = discretisation.dofs_per_block[Block::phase_field] > 0;
    if (coupling.strategy == "monolithic" || !has_s)
      return solve(step, u, internal_force, {{false, false, false}});

    NewtonReport total;
    if (coupling.strategy == "monolithic-staggered")
      {
        const TrilinosWrappers::MPI::BlockVector start = u;
        NewtonReport                             r =
          solve(step, u, internal_force, {{false, false, false}});
        if (r.converged)
          {
            r.staggered_iterations = 0; // Newton alone solved the step
            return r;
          }
        verbose_out << "      monolithic Newton failed (" << r.failure
                    << "); redoing the step staggered" << std::endl;
        u                       = start;
        total.iterations        = r.iterations;
        total.linear_iterations = r.linear_iterations;
      }

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
              solve(step,
                    u,
                    internal_force,
                    mechanics ? std::array<bool, 3>{{false, false, true}}
                              : std::array<bool, 3>{{true, true, false}});
            total.iterations += r.iterations;
            total.linear_iterations += r.linear_iterations;
            if (std::isfinite(r.tangent_error))
              total.tangent_error = r.tangent_error;
            total.info = r.info;
            if (!r.converged)
              {
                total.failure = (mechanics ? "mechanics sub-step: "
                                           : "phase-field sub-step: ") +
                                r.failure;
                return total;
              }
            if (r.iterations == 0 && (!mechanics || (k > 1 && !s_accelerated)))
              {
                total.converged        = true;
                total.convergence_rate = r.convergence_rate;
                return total;
              }
            total.convergence_rate = r.convergence_rate;
          }
        accelerate.update(s_iterate, u.block(Block::phase_field));
        verbose_out << "      staggered iteration " << k << " done"
                    << std::endl;
      }
    total.failure = "no staggered convergence in " +
                    std::to_string(coupling.max_staggered_iterations) +
                    " alternations";
    return total;
  }



  NewtonReport
  NewtonSolver::solve(const StepData                          &step,
                      TrilinosWrappers::MPI::BlockVector      &u,
                      TrilinosWrappers::MPI::BlockVector      &internal_force,
                      const std::array<bool, Block::n_blocks> &frozen)
  {
    NewtonReport              report;
    AffineConstraints<double> constraints;
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();

    // Irreversibility as a bound s >= s_n on the phase-field DoFs (not in
    // a sub-solve that freezes s). A state has converged only if it meets
    // the bound's KKT conditions, i.e. the complementarity residual C of
    // PhaseFieldBound in place of R_s meets the s tolerance. The active set
    // is engaged only once Newton has converged to a state that violates
    // them (usually a crack's band where s would relax): engaged from the
    // start, the active set of the first, far-off iterates holds DoFs that
    // the solution leaves free, and steps that never touch the bound took
    // 5 instead of 3 iterations (notched tension). Once engaged, the s rows
    // of the norms and the merit are C as well.
    const bool bounded =
      coupling.phase_field_bound() &&
      discretisation.dofs_per_block[Block::phase_field] > 0 &&
      !frozen[Block::phase_field] && step.old_solution != nullptr;
    PhaseFieldBound         bound(discretisation);
    bool                    bound_engaged = false, bound_applied = false;
    types::global_dof_index n_on_bound  = 0;
    const auto              apply_bound = [&]() {
      bound.record_diagonal(tangent);
      const types::global_dof_index n_first =
        bound.update_active_set(u, *step.old_solution, residual, constraints);
      const unsigned int sweeps =
        bound.identify_active_set(tangent,
                                  newton_rhs,
                                  u,
                                  *step.old_solution,
                                  constraints,
                                  linear_solver.direct_solver(),
                                  max_active_set_sweeps);
      n_on_bound = bound.active_size();
      verbose_out << "        active set on the s block: " << n_first << " -> "
                  << n_on_bound << " DoFs in " << sweeps << " sweeps"
                  << std::endl;
      bound.constrain(tangent, newton_rhs, u, *step.old_solution);
      bound.to_complementarity(residual, u, *step.old_solution, constraints);
      bound_applied = true;
    };

    const auto dirichlet_pending = [&]() {
      double largest = 0;
      for (const auto &line : constraints.get_lines())
        largest = std::max(largest, std::abs(line.inhomogeneity));
      return Utilities::MPI::max(largest, comm) > 0.;
    };

    // Norms of the residual blocks (frozen blocks are constrained, so
    // their entries are zero), their tolerances, and the merit: the norms
    // in units of the tolerances (for u alone simply ||R_u|| / tol_u).
    using Norms            = std::array<double, Block::n_blocks>;
    const auto block_norms = [&]() {
      Norms n;
      for (unsigned int b = 0; b < Block::n_blocks; ++b)
        n[b] = residual.block(b).l2_norm();
      return n;
    };
    const auto tolerances = [&](const double        f_int_norm,
                                const AssemblyInfo &info) {
      Norms tol;
      tol[0] = parameters.relative_tolerance * f_int_norm +
               parameters.absolute_tolerance * force_scale;
      for (unsigned int b = 1; b < Block::n_blocks; ++b)
        tol[b] = parameters.relative_tolerance * info.residual_scale[b];
      return tol;
    };
    const char *block_names[] = {"u", "alpha", "s"};
    const auto  merit         = [](const Norms &n, const Norms &tol) {
      double sum = 0;
      for (unsigned int b = 0; b < Block::n_blocks; ++b)
        if (tol[b] > 0.)
          sum += (n[b] / tol[b]) * (n[b] / tol[b]);
      return std::sqrt(sum);
    };

    // Records the merit (in the tolerances of the first state, so that
    // ratios are meaningful) of a state whose Dirichlet data are reached
    // and returns whether every block meets its tolerance; if so, also the
    // observed order from the last three merits above the round-off floor
    // (eps times the size of the terms summed into each block, see
    // AssemblyInfo::residual_magnitude): a residual at that floor says
    // nothing about the rate, so the rate stays undefined (nan) when fewer
    // than three residuals lie above it.
    Norms      reference{};
    const auto converged =
      [&](const Norms &n, const double f_int_norm, const AssemblyInfo &info) {
        report.residual_norms.push_back(merit(n, reference));
        const Norms tol = tolerances(f_int_norm, info);
        for (unsigned int b = 0; b < Block::n_blocks; ++b)
          if (n[b] > tol[b])
            return false;
        if (bounded && !bound_engaged)
          {
            // The tangent in memory is the current iterate's (the trial's
            // too: the line search assembles residuals only).
            bound.record_diagonal(tangent);
            TrilinosWrappers::MPI::BlockVector c = residual;
            bound.to_complementarity(c, u, *step.old_solution, constraints);
            if (c.block(Block::phase_field).l2_norm() > tol[Block::phase_field])
              {
                bound_engaged = true;
                // The merit changes (C in the s rows): the rate is that of
                // the iterations with the bound.
                report.residual_norms.clear();
                verbose_out << "        s falls below its last accepted "
                               "value: the bound s >= s_n is engaged"
                            << std::endl;
                return false;
              }
          }
        report.converged = true;
        Norms floor_norms;
        for (unsigned int b = 0; b < Block::n_blocks; ++b)
          floor_norms[b] = frozen[b] ? 0.
                                     : std::numeric_limits<double>::epsilon() *
                                         info.residual_magnitude[b];
        const double floor = merit(floor_norms, reference);
        const auto  &h     = report.residual_norms;
        std::size_t  k     = h.size();
        while (k >= 3 && h[k - 1] <= floor)
          --k;
        if (k >= 3 && h[k - 1] > 0 && h[k - 2] > 0 && h[k - 3] > 0 &&
            h[k - 2] != h[k - 3])
          report.convergence_rate =
            std::log(h[k - 1] / h[k - 2]) / std::log(h[k - 2] / h[k - 3]);
        return true;
      };

    const bool coupled = discretisation.dofs_per_block[Block::hardening] +
                           discretisation.dofs_per_block[Block::phase_field] >
                         0;
    const auto print = [&](const unsigned int  it,
                           const Norms        &n,
                           const double        f_int_norm,
                           const AssemblyInfo &info,
                           const bool          pending) {
      verbose_out << "      Newton " << std::setw(2) << it
                  << ": |R| = " << std::scientific << std::setprecision(3)
                  << n[0] << ", |R|/|f_int| = "
                  << (f_int_norm > 0 ? n[0] / f_int_norm : 0.);
      if (coupled)
        {
          const Norms tol = tolerances(f_int_norm, info);
          verbose_out << "; in tolerances:";
          for (unsigned int b = 0; b < Block::n_blocks; ++b)
            if (!frozen[b] && discretisation.dofs_per_block[b] > 0)
              verbose_out << " " << block_names[b] << " " << n[b] / tol[b];
        }
      if (bound_engaged)
        verbose_out << "; s held on its bound at " << n_on_bound << " DoFs";
      verbose_out << (pending ? ", Dirichlet data pending" : "")
                  << std::defaultfloat << std::endl;
    };

    // Whether the last accepted state was reached with frozen switches
    // (yield, crack-driver history) that its own state contradicts: its
    // residual is then not the true one, which the next assembly computes.
    bool switch_changed = false;
    for (unsigned int it = 0;; ++it)
      {
        u_ghosted = u;
        make_newton_constraints(discretisation,
                                boundary_conditions,
                                step.t,
                                &u_ghosted,
                                constraints,
                                frozen);
        const bool pending = dirichlet_pending();

        {
          TimerOutput::Scope scope(timer, "assembly");
          AssemblyTargets    targets{&tangent,
                                  &newton_rhs,
                                  &residual,
                                  &internal_force};
          targets.switches = AssemblyTargets::Switches::record;
          report.info      = assemble(step, constraints, targets);
        }
        bound_applied = false;
        if (bound_engaged)
          apply_bound();
        Norms        n     = block_norms();
        const double scale = internal_force.block(0).l2_norm();
        const Norms  tol   = tolerances(scale, report.info);
        double       r     = merit(n, tol);
        if (it == 0)
          reference = tol;
        report.iterations = it;
        if (it == 0 || switch_changed)
          print(it, n, scale, report.info, pending);
        if (!std::isfinite(r))
          {
            report.failure = "residual is not finite";
            return report;
          }
        // From the second iteration on, convergence is decided right after
        // the line search; only the start of a step is checked here.
        if ((it == 0 || switch_changed) && !pending &&
            converged(n, scale, report.info))
          return report;
        if (bound_engaged && !bound_applied) // engaged by the test above
          {
            apply_bound();
            n = block_norms();
            r = merit(n, tol);
          }

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
        if (parameters.check_tangent && !pending)
          report.tangent_error = tangent_error(
            step, u, constraints, bound_applied ? &bound : nullptr);

        // Backtracking: shorten while an element inverts or, once the
        // Dirichlet data are reached, while the merit does not decrease.
        // The residual of the accepted state also decides convergence, so a
        // converged step never assembles a tangent it does not use.
        double       step_length = 1.;
        bool         accepted    = false;
        double       trial_r = 0, trial_scale = 0;
        Norms        trial_n{};
        AssemblyInfo trial_info;
        for (unsigned int ls = 0; ls <= parameters.max_line_search_steps;
             ++ls, step_length *= 0.5)
          {
            TrilinosWrappers::MPI::BlockVector trial = u;
            trial.add(step_length, delta);
            u_ghosted = trial;
            {
              TimerOutput::Scope scope(timer, "assembly (line search)");
              // The switches of the iterate: R is smooth along the line
              // (a plastic point switching within it would make R jump by
              // its whole flow; a point whose psi^+ passes its history
              // maximum would add a slope the tangent does not have).
              AssemblyTargets targets{nullptr,
                                      nullptr,
                                      &residual,
                                      &internal_force};
              targets.switches = AssemblyTargets::Switches::frozen;
              trial_info       = assemble(step, constraints, targets);
              if (bound_engaged)
                bound.to_complementarity(residual,
                                         trial,
                                         *step.old_solution,
                                         constraints);
              trial_n     = block_norms();
              trial_r     = merit(trial_n, tol);
              trial_scale = internal_force.block(0).l2_norm();
            }
            const bool decreases = pending || !parameters.line_search ||
                                   trial_r <= (1. - 1e-4 * step_length) * r;
            if (!trial_info.inverted && std::isfinite(trial_r) && decreases)
              {
                u        = trial;
                accepted = true;
                break;
              }
            verbose_out << "        line search: step " << step_length
                        << (trial_info.inverted
                              ? std::string(" inverts an element")
                              : " does not reduce |R| (merit ratio " +
                                  std::to_string(trial_r / r) + ";")
                        << std::scientific << std::setprecision(2);
            if (!trial_info.inverted)
              for (unsigned int b = 0; b < Block::n_blocks; ++b)
                if (tol[b] > 0. && n[b] > 0.)
                  verbose_out << " " << block_names[b] << " "
                              << trial_n[b] / n[b];
            verbose_out << (trial_info.inverted ? "" : " by block)")
                        << std::defaultfloat << std::endl;
          }
        if (!accepted)
          {
            report.failure = "line search found no admissible step";
            return report;
          }
        verbose_out << "        linear iterations " << n_linear
                    << (step_length < 1
                          ? ", step length " + std::to_string(step_length)
                          : std::string())
                    << std::endl;

        const bool still_pending = pending && step_length < 1.;
        print(it + 1, trial_n, trial_scale, trial_info, still_pending);
        report.iterations = it + 1;
        switch_changed    = trial_info.switch_flips > 0;
        if (!still_pending && !switch_changed &&
            converged(trial_n, trial_scale, trial_info))
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
