#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/la_parallel_block_vector.h>
#include <deal.II/numerics/data_out.h>

#include <ductile_contact/output/solution_writer.h>

#include <fstream>

namespace DuctileContact
{
  using namespace dealii;

  SolutionWriter::SolutionWriter(
    const std::string                                          &directory,
    const OutputFormat                                          format,
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies)
      : directory(directory)
      , format(format)
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
    // DataOut needs, per vector block, one contiguous range of owned DoFs on
    // each rank (deal.II 9.4 builds a partitioner from it and, given the
    // several ranges of a component-wise numbered flat vector, hangs in the
    // index-owner exchange on several ranks). Each of our blocks is
    // contiguous per rank, so hand it a ghosted block vector of the
    // non-empty blocks (empty blocks are dropped: DataOut splits by block
    // size, and an empty block covers no DoF).
    LinearAlgebra::distributed::BlockVector<double> ghosted;
    std::vector<unsigned int>                       present;
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      if (discretisation.dofs_per_block[b] > 0)
        present.push_back(b);
    ghosted.reinit(present.size());
    for (unsigned int k = 0; k < present.size(); ++k)
      {
        const unsigned int b = present[k];
        ghosted.block(k).reinit(discretisation.owned_partitioning[b],
                                discretisation.relevant_partitioning[b],
                                tria.get_communicator());
        for (const auto i : discretisation.owned_partitioning[b])
          ghosted.block(k)[i] = u.block(b)[i];
      }
    ghosted.collect_sizes();
    ghosted.update_ghost_values();
    data_out.add_data_vector(ghosted,
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

    const MPI_Comm comm = tria.get_communicator();
    if (format == OutputFormat::vtu)
      {
        const std::string pvtu = data_out.write_vtu_with_pvtu_record(
          directory + "/", "solution", step, comm, 5);
        records.emplace_back(time, pvtu);
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::ofstream pvd(directory + "/solution.pvd");
            DataOutBase::write_pvd_record(pvd, records);
          }
        return;
      }

    // hdf5: no merging of nodes with equal coordinates (bodies in contact
    // would be glued), the mesh only when it is new; names in the .xdmf
    // are relative to it.
    DataOutBase::DataOutFilter filter(
      DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices=*/false,
                                      /*xdmf_hdf5_output=*/true));
    data_out.write_filtered_data(filter);
    const bool        new_mesh = mesh_file.empty();
    const std::string solution_file =
      "solution_" + Utilities::int_to_string(step, 5) + ".h5";
    if (new_mesh)
      mesh_file = "mesh_" + Utilities::int_to_string(step, 5) + ".h5";
    data_out.write_hdf5_parallel(filter,
                                 new_mesh,
                                 directory + "/" + mesh_file,
                                 directory + "/" + solution_file,
                                 comm);
    xdmf_entries.push_back(
      data_out.create_xdmf_entry(filter, mesh_file, solution_file, time, comm));
    data_out.write_xdmf_file(xdmf_entries, directory + "/solution.xdmf", comm);
  }



  void
  SolutionWriter::mesh_changed()
  {
    mesh_file.clear();
  }
} // namespace DuctileContact
