#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/distributed/cell_data_transfer.templates.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/discretisation/mesh_adaptation.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace DuctileContact
{
  using namespace dealii;

  std::vector<std::vector<unsigned int>>
  nearest_parent_points(const Quadrature<dim> &quadrature)
  {
    const unsigned int n_children = GeometryInfo<dim>::max_children_per_cell;
    std::vector<std::vector<unsigned int>> nearest(n_children);
    for (unsigned int c = 0; c < n_children; ++c)
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const Point<dim> x =
            GeometryInfo<dim>::child_to_cell_coordinates(quadrature.point(q),
                                                         c);
          unsigned int best = 0;
          for (unsigned int p = 1; p < quadrature.size(); ++p)
            if (x.distance_square(quadrature.point(p)) <
                x.distance_square(quadrature.point(best)))
              best = p;
          nearest[c].push_back(best);
        }
    return nearest;
  }



  MeshAdaptation::MeshAdaptation(
    const MeshParameters::AdaptiveRefinement  &parameters,
    parallel::distributed::Triangulation<dim> &tria,
    const Discretisation                      &d)
      : parameters(parameters)
      , tria(tria)
      , discretisation(d)
  {
  }



  double
  MeshAdaptation::indicator(const DoFHandler<dim>::active_cell_iterator &cell,
                            const Vector &u) const
  {
    const LocalDofs &dofs = discretisation.local_dofs(cell->active_fe_index());
    dealii::Vector<double> values(cell->get_fe().n_dofs_per_cell());
    cell->get_dof_values(u, values);
    double     eta     = 0.;
    const auto largest = [&](const std::vector<unsigned int> &indices,
                             const double                     threshold) {
      if (threshold > 0.)
        for (const unsigned int i : indices)
          eta = std::max(eta, values[i] / threshold);
    };
    largest(dofs.s, parameters.phase_field_threshold);
    largest(dofs.alpha, parameters.hardening_threshold);
    return eta;
  }



  MeshAdaptation::Flags
  MeshAdaptation::flag(const Vector &u)
  {
    const MPI_Comm comm = tria.get_communicator();
    std::vector<std::pair<double, DoFHandler<dim>::active_cell_iterator>>
      candidates;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          static_cast<unsigned int>(cell->level()) < parameters.maximum_level)
        {
          const double eta = indicator(cell, u);
          if (eta > 1.)
            candidates.emplace_back(eta, cell);
        }

    Flags      flags;
    const auto n_candidates =
      Utilities::MPI::sum<unsigned int>(candidates.size(), comm);
    // The smallest eta_K that is refined (all candidates without a limit).
    double cut = 1.;
    if (parameters.maximum_cells > 0)
      {
        const std::size_t cells   = tria.n_global_active_cells();
        const std::size_t room    = parameters.maximum_cells > cells
                                      ? parameters.maximum_cells - cells
                                      : 0;
        const std::size_t allowed = room / 7;
        if (n_candidates > allowed)
          {
            std::vector<double> mine;
            for (const auto &c : candidates)
              mine.push_back(c.first);
            std::vector<double> all;
            for (const auto &part : Utilities::MPI::all_gather(comm, mine))
              all.insert(all.end(), part.begin(), part.end());
            std::sort(all.begin(), all.end(), std::greater<double>());
            cut = allowed == 0 ? std::numeric_limits<double>::infinity()
                               : all[allowed - 1];
          }
      }
    unsigned int flagged = 0;
    for (const auto &[eta, cell] : candidates)
      if (eta >= cut)
        {
          cell->set_refine_flag();
          ++flagged;
        }
    flags.flagged   = Utilities::MPI::sum(flagged, comm);
    flags.held_back = n_candidates - flags.flagged;
    return flags;
  }



  void
  MeshAdaptation::refine(const std::vector<const Vector *> &ghosted,
                         CellData                          &cell_data,
                         const unsigned int                 record_size,
                         const Quadrature<dim>             &quadrature,
                         const std::function<void()>       &redistribute,
                         const std::vector<Vector *>       &owned)
  {
    using Records      = std::vector<double>;
    const auto nearest = nearest_parent_points(quadrature);
    const auto inject  = [&](const Triangulation<dim>::cell_iterator &,
                            const Records &parent) {
      std::vector<Records> children(nearest.size());
      if (parent.empty())
        return children;
      for (unsigned int c = 0; c < nearest.size(); ++c)
        for (const unsigned int p : nearest[c])
          children[c].insert(children[c].end(),
                             parent.begin() + p * record_size,
                             parent.begin() + (p + 1) * record_size);
      return children;
    };
    // Cells are never coarsened; the strategy is required by the class.
    const auto keep_first = [](const Triangulation<dim>::cell_iterator &,
                               const std::vector<Records> &children) {
      return children.front();
    };

    parallel::distributed::SolutionTransfer<dim, Vector> vectors(
      discretisation.dof_handler);
    vectors.prepare_for_coarsening_and_refinement(ghosted);
    parallel::distributed::CellDataTransfer<dim, dim, CellData> cells(
      tria, true, inject, keep_first);
    cells.prepare_for_coarsening_and_refinement(cell_data);

    tria.execute_coarsening_and_refinement();
    redistribute();

    std::vector<Vector *> out = owned;
    vectors.interpolate(out);
    for (Vector *v : owned)
      discretisation.hanging_node_constraints.distribute(*v);
    cell_data.assign(tria.n_active_cells(), {});
    cells.unpack(cell_data);
  }
} // namespace DuctileContact
