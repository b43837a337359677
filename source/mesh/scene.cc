#include <deal.II/base/mpi.h>

#include <ductile_contact/core/input_error.h>
#include <ductile_contact/mesh/scene.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    void
    refine_boxes(const MeshParameters                      &parameters,
                 parallel::distributed::Triangulation<dim> &tria)
    {
      for (const RefinementBox &box : parameters.refinement_boxes)
        for (unsigned int level = 0; level < box.levels; ++level)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  const Point<dim> c      = cell->center();
                  bool             inside = true;
                  for (unsigned int d = 0; d < dim; ++d)
                    inside =
                      inside && c[d] >= box.lower[d] && c[d] <= box.upper[d];
                  if (inside)
                    cell->set_refine_flag();
                }
            tria.execute_coarsening_and_refinement();
          }
    }
  } // namespace



  void
  create_scene_mesh(const MeshParameters                      &parameters,
                    parallel::distributed::Triangulation<dim> &tria)
  {
    switch (parameters.scene)
      {
      case SceneType::box:
        create_box_scene(parameters.box, tria);
        break;
      case SceneType::two_bodies:
        create_two_body_scene(parameters.two_bodies, tria);
        break;
      case SceneType::round_bar:
#if DUCTILE_CONTACT_DIM == 3
        create_round_bar_scene(parameters.round_bar, tria);
        break;
#else
        // Refused by MeshParameters::check().
        AssertThrow(false, ExcInternalError());
#endif
      case SceneType::gmsh:
        create_gmsh_scene(parameters.gmsh, tria);
        break;
      }

    tria.refine_global(parameters.global_refinements);
    refine_boxes(parameters, tria);
  }



  std::set<types::material_id>
  material_ids_in_mesh(const parallel::distributed::Triangulation<dim> &tria)
  {
    std::set<types::material_id> ids;
    // The coarse mesh is known on every rank and children inherit ids.
    for (const auto &cell : tria.cell_iterators_on_level(0))
      ids.insert(cell->material_id());
    return ids;
  }



  std::set<types::boundary_id>
  boundary_ids_in_mesh(const Triangulation<dim> &tria)
  {
    std::set<types::boundary_id> ids;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          ids.insert(face->boundary_id());
    return ids;
  }
} // namespace DuctileContact
