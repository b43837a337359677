#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <ductile_contact/app/simulation.h>
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/coupled/coupled_problem.h>
#include <ductile_contact/coupled/coupled_solver.h>

#include <cmath>

// The statistics columns of a step: boundary forces and displacements,
// probes, field extrema and crack measures, solver counts (Simulation's
// record_step()).
namespace DuctileContact
{
  using namespace dealii;

  std::vector<Simulation::BoundaryIntegrals>
  Simulation::boundary_integrals(const TrilinosWrappers::MPI::BlockVector &u,
                                 const double t) const
  {
    const unsigned int n_bc = parameters.boundary_conditions.size();
    std::map<types::boundary_id, unsigned int> index;
    for (unsigned int b = 0; b < n_bc; ++b)
      index[parameters.boundary_conditions[b].boundary_id] = b;

    // Per boundary: int u dA (3), int T dA (3), area.
    std::vector<double>         sums(n_bc * (2 * dim + 1), 0.);
    hp::FEFaceValues<dim>       hp_face_values(discretisation->mapping,
                                         discretisation->fe_collection,
                                         discretisation->face_quadrature,
                                         update_values |
                                           update_quadrature_points |
                                           update_JxW_values);
    std::vector<Tensor<1, dim>> values;
    for (const auto &cell : discretisation->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto it = index.find(cell->face(f)->boundary_id());
              if (it == index.end())
                continue;
              const BoundaryCondition &bc =
                parameters.boundary_conditions[it->second];
              double *sum = &sums[it->second * (2 * dim + 1)];
              hp_face_values.reinit(cell, f);
              const auto &fv = hp_face_values.get_present_fe_values();
              values.resize(fv.n_quadrature_points);
              fv[discretisation->displacement].get_function_values(u, values);
              for (unsigned int q = 0; q < values.size(); ++q)
                {
                  const Tensor<1, dim> T =
                    bc.has_traction ? bc.traction_at(fv.quadrature_point(q), t)
                                    : Tensor<1, dim>();
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      sum[d] += values[q][d] * fv.JxW(q);
                      sum[dim + d] += T[d] * fv.JxW(q);
                    }
                  sum[2 * dim] += fv.JxW(q);
                }
            }
    Utilities::MPI::sum(sums, comm, sums);

    std::vector<BoundaryIntegrals> result(n_bc);
    for (unsigned int b = 0; b < n_bc; ++b)
      {
        const double *sum = &sums[b * (2 * dim + 1)];
        for (unsigned int d = 0; d < dim; ++d)
          {
            result[b].mean_displacement[d] = sum[d] / sum[2 * dim];
            result[b].traction_force[d]    = sum[dim + d];
          }
      }
    return result;
  }



  void
  Simulation::add_boundary_columns(const double t)
  {
    const auto  integrals = boundary_integrals(u_ghosted, t);
    const char *xyz[]     = {"x", "y", "z"};
    for (unsigned int b = 0; b < parameters.boundary_conditions.size(); ++b)
      {
        const BoundaryCondition &bc = parameters.boundary_conditions[b];
        const std::string        id = Utilities::to_string(bc.boundary_id);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add("u" + id + "_" + xyz[d],
                         integrals[b].mean_displacement[d]);
        // Force on the body through this boundary: on a constrained
        // component the reaction, i.e. the sum of f_int over the DoFs this
        // boundary constrains; on the others the applied traction int T dA.
        // (Summing f_int there too would count the reactions of nodes this
        // boundary shares with a constrained one.)
        for (unsigned int d = 0; d < dim; ++d)
          {
            double reaction = 0;
            if (bc.constrained[d])
              for (const auto i : boundary_dofs[b][d])
                reaction += internal_force(i);
            statistics.add("F" + id + "_" + xyz[d],
                           bc.constrained[d]
                             ? Utilities::MPI::sum(reaction, comm)
                             : integrals[b].traction_force[d]);
          }
      }
    const auto probe_values = probes->evaluate(u_ghosted);
    for (unsigned int k = 0; k < probe_values.size(); ++k)
      {
        const std::string name = "probe" + std::to_string(k + 1);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add(name + "_u_" + xyz[d], probe_values[k].u[d]);
        if (has_block(Block::hardening))
          statistics.add(name + "_alpha", probe_values[k].alpha);
        if (has_block(Block::phase_field))
          statistics.add(name + "_s", probe_values[k].s);
      }
  }



  void
  Simulation::add_field_columns()
  {
    if (has_block(Block::hardening))
      {
        statistics.add("max_alpha", committed.max_alpha);
        const double min_increment = committed.min_yielding_alpha_increment;
        statistics.add("min_alpha_change_yielding",
                       min_increment < std::numeric_limits<double>::max()
                         ? min_increment
                         : 0.);
      }
    if (has_block(Block::phase_field))
      {
        statistics.add("max_s", max_phase_field);
        statistics.add("max_s_points", committed.max_s_point);
        statistics.add("min_s_change", min_phase_field_change);
        statistics.add("crack_area", committed.crack_area);
        statistics.add("cracked_volume", committed.cracked_volume);
        const char *xyz[] = {"x", "y", "z"};
        for (const auto &[name, box] :
             {std::pair{"cracked_min_", committed.cracked_min},
              std::pair{"cracked_max_", committed.cracked_max}})
          for (unsigned int d = 0; d < dim; ++d)
            statistics.add(name + std::string(xyz[d]), box[d]);
      }
  }



  void
  Simulation::add_solver_columns(const StepReport  &report,
                                 const unsigned int cutbacks)
  {
    statistics.add("newton_iterations", report.iterations);
    if (has_block(Block::phase_field))
      statistics.add("staggered_iterations", report.staggered_iterations);
    // Undefined values are written as 0 (an order and an error are
    // positive where defined): no NaN in the results.
    const auto defined = [](const double v) {
      return std::isfinite(v) ? v : 0.;
    };
    statistics.add("newton_rate", defined(report.convergence_rate));
    statistics.add("branch_conflicts", report.branch_conflicts);
    if (parameters.newton.check_tangent)
      statistics.add("tangent_error", defined(report.tangent_error));
    statistics.add("linear_iterations", report.linear_iterations);
    statistics.add("cutbacks", cutbacks);
    if (dynamics)
      statistics.add("local_error", local_error);
    // Cumulative wall time of the phases, for work-precision studies.
    const Times times = cumulative_times();
    statistics.add("assembly_time", times.assembly);
    statistics.add("solve_time", times.solve);
    statistics.add("wall_time", times.wall);
  }
} // namespace DuctileContact
