#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <ductile_contact/app/application.h>
#include <ductile_contact/app/physics_modules.h>
#include <ductile_contact/app/prm_writer.h>
#include <ductile_contact/app/simulation.h>
#include <ductile_contact/app/step_controller.h>
#include <ductile_contact/app/stop_request.h>
#include <ductile_contact/app/time_integrator.h>
#include <ductile_contact/core/input_error.h>
#include <ductile_contact/core/memory_use.h>
#include <ductile_contact/coupled/coupled_problem.h>
#include <ductile_contact/coupled/coupled_solver.h>
#include <ductile_contact/output/progress_line.h>
#include <ductile_contact/output/solution_writer.h>
#include <ductile_contact/phase_field/initial_crack.h>
#include <ductile_contact/solver/linear_solver.h>
#include <ductile_contact/solver/newton_solver.h>

#include <algorithm>
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  Simulation::Simulation(const RunParameters &parameters,
                         const MPI_Comm       comm,
                         TeeStream           &log,
                         const std::string   &resume_from)
      : parameters(parameters)
      , comm(comm)
      , resume_from(resume_from)
      , log(log)
      , pcout(log, Utilities::MPI::this_mpi_process(comm) == 0)
      , verbose_out(log,
                    Utilities::MPI::this_mpi_process(comm) == 0 &&
                      parameters.output.verbosity >= 2)
      , timer(comm, pcout, TimerOutput::summary, TimerOutput::wall_times)
      , triangulation(comm)
      , statistics(parameters.output.directory + "/statistics")
      , controller(parameters.load_stepping)
      , checkpoints(parameters.output.directory,
                    parameters.checkpoint.keep,
                    comm)
  {
    for (const BodyParameters &b : parameters.bodies)
      bodies[b.material_id] = &b;
  }



  Simulation::~Simulation() = default;



  void
  Simulation::create_mesh()
  {
    TimerOutput::Scope scope(timer, "setup: mesh");
    if (resume_from.empty())
      {
        build_and_check_mesh(parameters, triangulation, true);
        return;
      }
    build_and_check_mesh(parameters, triangulation, false);
    const std::string saved = checkpoints.read(resume_from, "coarse_mesh");
    const std::string here = Checkpoint::coarse_mesh_fingerprint(triangulation);
    if (Utilities::trim(saved) != here)
      throw InputError("Mesh",
                       "(a coarse mesh of " + here + ")",
                       "the coarse mesh the checkpoint was made on (" +
                         Utilities::trim(saved) +
                         "); has the mesh file changed?");
    Checkpoint::load_mesh(resume_from, triangulation);
  }



  void
  Simulation::limit_phase_field_increment(
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &u_old,
    const double                              dt,
    StepReport                               &report) const
  {
    const LoadSteppingParameters &ls = parameters.load_stepping;
    if (!has_block(Block::phase_field) || ls.max_phase_field_increment >= 1. ||
        dt <= 1e-3 * ls.time_step)
      return;
    TrilinosWrappers::MPI::Vector rise = u.block(Block::phase_field);
    rise -= u_old.block(Block::phase_field);
    const double largest = rise.max();
    if (largest <= ls.max_phase_field_increment)
      return;
    std::ostringstream s;
    s << "s rose by " << largest
      << " at a DoF, more than 'Load stepping/Maximum phase-field "
         "increment' = "
      << ls.max_phase_field_increment;
    report.converged = false;
    report.failure   = s.str();
  }



  double
  Simulation::limit_local_error(const TrilinosWrappers::MPI::BlockVector &u,
                                const TrilinosWrappers::MPI::BlockVector &u_old,
                                const double                              dt,
                                StepReport &report)
  {
    const LoadSteppingParameters &ls = parameters.load_stepping;
    if (!dynamics)
      return std::numeric_limits<double>::infinity();
    local_error            = dynamics->local_error(u, u_old, dt);
    const double tolerance = ls.local_error_tolerance;
    if (tolerance <= 0. || local_error <= 0.)
      return std::numeric_limits<double>::infinity();
    const double factor = 0.9 * std::cbrt(tolerance / local_error);
    if (local_error > tolerance && dt > 2. * ls.minimum_time_step)
      {
        std::ostringstream s;
        s << "local error estimate " << local_error
          << " above 'Load stepping/Local error tolerance' = " << tolerance;
        report.converged = false;
        report.failure   = s.str();
      }
    return factor;
  }



  void
  Simulation::setup()
  {
    create_mesh();

    std::map<types::material_id, BodyFields> fields;
    for (const BodyParameters &b : parameters.bodies)
      fields[b.material_id] = BodyFields{b.plasticity, b.fracture};
    discretisation =
      std::make_unique<Discretisation>(triangulation,
                                       parameters.fe_degree,
                                       fields,
                                       parameters.phase_field_basis,
                                       parameters.hardening_basis);
    probes = std::make_unique<ProbePoints>(parameters.output.probe_points);

    // Force scale of the absolute Newton tolerance: mu_max * diameter^2.
    Point<dim> lo, hi;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lo[d] = std::numeric_limits<double>::max();
        hi[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::min(lo[d], cell->vertex(v)[d]);
            hi[d] = std::max(hi[d], cell->vertex(v)[d]);
          }
    double mu_max = 0;
    for (const BodyParameters &b : parameters.bodies)
      mu_max = std::max(mu_max, b.shear_modulus);
    const double force_scale = mu_max * lo.distance_square(hi);

    assembler =
      std::make_unique<SystemAssembler>(*discretisation,
                                        bodies,
                                        parameters.boundary_conditions,
                                        parameters.coupling.crack_history());
    linear_solver =
      std::make_unique<LinearSolver>(parameters.linear_solver, *discretisation);
    modules = make_physics_modules(parameters, *discretisation, bodies);
    std::vector<PhysicsModule *> module_list;
    for (const auto &m : modules)
      module_list.push_back(m.get());
    problem = std::make_unique<CoupledProblem>(*discretisation,
                                               *assembler,
                                               parameters.boundary_conditions,
                                               parameters.coupling,
                                               force_scale,
                                               verbose_out,
                                               timer,
                                               module_list);
    newton  = std::make_unique<NewtonSolver>(parameters.newton,
                                            *linear_solver,
                                            NewtonMonitor{verbose_out, timer});
    solver  = std::make_unique<CoupledSolver>(
      parameters.coupling, *problem, *newton, verbose_out, module_list);
    writer = std::make_unique<SolutionWriter>(parameters.output.directory,
                                              parameters.output.format,
                                              *discretisation,
                                              bodies);

    if (parameters.load_stepping.time_integration !=
        TimeIntegration::quasi_static)
      {
        std::vector<types::boundary_id> massless;
        if (parameters.load_stepping.contact_surface_mass ==
            ContactSurfaceMass::redistributed)
          for (const ContactPairParameters &c : parameters.contact_pairs)
            {
              massless.push_back(c.slave_boundary_id);
              massless.push_back(c.master_boundary_id);
            }
        dynamics =
          std::make_unique<TimeIntegrator>(parameters.load_stepping,
                                           parameters.bodies,
                                           parameters.boundary_conditions,
                                           *discretisation,
                                           massless);
      }
    if (parameters.mesh.adaptive.enabled)
      adaptation = std::make_unique<MeshAdaptation>(parameters.mesh.adaptive,
                                                    triangulation,
                                                    *discretisation);
    setup_dofs();

    const auto        &n = discretisation->dofs_per_block;
    std::ostringstream body_list;
    for (const BodyParameters &b : parameters.bodies)
      body_list << (b.material_id == parameters.bodies.front().material_id
                      ? ""
                      : ", ")
                << b.name << " (id " << static_cast<unsigned>(b.material_id)
                << ")";
    pcout << "Mesh: " << triangulation.n_global_active_cells() << " cells on "
          << Utilities::MPI::n_mpi_processes(comm)
          << " MPI rank(s); bodies: " << body_list.str() << std::endl
          << "DoFs: " << discretisation->dof_handler.n_dofs() << " (u "
          << n[Block::displacement] << ", alpha " << n[Block::hardening]
          << ", s " << n[Block::phase_field] << "), FE_Q("
          << parameters.fe_degree << ")" << std::endl
          << "Linear solver: " << linear_solver->describe() << std::endl;
  }



  void
  Simulation::setup_dofs()
  {
    {
      TimerOutput::Scope scope(timer, "setup: dofs");
      discretisation->setup();
      probes->setup(*discretisation);
    }
    {
      TimerOutput::Scope scope(timer, "setup: rigid-body modes");
      linear_solver->setup();
    }
    for (const auto &m : modules)
      {
        TimerOutput::Scope scope(timer, "setup: " + m->name());
        m->setup();
      }
    problem->setup();

    for (auto *v : {&u, &internal_force, &last_increment})
      v->reinit(discretisation->owned_partitioning, comm);
    for (auto *v : {&u_ghosted, &old_solution})
      v->reinit(discretisation->owned_partitioning,
                discretisation->relevant_partitioning,
                comm);
    history.reinit(discretisation->dof_handler,
                   discretisation->quadrature[0].size());
    if (dynamics)
      dynamics->setup();

    boundary_dofs.clear();
    for (const BoundaryCondition &bc : parameters.boundary_conditions)
      {
        // Only constrained components report a reaction (record_step).
        std::array<IndexSet, dim> per_component;
        for (unsigned int c = 0; c < dim; ++c)
          if (bc.constrained[c])
            {
              std::vector<bool> mask(Component::n_components, false);
              mask[c] = true;
              per_component[c] =
                DoFTools::extract_boundary_dofs(discretisation->dof_handler,
                                                ComponentMask(mask),
                                                {bc.boundary_id});
              per_component[c] =
                per_component[c] & discretisation->locally_owned_dofs;
            }
        boundary_dofs.push_back(per_component);
      }
  }



  Simulation::Times
  Simulation::cumulative_times() const
  {
    const NewtonTimes &newton_times = newton->times();
    return {earlier.wall + MPI_Wtime() - wall_start,
            earlier.assembly + newton_times.assembly,
            earlier.solve + newton_times.solve};
  }



  void
  Simulation::record_step(const unsigned int step,
                          const double       t,
                          const double       dt,
                          const StepReport  &report,
                          const unsigned int cutbacks)
  {
    statistics.add("step", step);
    statistics.add("time", t);
    statistics.add("dt", dt);
    add_boundary_columns(t);
    double module_dissipation = 0.;
    for (const auto &m : modules)
      module_dissipation += m->dissipation();
    energy.add_columns(statistics,
                       committed,
                       has_block(Block::hardening),
                       has_block(Block::phase_field),
                       dynamics != nullptr,
                       module_dissipation);
    add_field_columns();
    for (const auto &m : modules)
      m->add_columns(statistics);
    add_solver_columns(report, cutbacks);
    if (adaptation)
      add_mesh_columns();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      statistics.write();
  }



  AssemblyInfo
  Simulation::commit(const StepData &step_data)
  {
    TimerOutput::Scope scope(timer, "commit history");
    QuadratureHistory  updated = history;
    u_ghosted                  = u;
    const AssemblyInfo info =
      assembler->commit(u_ghosted, step_data, updated, cell_quantities);
    history = std::move(updated);
    return info;
  }



  bool
  Simulation::has_block(const unsigned int b) const
  {
    return discretisation->dofs_per_block[b] > 0;
  }



  void
  Simulation::write_output(const unsigned int step, const double t)
  {
    TimerOutput::Scope scope(timer, "output");
    writer->write(step,
                  t,
                  u_ghosted,
                  cell_quantities,
                  dynamics ? &dynamics->current_velocity() : nullptr);
    for (const auto &m : modules)
      m->write_output(parameters.output.directory,
                      parameters.output.format,
                      step,
                      t);
  }



  void
  Simulation::accept_step(const StepData                           &step_data,
                          const TrilinosWrappers::MPI::BlockVector &u_old)
  {
    internal_force                               = problem->internal_force();
    TrilinosWrappers::MPI::BlockVector increment = u;
    increment -= u_old;
    StepData commit_data = step_data;
    if (dynamics)
      commit_data.inertia = &dynamics->commit_terms(u, u_old, step_data.dt);
    committed = commit(commit_data);
    if (dynamics)
      dynamics->accept();
    for (const auto &m : modules)
      m->commit();
    energy.add_step(internal_force, increment, committed);
    if (has_block(Block::phase_field))
      {
        TrilinosWrappers::MPI::Vector ds = u.block(Block::phase_field);
        ds -= u_old.block(Block::phase_field);
        min_phase_field_change = ds.min();
        max_phase_field        = u.block(Block::phase_field).max();
      }
    old_solution = u;
    u_ghosted    = u;
  }



  void
  Simulation::start()
  {
    u = 0;
    if (set_initial_crack(*discretisation, parameters.bodies, u))
      {
        // The initial crack relaxed at zero load: the minimiser of the
        // crack functional with s at least the given one (the bound
        // s >= s_n), the state the run starts from and whose energy is the
        // zero of the energy account.
        old_solution            = u;
        const StepReport report = solver->solve_step(
          {0., parameters.load_stepping.time_step, &old_solution, &history}, u);
        if (!report.converged)
          throw InputError("the initial crack of Fracture/Initial crack "
                           "cannot be relaxed at zero load (" +
                           report.failure + ")");
        pcout << "Initial crack relaxed at zero load in " << report.iterations
              << " Newton iterations" << std::endl;
      }
    old_solution = u;
    if (dynamics)
      dynamics->start();
    committed = commit({0.,
                        parameters.load_stepping.time_step,
                        &old_solution,
                        &history,
                        dynamics ? &dynamics->initial_terms() : nullptr});
    energy.start(committed);
    record_step(0, 0., 0., StepReport(), 0);
    if (parameters.output.interval > 0)
      write_output(0, 0.);
  }



  std::string
  Simulation::run_state() const
  {
    const Times                     times = cumulative_times();
    std::ostringstream              text;
    boost::archive::binary_oarchive ar(text);
    ar << step << t << last_dt << times.wall << times.assembly << times.solve
       << controller << energy << statistics << *writer;
    // One (state, output series) record per module; one empty record
    // without modules.
    if (modules.empty())
      ar << std::vector<double>() << PhysicsModule::OutputSeries();
    for (const auto &m : modules)
      ar << m->committed_state() << m->output_series();
    return text.str();
  }



  void
  Simulation::load_run_state(const std::string &text)
  {
    std::istringstream              in(text);
    boost::archive::binary_iarchive ar(in);
    ar >> step >> t >> last_dt >> earlier.wall >> earlier.assembly >>
      earlier.solve >> controller >> energy >> statistics >> *writer;
    std::vector<double>         state;
    PhysicsModule::OutputSeries series;
    if (modules.empty())
      {
        ar >> state >> series;
        if (!state.empty())
          throw InputError("the checkpoint has a contact state, but this run "
                           "has no contact pairs");
      }
    for (const auto &m : modules)
      {
        ar >> state >> series;
        m->restore_committed_state(state);
        m->output_series() = series;
      }
  }



  void
  Simulation::restore()
  {
    TimerOutput::Scope scope(timer, "checkpoint");
    energy.last_force().reinit(discretisation->owned_partitioning, comm);
    Checkpoint::CellData                              cells;
    std::vector<TrilinosWrappers::MPI::BlockVector *> vectors{
      &u, &last_increment, &energy.last_force()};
    if (dynamics)
      for (auto *v : dynamics->vectors())
        vectors.push_back(v);
    Checkpoint::load_data(discretisation->dof_handler, vectors, cells);
    for (const auto &cell : discretisation->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !history.unpack(cell, cells[cell->active_cell_index()]))
        throw InputError("the checkpoint's quadrature-point history does "
                         "not fit this run's quadrature");
    old_solution = u;
    u_ghosted    = u;
    load_run_state(checkpoints.read(resume_from, "state.bin"));
    // The HDF5 output's mesh file holds the cells in the order of the
    // partition that wrote it: a resumed run writes its own.
    writer->mesh_changed();
    assembler->cell_averages(u_ghosted,
                             {t, last_dt, &old_solution, &history},
                             cell_quantities);
    // The statistics end at the checkpoint's step: rows a killed run
    // wrote after it are dropped now, not at the next step.
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      statistics.write();
    pcout << "Resumed from " << resume_from << " at step " << step
          << ", t = " << t << std::endl;
  }



  void
  Simulation::write_checkpoint()
  {
    TimerOutput::Scope   scope(timer, "checkpoint");
    Checkpoint::CellData cells(triangulation.n_active_cells());
    for (const auto &cell : discretisation->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cells[cell->active_cell_index()] = history.pack(cell);
    TrilinosWrappers::MPI::BlockVector increment(
      discretisation->owned_partitioning,
      discretisation->relevant_partitioning,
      comm),
      force(increment);
    increment = last_increment;
    force     = energy.last_force();
    std::ostringstream all;
    write_prm(parameters.prm, all);
    std::vector<TrilinosWrappers::MPI::BlockVector>         dynamic_state;
    std::vector<const TrilinosWrappers::MPI::BlockVector *> vectors{&u_ghosted,
                                                                    &increment,
                                                                    &force};
    if (dynamics)
      dynamic_state = dynamics->ghosted_vectors();
    for (const auto &v : dynamic_state)
      vectors.push_back(&v);
    checkpoints.write(step,
                      discretisation->dof_handler,
                      vectors,
                      cells,
                      run_state(),
                      all.str());
  }



  std::vector<TrilinosWrappers::MPI::BlockVector>
  Simulation::predict(const double                        ratio,
                      TrilinosWrappers::MPI::BlockVector &u) const
  {
    const auto extrapolate_displacements =
      [&](TrilinosWrappers::MPI::BlockVector &v) {
        v.block(Block::displacement)
          .add(ratio, last_increment.block(Block::displacement));
      };
    switch (parameters.load_stepping.predictor)
      {
      case Predictor::constant:
        return {};
      case Predictor::linear:
        u.add(ratio, last_increment);
        return {};
      case Predictor::linear_displacements:
        extrapolate_displacements(u);
        return {};
      case Predictor::best_linear:
        {
          std::vector<TrilinosWrappers::MPI::BlockVector> alternatives{u};
          extrapolate_displacements(alternatives[0]);
          u.add(ratio, last_increment);
          return alternatives;
        }
      }
    Assert(false, ExcInternalError());
    return {};
  }



  int
  Simulation::run()
  {
    wall_start = MPI_Wtime();
    setup();
    if (resume_from.empty())
      start();
    else
      restore();

    const auto  &ls  = parameters.load_stepping;
    const double T   = ls.end_time;
    const double eps = 1e-12 * T;
    const auto   n_steps =
      static_cast<unsigned int>(std::ceil(T / ls.time_step - 1e-9));
    const unsigned int interval            = parameters.output.interval;
    const unsigned int checkpoint_interval = parameters.checkpoint.interval;
    const ProgressLine progress(pcout, T, n_steps);
    // Adaptive refinement: the converged trial state of a step whose
    // mesh was refined (the next attempt's initial guess), and how often
    // the step has been refined.
    std::optional<TrilinosWrappers::MPI::BlockVector> refined_trial;
    while (t < T - eps)
      {
        const double dt_try = controller.next_increment(t);
        const TrilinosWrappers::MPI::BlockVector        u_old = u;
        std::vector<TrilinosWrappers::MPI::BlockVector> alternatives;
        if (refined_trial)
          {
            u = *refined_trial;
            refined_trial.reset();
          }
        else if (last_dt > 0.)
          alternatives = predict(dt_try / last_dt, u);
        const StepData step_data{t + dt_try,
                                 dt_try,
                                 &old_solution,
                                 &history,
                                 dynamics
                                   ? &dynamics->step_terms(old_solution, dt_try)
                                   : nullptr};
        StepReport     report = solver->solve_step(step_data, u, alternatives);

        double error_factor = std::numeric_limits<double>::infinity();
        if (report.converged)
          {
            limit_phase_field_increment(u, u_old, dt_try, report);
            error_factor = limit_local_error(u, u_old, dt_try, report);
          }
        if (!report.converged)
          {
            u = u_old;
            const bool go_on =
              controller.reject(t, dt_try, std::clamp(error_factor, 0.2, 0.5));
            pcout << "  step " << step + 1 << " at t = " << t + dt_try
                  << " failed (" << report.failure
                  << "); cutting back to dt = " << controller.increment()
                  << std::endl;
            if (!go_on)
              {
                if (controller.stalled())
                  pcout << "Error: the load stepping stalls: "
                        << ls.max_stalled_failures
                        << " failed steps since t = " << controller.stall_time()
                        << ", while t advanced by less than 1e-3 of the time "
                           "step ('Load stepping/Maximum failures without "
                           "progress'); the last failure: "
                        << report.failure;
                else
                  pcout << "Error: the load step would have to be smaller "
                           "than 'Load stepping/Minimum time step' = "
                        << ls.minimum_time_step;
                pcout << " at t = " << t << ". Results up to this time are in '"
                      << parameters.output.directory << "'." << std::endl;
                print_resources();
                return gave_up;
              }
            continue;
          }

        if (adaptation && refinements < parameters.mesh.adaptive.maximum_passes)
          {
            TrilinosWrappers::MPI::BlockVector trial  = u;
            const LinearSolverType             before = linear_solver->type();
            if (adapt_mesh(trial))
              {
                ++refinements;
                pcout << "  step " << step + 1 << " at t = " << t + dt_try
                      << ": mesh refined (pass " << refinements << "), "
                      << triangulation.n_global_active_cells() << " cells, "
                      << discretisation->dof_handler.n_dofs()
                      << " DoFs; solving the step again" << std::endl;
                if (linear_solver->type() != before)
                  pcout << "  Linear solver: " << linear_solver->describe()
                        << std::endl;
                refined_trial = std::move(trial);
                continue;
              }
          }

        t += dt_try;
        ++step;
        last_increment = u;
        last_increment -= u_old;
        last_dt = dt_try;
        accept_step(step_data, u_old);
        record_step(step, t, dt_try, report, controller.cutbacks());
        controller.accept(dt_try, report.iterations, error_factor);
        refinements = 0;

        const bool stop = stop_requested(comm);
        const bool last = t >= T - eps;
        if (interval > 0 && (step % interval == 0 || last || stop))
          write_output(step, t);
        if (checkpoint_interval > 0 &&
            (step % checkpoint_interval == 0 || stop))
          write_checkpoint();

        StepProgress p;
        p.step              = step;
        p.t                 = t;
        p.newton_iterations = report.iterations;
        p.linear_iterations = report.linear_iterations;
        p.rate              = report.convergence_rate;
        if (has_block(Block::phase_field))
          {
            p.max_s = max_phase_field;
            p.alternations =
              parameters.coupling.strategy != CouplingStrategy::monolithic
                ? report.staggered_iterations
                : 0;
          }
        p.min_J   = report.info.min_J;
        p.elapsed = earlier.wall + MPI_Wtime() - wall_start;
        progress.print(p);

        if (stop && !last)
          {
            pcout << "Stopped by a signal after step " << step << " (t = " << t
                  << "); results up to it are in '"
                  << parameters.output.directory << "'"
                  << (checkpoint_interval > 0
                        ? ", and 'ductile-contact --resume' continues from "
                          "its checkpoint"
                        : " (no checkpoint: Checkpoint/Interval = 0)")
                  << "." << std::endl;
            return stopped;
          }
      }
    print_resources();
    return finished;
  }



  void
  Simulation::print_resources()
  {
    const MemoryUse memory = MemoryUse::peak(comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      linear_solver->print_summary(pcout.get_stream());
    pcout << "Memory: " << memory.describe(discretisation->dof_handler.n_dofs())
          << std::endl;
  }
} // namespace DuctileContact
