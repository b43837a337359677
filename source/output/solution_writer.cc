#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <ductile_contact/output/solution_writer.h>

#include <fstream>

namespace DuctileContact
{
  using namespace dealii;

  SolutionWriter::SolutionWriter(
    const std::string                                          &directory,
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies)
      : directory(directory)
      , discretisation(discretisation)
      , bodies(bodies)
  {
  }



  void
  SolutionWriter::write(const unsigned int                        step,
                        const double                              time,
                        const TrilinosWrappers::MPI::BlockVector &u,
                        const CellQuantities                     &cells)
  {
    const auto   &tria = discretisation.triangulation;
    Vector<float> body(tria.n_active_cells()), rank(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          body[cell->active_cell_index()] = cell->material_id();
          rank[cell->active_cell_index()] = tria.locally_owned_subdomain();
        }

    DataOut<dim> data_out;
    data_out.attach_dof_handler(discretisation.dof_handler);
    std::vector<std::string> names(dim, "displacement");
    names.emplace_back("alpha");
    names.emplace_back("s");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    // DataOut cannot take a Trilinos block vector with empty blocks (a
    // scene without alpha or s): hand it one flat ghosted vector instead.
    // KNOWN BUG (open): with a non-empty alpha or s block on 2 ranks,
    // deal.II 9.4 hangs in the index-owner exchange (ComputeIndexOwner) that
    // DataOut sets up for this vector (also for a serial vector); u-only
    // scenes are fine. Coupled runs on several ranks need Interval = 0 until
    // this is fixed; see the notes of issues #3 and #4.
    TrilinosWrappers::MPI::Vector owned(discretisation.locally_owned_dofs,
                                        tria.get_communicator());
    for (const auto i : discretisation.locally_owned_dofs)
      owned[i] = u(i);
    owned.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector flat(discretisation.locally_owned_dofs,
                                       discretisation.locally_relevant_dofs,
                                       tria.get_communicator());
    flat = owned;
    data_out.add_data_vector(flat,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(cells.von_mises, "von_mises_kirchhoff");
    data_out.add_data_vector(cells.mean_stress, "mean_kirchhoff_stress");
    data_out.add_data_vector(cells.J, "J");
    if (discretisation.dofs_per_block[Block::phase_field] > 0)
      data_out.add_data_vector(cells.crack_driving_force,
                               "crack_driving_force");
    data_out.add_data_vector(body, "body");
    data_out.add_data_vector(rank, "mpi_rank");
    data_out.build_patches(discretisation.degree);

    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      directory + "/", "solution", step, tria.get_communicator(), 5);

    records.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(tria.get_communicator()) == 0)
      {
        std::ofstream pvd(directory + "/solution.pvd");
        DataOutBase::write_pvd_record(pvd, records);
      }
  }
} // namespace DuctileContact
