// Adaptive refinement in the load-step loop (Simulation::adapt_mesh()):
// the corrector of the predictor-corrector scheme and the state it carries.
#include <deal.II/hp/fe_values.h>

#include <ductile_contact/app/simulation.h>
#include <ductile_contact/app/time_integrator.h>
#include <ductile_contact/coupled/coupled_problem.h>
#include <ductile_contact/output/solution_writer.h>

#include <stdexcept>

namespace DuctileContact
{
  using namespace dealii;

  bool
  Simulation::adapt_mesh(TrilinosWrappers::MPI::BlockVector &trial)
  {
    TimerOutput::Scope scope(timer, "mesh adaptation");
    const auto ghosted = [&](const TrilinosWrappers::MPI::BlockVector &v) {
      TrilinosWrappers::MPI::BlockVector g(
        discretisation->owned_partitioning,
        discretisation->relevant_partitioning,
        comm);
      g = v;
      return g;
    };
    const TrilinosWrappers::MPI::BlockVector trial_ghosted = ghosted(trial);
    const MeshAdaptation::Flags flags = adaptation->flag(trial_ghosted);
    if (flags.held_back > 0 && !cell_limit_noted)
      {
        pcout << "  Note: Mesh/Adaptive refinement/Maximum cells = "
              << parameters.mesh.adaptive.maximum_cells << " leaves "
              << flags.held_back
              << " cells above the thresholds unrefined (noted once)."
              << std::endl;
        cell_limit_noted = true;
      }
    if (flags.flagged == 0)
      return false;

    // The accepted state: u_n (= old_solution), the quadrature-point
    // history, and the linear predictor's last increment.
    const TrilinosWrappers::MPI::BlockVector increment =
      ghosted(last_increment);
    MeshAdaptation::CellData cells(triangulation.n_active_cells());
    for (const auto &cell : discretisation->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cells[cell->active_cell_index()] = history.pack(cell);

    for (const auto &m : modules)
      m->keep_committed_state();
    const auto redistribute = [&]() {
      setup_dofs();
      trial.reinit(discretisation->owned_partitioning, comm);
    };
    // A dynamic run carries v_n, a_n and a_m,n too: fields, interpolated.
    std::vector<TrilinosWrappers::MPI::BlockVector> dynamic_state;
    if (dynamics)
      dynamic_state = dynamics->ghosted_vectors();
    std::vector<const TrilinosWrappers::MPI::BlockVector *> carried{
      &old_solution, &trial_ghosted, &increment};
    for (const auto &v : dynamic_state)
      carried.push_back(&v);
    std::vector<TrilinosWrappers::MPI::BlockVector *> arrived{&u,
                                                              &trial,
                                                              &last_increment};
    if (dynamics)
      for (auto *v : dynamics->vectors())
        arrived.push_back(v);
    adaptation->refine(carried,
                       cells,
                       QuadratureHistory::packed_size,
                       discretisation->quadrature[0],
                       redistribute,
                       arrived);

    for (const auto &cell : discretisation->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !history.unpack(cell, cells[cell->active_cell_index()]))
        throw std::logic_error("adapt_mesh: a cell's history did not arrive");
    old_solution = u;
    u_ghosted    = u;
    for (const auto &m : modules)
      m->transfer_committed_state(old_solution);
    align_hardening_history();
    accepted_force_on_new_mesh();
    writer->mesh_changed();
    return true;
  }



  void
  Simulation::accepted_force_on_new_mesh()
  {
    if (energy.last_force().size() == 0)
      return; // no step accepted yet: the unloaded start
    // A nodal force is not a field: interpolating it would put the
    // parent's nodal values on the new nodes too. It is assembled again
    // from the carried state instead. With alpha_n aligned to the alpha
    // field and u_n as both the state and the old solution, the points
    // neither flow nor pay viscous terms: f_int is that of the accepted
    // stresses.
    energy.last_force().reinit(discretisation->owned_partitioning, comm);
    AssemblyTargets targets;
    targets.internal_force = &energy.last_force();
    assembler->assemble(
      old_solution,
      {t,
       last_dt > 0. ? last_dt : parameters.load_stepping.time_step,
       &old_solution,
       &history,
       dynamics ? &dynamics->accepted_terms(old_solution) : nullptr},
      discretisation->hanging_node_constraints,
      targets);
    for (const auto &m : modules)
      m->add_committed_forces(old_solution, energy.last_force());
  }



  void
  Simulation::add_mesh_columns()
  {
    statistics.add("cells",
                   static_cast<unsigned int>(
                     triangulation.n_global_active_cells()));
    statistics.add(
      "dofs", static_cast<unsigned int>(discretisation->dof_handler.n_dofs()));
    statistics.add("refinements", refinements);
  }



  void
  Simulation::align_hardening_history()
  {
    if (!has_block(Block::hardening))
      return;
    hp::FEValues<dim>   hp_values(discretisation->mapping,
                                discretisation->fe_collection,
                                discretisation->quadrature,
                                update_values);
    std::vector<double> alpha;
    for (const auto &cell : discretisation->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          discretisation->cell_fields(cell).hardening)
        {
          hp_values.reinit(cell);
          const auto &fv = hp_values.get_present_fe_values();
          alpha.resize(fv.n_quadrature_points);
          fv[discretisation->hardening].get_function_values(old_solution,
                                                            alpha);
          PointHistory *h = history(cell);
          for (unsigned int q = 0; q < alpha.size(); ++q)
            h[q].plastic.alpha = std::max(0., alpha[q]);
        }
  }
} // namespace DuctileContact
