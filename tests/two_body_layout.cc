// The two-body scene of model.md section 7 and the [u | alpha | s] layout:
//  - plate and block are disconnected (no shared vertex), with the material
//    and boundary ids documented in MeshParameters (areas per id checked);
//  - with alpha and s on the plate only, the DoFs per block equal the
//    closed-form node counts of Q2 (u on both bodies, alpha and s on the
//    plate), and block cells carry FE_Nothing for alpha and s.
// Identical on 1 and 2 MPI ranks.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/mesh/scene.h>

#include "tests.h"

#include <set>

using namespace dealii;
using namespace DuctileContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  std::ofstream                    out  = Testing::open_output();

  MeshParameters mesh;
  mesh.scene = SceneType::two_bodies;
  parallel::distributed::Triangulation<dim> tria(comm);
  create_scene_mesh(mesh, tria);

  // Disconnected bodies: no vertex used by cells of both.
  std::set<unsigned int> plate_vertices, shared;
  for (const auto &cell : tria.cell_iterators_on_level(0))
    if (cell->material_id() == 0)
      for (const unsigned int v : cell->vertex_indices())
        plate_vertices.insert(cell->vertex_index(v));
  for (const auto &cell : tria.cell_iterators_on_level(0))
    if (cell->material_id() == 1)
      for (const unsigned int v : cell->vertex_indices())
        if (plate_vertices.count(cell->vertex_index(v)))
          shared.insert(cell->vertex_index(v));
  out << "coarse cells: " << tria.n_global_active_cells()
      << ", vertices shared by plate and block: " << shared.size() << std::endl;

  // Area of each boundary id.
  std::map<unsigned int, double> area;
  MappingQ<dim>                  mapping(1);
  QGauss<dim - 1>                q(2);
  FE_Q<dim>                      fe(1);
  FEFaceValues<dim>              fv(mapping, fe, q, update_JxW_values);
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            fv.reinit(cell, f);
            for (unsigned int k = 0; k < q.size(); ++k)
              area[cell->face(f)->boundary_id()] += fv.JxW(k);
          }
  const double expected[6] = {0.076, 0.004, 0.0016, 0.06, 0.0016, 0.0064};
  bool         areas_ok    = true;
  for (unsigned int id = 0; id < 6; ++id)
    {
      const double a = Utilities::MPI::sum(area[id], comm);
      areas_ok       = areas_ok && std::abs(a - expected[id]) < 1e-12;
      out << "boundary " << id << " area [cm^2] = " << a * 1e4 << std::endl;
    }
  out << "boundary areas as documented: " << Testing::yes_no(areas_ok)
      << std::endl;

  // Layout: alpha and s on the plate (material 0) only.
  Discretisation d(
    tria, 2, {{0, BodyFields{true, true}}, {1, BodyFields{false, false}}});
  d.setup();
  const types::global_dof_index plate_nodes = 39 * 27 * 5;
  const types::global_dof_index block_nodes = 11 * 11 * 11;
  out << "DoFs u, alpha, s: " << d.dofs_per_block[0] << ", "
      << d.dofs_per_block[1] << ", " << d.dofs_per_block[2] << std::endl;
  const bool counts_ok =
    d.dofs_per_block[0] == 3 * (plate_nodes + block_nodes) &&
    d.dofs_per_block[1] == plate_nodes && d.dofs_per_block[2] == plate_nodes;
  bool fe_ok = true;
  for (const auto &cell : d.dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      fe_ok = fe_ok && cell->get_fe().n_dofs_per_cell() ==
                         (cell->material_id() == 0 ? 5u * 27u : 3u * 27u);
  fe_ok = Utilities::MPI::min(fe_ok ? 1 : 0, comm) == 1;
  out << "block counts equal the Q2 node counts: " << Testing::yes_no(counts_ok)
      << std::endl;
  out << "FE_Nothing for alpha and s on the block: " << Testing::yes_no(fe_ok)
      << std::endl;
}
