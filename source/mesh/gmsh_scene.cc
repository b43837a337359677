#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>

#include <ductile_contact/core/input_error.h>
#include <ductile_contact/core/one_line.h>
#include <ductile_contact/mesh/scene.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The distance of @p p from the centre of @p b, or from its axis.
    double
    radius_of(const Point<dim> &p, const MeshParameters::CurvedBoundary &b)
    {
      Tensor<1, dim> d = p - b.centre;
      if (b.axis.norm() > 0.)
        {
          const Tensor<1, dim> e = b.axis / b.axis.norm();
          d -= (d * e) * e;
        }
      return d.norm();
    }

    /// Gives the faces of boundary @p b the manifold id @p id and attaches
    /// the circle, sphere or cylinder to @p tria, after checking that the
    /// boundary's vertices lie on it.
    void
    attach_curved_boundary(const MeshParameters::CurvedBoundary &b,
                           const types::manifold_id              id,
                           Triangulation<dim>                   &tria)
    {
      const std::string entry = "Mesh/Gmsh/Curved boundaries";
      double            r_min = std::numeric_limits<double>::max(), r_max = 0.;
      std::string       ids_text;
      for (const types::boundary_id i : boundary_ids_in_mesh(tria))
        ids_text += (ids_text.empty() ? "" : ", ") + std::to_string(i);
      for (const auto &cell : tria.cell_iterators_on_level(0))
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == b.boundary_id)
            {
              face->set_all_manifold_ids(id);
              for (const unsigned int v : face->vertex_indices())
                {
                  const double r = radius_of(face->vertex(v), b);
                  r_min          = std::min(r_min, r);
                  r_max          = std::max(r_max, r);
                }
            }
      check_input(r_max > 0.,
                  entry,
                  b.text,
                  "no face of the mesh has boundary id " +
                    std::to_string(b.boundary_id) + " (it has " + ids_text +
                    ")");
      check_input(r_max - r_min <= 1e-6 * r_max,
                  entry,
                  b.text,
                  "the vertices of boundary " + std::to_string(b.boundary_id) +
                    " are not on one surface: their distances from the " +
                    (b.axis.norm() > 0. ? "axis" : "centre") + " range from " +
                    Utilities::to_string(r_min) + " to " +
                    Utilities::to_string(r_max) +
                    ", and must agree to 1e-6 of the radius");
      if (b.axis.norm() > 0.)
        {
#if DUCTILE_CONTACT_DIM == 3
          tria.set_manifold(id, CylindricalManifold<dim>(b.axis, b.centre));
#endif
        }
      else
        tria.set_manifold(id, SphericalManifold<dim>(b.centre));
    }
  } // namespace



  void
  create_gmsh_scene(const MeshParameters::Gmsh &parameters,
                    Triangulation<dim>         &tria)
  {
    std::ifstream in(parameters.file_name);
    if (!in)
      throw InputError("Mesh/Gmsh/File name",
                       parameters.file_name,
                       "this file cannot be opened");
    GridIn<dim> grid_in;
    grid_in.attach_triangulation(tria);
    try
      {
        // Physical volume tags -> material_id, physical surface tags ->
        // boundary_id (GridIn's convention for .msh files).
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        throw InputError("Mesh/Gmsh/File name",
                         parameters.file_name,
                         std::string("it is not a readable ") +
                           (dim == 2 ? "plane quadrilateral"
                                     : "3-D hexahedral") +
                           " Gmsh mesh (" + one_line(info.str()) + ")");
      }
    for (unsigned int k = 0; k < parameters.curved_boundaries.size(); ++k)
      attach_curved_boundary(parameters.curved_boundaries[k], k, tria);
  }
} // namespace DuctileContact
