#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>

#include <ductile_contact/core/input_error.h>
#include <ductile_contact/core/one_line.h>
#include <ductile_contact/mesh/scene.h>

#include <fstream>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

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
                         "it is not a readable 3-D hexahedral Gmsh mesh (" +
                           one_line(info.str()) + ")");
      }
  }
} // namespace DuctileContact
