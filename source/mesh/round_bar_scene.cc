#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <ductile_contact/mesh/scene.h>

#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  void
  create_round_bar_scene(const MeshParameters::RoundBar &parameters,
                         Triangulation<dim>             &tria)
  {
    const double R = parameters.radius, L = parameters.length;

    // A cylinder along x on [-L/2, L/2] (5 cells per cross-section), its
    // hull rounded by a cylindrical manifold while it is refined.
    Triangulation<dim> round;
    GridGenerator::subdivided_cylinder(round,
                                       parameters.axial_subdivisions,
                                       R,
                                       0.5 * L);
    round.set_manifold(0, CylindricalManifold<dim>(0));
    round.refine_global(parameters.refinements);

    // One level of straight-sided cells (the mapping is Q1 anyway), then
    // the imperfection: the radius shrinks linearly from the ends to
    // (1 - imperfection) R at mid-length. Axis moved to x in [0, L].
    Triangulation<dim> flat;
    GridGenerator::flatten_triangulation(round, flat);
    GridTools::transform(
      [&](const Point<dim> &p) {
        const double f =
          1. - parameters.imperfection * (1. - std::abs(p[0]) / (0.5 * L));
        return Point<dim>(p[0] + 0.5 * L, f * p[1], f * p[2]);
      },
      flat);

    // Boundary ids: 0 hull, 1 end x = 0, 2 end x = L (as generated).
    tria.copy_triangulation(flat);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
  }
} // namespace DuctileContact
