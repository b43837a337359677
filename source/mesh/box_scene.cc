#include <deal.II/grid/grid_generator.h>

#include <ductile_contact/mesh/scene.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  create_box_scene(const MeshParameters::Box &parameters,
                   Triangulation<dim>        &tria)
  {
    // colorize = true gives ids 0..5 on the faces x-, x+, y-, y+, z-, z+.
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              parameters.subdivisions,
                                              parameters.lower_corner,
                                              parameters.upper_corner,
                                              true);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(0);
  }
} // namespace DuctileContact
