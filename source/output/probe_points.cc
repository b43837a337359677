#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/core/input_error.h>
#include <ductile_contact/output/probe_points.h>

#include <limits>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  ProbePoints::ProbePoints(const std::vector<Point<dim>> &points)
      : points(points)
  {
  }



  namespace
  {
    void
    refuse_outside(const Point<dim> &p)
    {
      std::ostringstream text;
      text << p;
      throw InputError("Output/Probe points",
                       text.str(),
                       "points inside the mesh (reference configuration)");
    }

    /// A locally owned cell of @p mesh that contains @p p and the point's
    /// coordinates in it; false if this rank owns none.
    template <typename MappingType, typename MeshType>
    bool
    owned_cell_around(const MappingType                       &mapping,
                      const MeshType                          &mesh,
                      const Point<dim>                        &p,
                      typename MeshType::active_cell_iterator &cell,
                      Point<dim>                              &unit)
    {
      try
        {
          const auto found =
            GridTools::find_active_cell_around_point(mapping, mesh, p);
          if (found.first.state() != IteratorState::valid ||
              !found.first->is_locally_owned())
            return false;
          cell = found.first;
          unit = found.second;
          return true;
        }
      catch (...)
        {
          return false; // not in this rank's part of the mesh
        }
    }
  } // namespace



  void
  ProbePoints::check_inside(const Triangulation<dim>      &tria,
                            const std::vector<Point<dim>> &points)
  {
    for (const Point<dim> &p : points)
      {
        Triangulation<dim>::active_cell_iterator cell;
        Point<dim>                               unit;
        const unsigned int                       found =
          owned_cell_around(MappingQ1<dim>(), tria, p, cell, unit);
        if (Utilities::MPI::max(found, tria.get_communicator()) == 0)
          refuse_outside(p);
      }
  }



  void
  ProbePoints::setup(const Discretisation &d)
  {
    discretisation = &d;
    locations.assign(points.size(), Location());
    const MPI_Comm     comm = d.dof_handler.get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        // Which rank owns a cell that contains the point: the lowest one.
        Location   found;
        Point<dim> unit;
        found.here = owned_cell_around(
          d.mapping, d.dof_handler, points[k], found.cell, unit);
        found.unit_point = GeometryInfo<dim>::project_to_unit_cell(unit);
        const unsigned int owner =
          found.here ? rank : std::numeric_limits<unsigned int>::max();
        const unsigned int lowest = Utilities::MPI::min(owner, comm);
        if (lowest == std::numeric_limits<unsigned int>::max())
          refuse_outside(points[k]);
        if (lowest == rank)
          locations[k] = found;
      }
  }



  std::vector<ProbeValue>
  ProbePoints::evaluate(const TrilinosWrappers::MPI::BlockVector &u) const
  {
    // Per point: the dim displacement components, alpha, s.
    constexpr unsigned int n_values = dim + 2;
    std::vector<double>    values(n_values * points.size(), 0.);
    Vector<double>         local;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const Location &at = locations[k];
        if (!at.here)
          continue;
        const auto &fe = at.cell->get_fe();
        local.reinit(fe.n_dofs_per_cell());
        at.cell->get_dof_values(u, local);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c    = fe.system_to_component_index(i).first;
            const unsigned int slot = c < dim                       ? c
                                      : c == Component::hardening   ? dim
                                      : c == Component::phase_field ? dim + 1
                                                                    : n_values;
            if (slot < n_values)
              values[n_values * k + slot] +=
                local[i] * fe.shape_value_component(i, at.unit_point, c);
          }
      }
    const std::vector<double> mine = values;
    Utilities::MPI::sum(make_array_view(mine),
                        discretisation->dof_handler.get_communicator(),
                        make_array_view(values));
    std::vector<ProbeValue> result(points.size());
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        for (unsigned int c = 0; c < dim; ++c)
          result[k].u[c] = values[n_values * k + c];
        result[k].alpha = values[n_values * k + dim];
        result[k].s     = values[n_values * k + dim + 1];
      }
    return result;
  }
} // namespace DuctileContact
