#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/coupled/coupled_problem.h>
#include <ductile_contact/discretisation/constraints.h>

#include <cmath>
#include <limits>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The s DoFs of @p cell (the global indices of its phase-field
    /// component), appended to @p dofs.
    void
    append_phase_field_dofs(const DoFHandler<dim>::cell_iterator &cell,
                            std::vector<types::global_dof_index> &dofs)
    {
      std::vector<types::global_dof_index> indices(
        cell->get_fe().n_dofs_per_cell());
      cell->get_dof_indices(indices);
      for (unsigned int i = 0; i < indices.size(); ++i)
        if (cell->get_fe().system_to_component_index(i).first ==
            Component::phase_field)
          dofs.push_back(indices[i]);
    }



    /**
     * The couplings of the C0IP face terms, added face by face as the
     * assembly visits the faces (for_each_owned_interior_face(): a face
     * with a finer neighbour from the finer side, periodic faces, only
     * between cells of the same element), through @p constraints as the
     * assembly distributes them. make_flux_sparsity_pattern() alone misses
     * some of these entries at hanging faces.
     */
    void
    add_crack_face_couplings(const Discretisation            &d,
                             const AffineConstraints<double> &constraints,
                             TrilinosWrappers::BlockSparsityPattern &sp)
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : d.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            Discretisation::fields(cell->active_fe_index()).phase_field)
          for (const unsigned int f : cell->face_indices())
            {
              const bool periodic = cell->has_periodic_neighbor(f);
              if (cell->at_boundary(f) && !periodic)
                continue;
              const auto neighbor =
                periodic ? cell->periodic_neighbor(f) : cell->neighbor(f);
              if (neighbor->has_children() ||
                  neighbor->active_fe_index() != cell->active_fe_index())
                continue;
              dofs.clear();
              append_phase_field_dofs(cell, dofs);
              append_phase_field_dofs(neighbor, dofs);
              constraints.add_entries_local_to_global(dofs, sp, false);
            }
    }
  } // namespace



  namespace
  {
    /// Sweeps of FieldBound::identify_active_set() per Newton
    /// iteration; the coupled iteration goes on from the last set if the
    /// sweeps have not settled (a set that cycles).
    constexpr unsigned int max_active_set_sweeps = 20;
  } // namespace



  CoupledProblem::CoupledProblem(
    const Discretisation                &discretisation,
    const SystemAssembler               &assembler,
    const std::deque<BoundaryCondition> &boundary_conditions,
    const CouplingParameters            &coupling,
    const double                         force_scale,
    ConditionalOStream                  &verbose_out,
    TimerOutput                         &timer,
    const std::vector<PhysicsModule *>  &modules)
      : discretisation(discretisation)
      , assembler(assembler)
      , boundary_conditions(boundary_conditions)
      , coupling(coupling)
      , force_scale(force_scale)
      , verbose_out(verbose_out)
      , timer(timer)
      , modules(modules)
  {
  }



  void
  CoupledProblem::setup()
  {
    TimerOutput::Scope scope(timer, "setup: sparsity");
    const MPI_Comm     comm = discretisation.dof_handler.get_communicator();

    // Same constrained DoF set as every Newton iteration (values differ).
    AffineConstraints<double> pattern_constraints;
    make_newton_constraints(
      discretisation, boundary_conditions, 0., nullptr, pattern_constraints);

    // Every field couples with every other within a cell (the coupled
    // [u | alpha | s] tangent); empty blocks cost nothing. A module may
    // write further rows (contact: every surface DoF, master rows of other
    // ranks).
    std::vector<IndexSet> writable_rows = discretisation.relevant_partitioning;
    for (const PhysicsModule *m : modules)
      {
        const IndexSet          rows  = m->written_rows();
        types::global_dof_index first = 0;
        for (unsigned int b = 0; b < Block::n_blocks; ++b)
          {
            const types::global_dof_index n = discretisation.dofs_per_block[b];
            writable_rows[b].add_indices(rows.get_view(first, first + n));
            first += n;
          }
      }
    TrilinosWrappers::BlockSparsityPattern sp(discretisation.owned_partitioning,
                                              discretisation.owned_partitioning,
                                              writable_rows,
                                              comm);
    if (!has_phase_field())
      DoFTools::make_sparsity_pattern(discretisation.dof_handler,
                                      sp,
                                      pattern_constraints,
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
                                             pattern_constraints,
                                             false,
                                             cell_coupling,
                                             face_coupling,
                                             Utilities::MPI::this_mpi_process(
                                               comm));
      }
    if (has_phase_field())
      add_crack_face_couplings(discretisation, pattern_constraints, sp);
    // Constrained rows get a diagonal entry in distribute_local_to_global(),
    // also from face terms assembled on a ghost neighbour's DoFs, whose
    // diagonal the flux pattern of this rank does not hold.
    for (const auto i : discretisation.locally_relevant_dofs)
      sp.add(i, i);
    for (const PhysicsModule *m : modules)
      m->add_couplings(sp, pattern_constraints);
    sp.compress();
    tangent.reinit(sp);
    tangent_pattern = new_pattern_id();

    for (auto *v : {&newton_rhs, &residual, &force})
      v->reinit(discretisation.owned_partitioning, comm);
    u_ghosted.reinit(discretisation.owned_partitioning,
                     discretisation.relevant_partitioning,
                     comm);
  }



  void
  CoupledProblem::begin_step(const StepData &step_data, const Vector &u)
  {
    step = step_data;
    if (modules.empty())
      return;
    u_ghosted          = u;
    bool new_couplings = false;
    for (PhysicsModule *m : modules)
      {
        TimerOutput::Scope scope(timer, m->name() + ": begin step");
        new_couplings = m->begin_step(u_ghosted) || new_couplings;
      }
    if (new_couplings)
      setup(); // e.g. the contact candidates changed: new couplings
  }



  void
  CoupledProblem::freeze(const std::array<bool, Block::n_blocks> &blocks)
  {
    frozen = blocks;
  }



  bool
  CoupledProblem::has_phase_field() const
  {
    return discretisation.dofs_per_block[Block::phase_field] > 0;
  }



  std::vector<std::string>
  CoupledProblem::block_names() const
  {
    return {"u", "alpha", "s"};
  }



  bool
  CoupledProblem::block_solved(const unsigned int b) const
  {
    return !frozen[b] && discretisation.dofs_per_block[b] > 0;
  }



  unsigned int
  CoupledProblem::n_nonempty_blocks() const
  {
    unsigned int n = 0;
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      n += discretisation.dofs_per_block[b] > 0 ? 1 : 0;
    return n;
  }



  void
  CoupledProblem::begin_solve()
  {
    // Irreversibility as a bound s_n <= s <= 1 on the phase-field DoFs, not in
    // a sub-solve that freezes s.
    bounds.clear();
    if (step.old_solution != nullptr && coupling.phase_field_bound() &&
        block_solved(Block::phase_field))
      bounds.push_back({FieldBound(discretisation, Block::phase_field, 1.)});
    // A bound that held DoFs in the last step (s at s_n where a crack
    // unloads, at 1 where the fourth-order field overshoots) is needed in
    // this one: engaged from the start, the step saves the iterations of a
    // first convergence without it.
    for (BoundState &b : bounds)
      b.engaged = bound_last_solve[b.bound.block()];
    // alpha_n <= alpha (Plasticity/Loading condition = bound) is engaged
    // from the first iteration: without it alpha would fall wherever the
    // stress is below yield, i.e. almost everywhere.
    if (step.old_solution != nullptr && coupling.hardening_bound &&
        block_solved(Block::hardening))
      {
        bounds.push_back({FieldBound(discretisation, Block::hardening)});
        bounds.back().engaged = true;
        bounds.back().chord   = true;
      }
  }



  bool
  CoupledProblem::begin_iteration(const Vector &x)
  {
    u_ghosted        = x;
    prescribed_fault = make_newton_constraints(discretisation,
                                               boundary_conditions,
                                               step.t,
                                               &u_ghosted,
                                               constraints,
                                               frozen);
    // Prescribed values that the iterate misses by round-off only are
    // reached: the linear predictor's u_n + r (u_n - u_n-1) lands within a
    // few ulps of the data, and half of prm/sent_coarse.prm's steps started
    // "pending", so that their first update was taken whatever it did to
    // the residual. Round-off is measured against the largest prescribed
    // value; the update applies the exact values either way.
    constexpr double round_off = 1e-10;
    double           mismatch = 0., value = 0.; // largest |g - x|, |g|
    for (const auto &line : constraints.get_lines())
      if (line.inhomogeneity != 0.)
        {
          mismatch = std::max(mismatch, std::abs(line.inhomogeneity));
          value =
            std::max(value,
                     std::abs(u_ghosted(line.index) + line.inhomogeneity));
        }
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    return Utilities::MPI::max(mismatch, comm) >
           round_off * Utilities::MPI::max(value, comm);
  }



  AssemblyInfo
  CoupledProblem::assemble(const AssemblyTargets &targets)
  {
    // A module compresses at its end; the bulk terms before the modules
    // only if one of them reads them complete.
    bool compressed_bulk = modules.empty();
    for (const PhysicsModule *m : modules)
      compressed_bulk = compressed_bulk || m->needs_compressed_bulk();
    const AssemblyInfo info = assembler.assemble(
      u_ghosted, step, constraints, targets, compressed_bulk);
    for (PhysicsModule *m : modules)
      {
        TimerOutput::Scope scope(timer,
                                 m->name() + (targets.tangent
                                                ? ": integration, tangent"
                                                : ": integration, residual"));
        m->assemble(u_ghosted, constraints, targets);
      }
    if (targets.tangent)
      {
        constrained.clear();
        for (const PhysicsModule *m : modules)
          m->add_constrained_rows(constrained);
      }
    return info;
  }



  std::vector<double>
  CoupledProblem::residual_norms() const
  {
    std::vector<double> n(Block::n_blocks);
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      n[b] = residual.block(b).l2_norm();
    return n;
  }



  ResidualEvaluation
  CoupledProblem::evaluation(const AssemblyInfo &info) const
  {
    ResidualEvaluation e;
    e.norms          = residual_norms();
    e.relative_scale = {force.block(Block::displacement).l2_norm(),
                        info.residual_scale[Block::hardening],
                        info.residual_scale[Block::phase_field]};
    e.absolute_scale = {force_scale, 0., 0.};
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      e.round_off.push_back(frozen[b] ? 0.
                                      : std::numeric_limits<double>::epsilon() *
                                          info.residual_magnitude[b]);
    std::string module_fault;
    for (const PhysicsModule *m : modules)
      if (module_fault.empty())
        module_fault = m->fault();
    e.admissible = !info.inverted && !info.non_finite &&
                   prescribed_fault.empty() && module_fault.empty();
    e.inadmissible   = !prescribed_fault.empty() ? prescribed_fault
                       : !module_fault.empty()   ? module_fault
                                                 : assembler.fault(info);
    e.branch_changes = info.switch_flips;
    return e;
  }



  DirectSolve &
  CoupledProblem::bound_solver(const unsigned int block)
  {
    if (!bound_solvers[block])
      bound_solvers[block] = std::make_unique<DirectSolve>(
        discretisation.dof_handler.get_communicator(),
        DirectSolveSettings::exact_lu());
    return *bound_solvers[block];
  }



  void
  CoupledProblem::apply_bounds(const Vector &x)
  {
    for (BoundState &b : bounds)
      if (b.engaged)
        {
          TimerOutput::Scope scope(timer, "bound: active set");
          FieldBound        &bound = b.bound;
          bound.record_diagonal(tangent);
          const types::global_dof_index n_first = bound.update_active_set(
            x, *step.old_solution, residual, constraints);
          const unsigned int sweeps =
            bound.identify_active_set(tangent,
                                      newton_rhs,
                                      x,
                                      *step.old_solution,
                                      constraints,
                                      bound_solver(bound.block()),
                                      max_active_set_sweeps);
          b.n_on_bound = bound.active_size();
          verbose_out << "        active set on the " << bound.field_name()
                      << " block: " << n_first << " -> " << b.n_on_bound
                      << " DoFs in " << sweeps << " sweeps" << std::endl;
          bound.constrain(tangent, newton_rhs, x, *step.old_solution);
          bound.to_complementarity(residual,
                                   x,
                                   *step.old_solution,
                                   constraints);
          b.applied   = true;
          b.rows_kept = true;
        }
  }



  bool
  CoupledProblem::any_bound_engaged() const
  {
    for (const BoundState &b : bounds)
      if (b.engaged)
        return true;
    return false;
  }



  ResidualEvaluation
  CoupledProblem::assemble_system(const Vector &x)
  {
    return assemble_recording(x, &tangent);
  }



  ResidualEvaluation
  CoupledProblem::assemble_recording(const Vector &x, Matrix *matrix)
  {
    AssemblyTargets targets{matrix, &newton_rhs, &residual, &force};
    if (matrix == &tangent)
      targets.pattern = tangent_pattern;
    targets.branch_record = &branches;
    targets.branches      = Branches::record;
    last_info             = assemble(targets);
    // A chord step keeps the bounds' rows while their active sets stay.
    // Otherwise (a tangent, or the first guesses of a step, whose bounds
    // have no rows yet) the active sets and rows are made afresh, scaled
    // by the diagonal of the tangent at hand.
    if (matrix == nullptr && keeps_tangent())
      keep_bound_rows(x);
    else
      {
        for (BoundState &b : bounds)
          b.applied = false;
        apply_bounds(x);
      }
    return evaluation(last_info);
  }



  ResidualEvaluation
  CoupledProblem::assemble_residual(const Vector &x)
  {
    // The switches of the iterate: R is smooth along the line (a plastic
    // point switching within it would make R jump by its whole flow; a
    // point whose psi^+ passes its history maximum would add a slope the
    // tangent does not have).
    u_ghosted = x;
    AssemblyTargets targets{nullptr, nullptr, &residual, &force};
    targets.branch_record = &branches;
    targets.branches      = Branches::frozen;
    last_info             = assemble(targets);
    for (const BoundState &b : bounds)
      if (b.engaged)
        b.bound.to_complementarity(residual,
                                   x,
                                   *step.old_solution,
                                   constraints);
    return evaluation(last_info);
  }



  bool
  CoupledProblem::keeps_tangent() const
  {
    // The bounds' rows are those of the iterate's active sets: a tangent
    // with a bound's rows serves only while that set stays.
    for (const BoundState &b : bounds)
      if (b.engaged && !(b.chord && b.applied && b.rows_kept))
        return false;
    return true;
  }



  void
  CoupledProblem::keep_bound_rows(const Vector &x)
  {
    for (BoundState &b : bounds)
      if (b.engaged)
        {
          TimerOutput::Scope scope(timer, "bound: active set");
          b.rows_kept = b.bound.keep_active_set(
            x, *step.old_solution, residual, constraints, newton_rhs);
          b.bound.to_complementarity(residual,
                                     x,
                                     *step.old_solution,
                                     constraints);
        }
  }



  ResidualEvaluation
  CoupledProblem::assemble_right_hand_side(const Vector &x)
  {
    // A chord step (keeps_tangent()) or a first guess of the step
    // (NewtonSolver::best_start, before any tangent of this solve).
    return assemble_recording(x, nullptr);
  }



  bool
  CoupledProblem::converged(const Vector              &x,
                            const std::vector<double> &tolerances)
  {
    // The tangent in memory is the current iterate's (the trial's too: the
    // line search assembles residuals only).
    bool engaged_now = false;
    for (BoundState &b : bounds)
      if (!b.engaged)
        {
          const unsigned int block = b.bound.block();
          b.bound.record_diagonal(tangent);
          Vector c = residual;
          b.bound.to_complementarity(c, x, *step.old_solution, constraints);
          if (c.block(block).l2_norm() > tolerances[block])
            {
              b.engaged   = true;
              engaged_now = true;
              verbose_out << "        " << b.bound.field_name()
                          << " falls below its last accepted value"
                          << (block == Block::phase_field ? " or rises above 1"
                                                          : "")
                          << ": its bound is engaged" << std::endl;
            }
        }
    if (engaged_now)
      return false;
    accepted_info = last_info;
    // Not from the solve at t = 0 that relaxes an initial crack: the first
    // load step, a jump of the prescribed values from rest, starts free.
    bound_last_solve.fill(false);
    for (const BoundState &b : bounds)
      bound_last_solve[b.bound.block()] =
        b.engaged && b.n_on_bound > 0 && step.t > 0.;
    return true;
  }



  std::vector<double>
  CoupledProblem::modify_linear_system(const Vector &x)
  {
    bool pending = false; // engaged by converged()
    for (const BoundState &b : bounds)
      pending = pending || (b.engaged && !b.applied);
    if (pending)
      apply_bounds(x);
    return residual_norms();
  }



  void
  CoupledProblem::distribute(Vector &d) const
  {
    constraints.distribute(d);
  }



  std::string
  CoupledProblem::describe() const
  {
    std::string text;
    for (const BoundState &b : bounds)
      if (b.engaged)
        text += (text.empty() ? "" : ", ") + b.bound.field_name() +
                " held on its bound at " + std::to_string(b.n_on_bound) +
                " DoFs";
    return text;
  }



  void
  CoupledProblem::compared_product(const Vector &d, Vector &k_d) const
  {
    tangent.vmult(k_d, d);
    constraints.set_zero(k_d);
    for (const BoundState &b : bounds)
      if (b.applied)
        b.bound.remove_active_rows(k_d);
  }



  void
  CoupledProblem::compared_residual(const Vector &x, Vector &r)
  {
    u_ghosted = x;
    AssemblyTargets targets{nullptr, nullptr, &residual, nullptr};
    targets.branch_record = &branches;
    targets.branches      = Branches::frozen;
    assemble(targets);
    for (const BoundState &b : bounds)
      if (b.applied)
        b.bound.remove_active_rows(residual);
    r = residual;
  }
} // namespace DuctileContact
