// Geometry of the necking bar (Mesh/Scene = round bar): the hull is the
// tapered surface r = f(x) R, f = 1 - e (1 - |2x/L - 1|), at every
// refinement level, and the cells are curved to the element degree. The
// mesh volume with the mapping the Discretisation picks (MappingQ(p) for a
// curved mesh) against the exact volume
//   V = pi R^2 L (1 + (1 - e) + (1 - e)^2) / 3
// must converge like h^(p+1) or faster; a faceted bar (MappingQ1, straight
// cells) is shown for contrast and does not come close. Every hull vertex
// must lie on the surface to round-off, every other boundary vertex on the
// plane its boundary id names to 1e-10 R (the transfinite interpolation
// inverts its chart iteratively: ~1e-12 R). The same for Model = octant (an
// eighth of the volume; ids 3, 4, 5 on the symmetry planes x = L/2, y = 0, z =
// 0). Identical on 1 and 2 MPI ranks.
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/mesh/scene.h>

#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const double R = 6.413e-3, L = 53.334e-3, e = 0.018;
  const double exact =
    M_PI * R * R * L * (1. + (1. - e) + (1. - e) * (1. - e)) / 3.;

  for (const std::string model : {"full", "octant"})
    {
      // The octant needs one refinement; its volume is an eighth.
      const unsigned int first        = model == "full" ? 0 : 1;
      const double       volume_exact = model == "full" ? exact : exact / 8.;
      out << "Model = " << model << "\n";
      double previous = 0.;
      for (unsigned int r = first; r < first + 3; ++r)
        {
          MeshParameters parameters;
          parameters.scene                        = SceneType::round_bar;
          parameters.round_bar.radius             = R;
          parameters.round_bar.length             = L;
          parameters.round_bar.imperfection       = e;
          parameters.round_bar.axial_subdivisions = 4;
          parameters.round_bar.refinements        = r;
          parameters.round_bar.model =
            from_name(round_bar_model_names(), model);
          parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
          create_scene_mesh(parameters, tria);

          const std::map<types::material_id, BodyFields> bodies{{0, {}}};
          const Discretisation discretisation(tria, 2, bodies);
          const auto          *mapping =
            dynamic_cast<const MappingQ<dim> *>(&discretisation.mapping[0]);
          AssertThrow(mapping != nullptr && mapping->get_degree() == 2,
                      ExcMessage("the round bar must get a MappingQ(2)"));

          const double volume  = GridTools::volume(tria, *mapping);
          const double faceted = GridTools::volume(tria, MappingQ<dim>(1));
          const double error   = std::abs(volume / volume_exact - 1.);

          // Largest distance of a hull vertex from the tapered surface, and
          // of a vertex of the other boundaries from their planes.
          double off_surface = 0., off_plane = 0.;
          for (const auto &cell : tria.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary())
                  for (const unsigned int v : face->vertex_indices())
                    {
                      const Point<dim> p = face->vertex(v);
                      const double     f =
                        1. - e * (1. - std::abs(2. * p[0] / L - 1.));
                      const double distance[] = {
                        std::abs(std::hypot(p[1], p[2]) - f * R) / R,
                        std::abs(p[0]) / R,
                        std::abs(p[0] - L) / R,
                        std::abs(p[0] - 0.5 * L) / R,
                        std::abs(p[1]) / R,
                        std::abs(p[2]) / R};
                      const unsigned int id = face->boundary_id();
                      AssertThrow(id <= 5, ExcMessage("unknown boundary id"));
                      (id == 0 ? off_surface : off_plane) =
                        std::max(id == 0 ? off_surface : off_plane,
                                 distance[id]);
                    }
          off_surface = Utilities::MPI::max(off_surface, MPI_COMM_WORLD);
          off_plane   = Utilities::MPI::max(off_plane, MPI_COMM_WORLD);

          const double rate =
            r > first ? std::log(previous / error) / std::log(2.) : 0.;
          out << "  refinements " << r << ": volume error with MappingQ(2) "
              << std::scientific << std::setprecision(1) << error
              << ", faceted (MappingQ1) "
              << std::abs(faceted / volume_exact - 1.) << std::fixed;
          if (r > first)
            out << ", rate " << std::setprecision(1) << rate;
          out << "\n    hull vertices on the hull to 1e-12 R, the others on "
                 "their planes to 1e-10 R: "
              << Testing::yes_no(off_surface < 1e-12 && off_plane < 1e-10)
              << "\n";
          AssertThrow(r == first || rate > 2.9,
                      ExcMessage("the volume must converge at least like h^3"));
          previous = error;
        }
      AssertThrow(previous < 1e-4, ExcMessage("volume error too large"));
    }
}
