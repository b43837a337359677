#pragma once

#include <deal.II/distributed/tria.h>

#include <ductile_contact/core/types.h>
#include <ductile_contact/mesh/mesh_parameters.h>

#include <set>

namespace DuctileContact
{
  /**
   * Builds the mesh of the scene named in `Mesh/Scene` into @p tria: the
   * coarse mesh with material ids (bodies) and boundary ids, then the global
   * and the box-wise local refinements. Throws InputError when the scene
   * cannot be built (e.g. an unreadable Gmsh file).
   *
   * Each scene lives in a file of its own (box_scene.cc, two_body_scene.cc,
   * round_bar_scene.cc, gmsh_scene.cc); nothing outside this folder knows which
   * scene runs.
   */
  void
  create_scene_mesh(const MeshParameters &parameters,
                    dealii::parallel::distributed::Triangulation<dim> &tria);

  /// A brick with boundary ids 0..5 on the faces x-, x+, y-, y+, z-, z+
  /// (a rectangle with 0..3 on its edges x-, x+, y-, y+ in 2-D).
  void
  create_box_scene(const MeshParameters::Box  &parameters,
                   dealii::Triangulation<dim> &tria);

  /**
   * The plate and block of doc/model.md section 7 as one mesh of two
   * disconnected bodies (no shared vertices): material id 0 = plate,
   * 1 = block; boundary ids 1 = clamp (plate face x = Lx), 3 = plate top,
   * 2 = block top, 4 = block bottom, 5 = block sides, 0 = other plate faces.
   */
  void
  create_two_body_scene(const MeshParameters::TwoBodies &parameters,
                        dealii::Triangulation<dim>      &tria);

  /**
   * Round bar along x in [0, L] with a linear taper to (1 - imperfection)
   * times the radius at mid-length (validation rung 3): material id 0.
   * Model full: boundary ids 0 = hull, 1 = end x = 0, 2 = end x = L;
   * octant: the part x >= L/2, y >= 0, z >= 0 with ids 0 = hull, 2 = end,
   * 3, 4, 5 = planes x = L/2, y = 0, z = 0. The hull carries a chart
   * manifold of the tapered surface, the cells a transfinite interpolation
   * (so refinement and a MappingQ(p) follow the exact geometry).
   */
  void
  create_round_bar_scene(const MeshParameters::RoundBar &parameters,
                         dealii::Triangulation<dim>     &tria);

  /// A Gmsh mesh; physical tags become material and boundary ids.
  void
  create_gmsh_scene(const MeshParameters::Gmsh &parameters,
                    dealii::Triangulation<dim> &tria);

  /// Material ids present in the (distributed) mesh, on all ranks.
  std::set<dealii::types::material_id>
  material_ids_in_mesh(
    const dealii::parallel::distributed::Triangulation<dim> &tria);

  /// Boundary ids present in the (distributed) mesh, on all ranks: those
  /// of the coarse mesh, which every rank holds.
  std::set<dealii::types::boundary_id>
  boundary_ids_in_mesh(const dealii::Triangulation<dim> &tria);
} // namespace DuctileContact
