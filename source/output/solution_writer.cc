#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/la_parallel_block_vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/output/solution_writer.h>

#include <array>
#include <cmath>
#include <fstream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// @p v as DataOut needs it: a ghosted block vector of the non-empty
    /// blocks. DataOut needs, per vector block, one contiguous range of
    /// owned DoFs on each rank (deal.II 9.4 builds a partitioner from it
    /// and, given the several ranges of a component-wise numbered flat
    /// vector, hangs in the index-owner exchange on several ranks). Each of
    /// our blocks is contiguous per rank; empty blocks are dropped (DataOut
    /// splits by block size, and an empty block covers no DoF).
    LinearAlgebra::distributed::BlockVector<double>
    present_blocks(const TrilinosWrappers::MPI::BlockVector &v,
                   const Discretisation                     &discretisation)
    {
      LinearAlgebra::distributed::BlockVector<double> ghosted;
      std::vector<unsigned int>                       present;
      for (unsigned int b = 0; b < Block::n_blocks; ++b)
        if (discretisation.dofs_per_block[b] > 0)
          present.push_back(b);
      ghosted.reinit(present.size());
      for (unsigned int k = 0; k < present.size(); ++k)
        {
          const unsigned int b = present[k];
          ghosted.block(k).reinit(
            discretisation.owned_partitioning[b],
            discretisation.relevant_partitioning[b],
            discretisation.triangulation.get_communicator());
          for (const auto i : discretisation.owned_partitioning[b])
            ghosted.block(k)[i] = v.block(b)[i];
        }
      ghosted.collect_sizes();
      ghosted.update_ghost_values();
      return ghosted;
    }

    /// The displacement components of a vector of the [u | alpha | s]
    /// layout as one vector field (the velocity of a dynamic run).
    class DisplacementPart : public DataPostprocessorVector<dim>
    {
    public:
      explicit DisplacementPart(const std::string &name)
          : DataPostprocessorVector<dim>(name, update_values)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          for (unsigned int d = 0; d < dim; ++d)
            computed[q](d) = inputs.solution_values[q](d);
      }
    };

    /// ln(A) of a symmetric positive definite A, through its eigenvalues;
    /// zero for a cell without averages (A = 0).
    SymmetricTensor<2, material_dim>
    logarithm(const SymmetricTensor<2, material_dim> &A)
    {
      SymmetricTensor<2, material_dim> log_A;
      if (!(determinant(A) > 0.))
        return log_A;
      for (const auto &[value, vector] : eigenvectors(A))
        log_A += std::log(value) * symmetrize(outer_product(vector, vector));
      return log_A;
    }

    /// The names of the tensor fields of the output, in the order of
    /// tensor_fields().
    const std::array<std::string, 4> tensor_names = {
      {"kirchhoff_stress", "cauchy_stress", "log_strain", "plastic_strain"}};

    /// A cell's tensor fields: the averaged Kirchhoff and Cauchy stress
    /// [Pa], the logarithmic strain 1/2 ln(b) and the plastic strain
    /// 1/2 ln(C^p) of the averaged b and C^p.
    std::array<SymmetricTensor<2, material_dim>, 4>
    tensor_fields(const CellQuantities &cells, const unsigned int i)
    {
      return {{cells.kirchhoff[i],
               cells.cauchy[i],
               0.5 * logarithm(cells.b[i]),
               0.5 * logarithm(cells.Cp[i])}};
    }
  } // namespace

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
                        const CellQuantities                     &cells,
                        const TrilinosWrappers::MPI::BlockVector *velocity)
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
    const LinearAlgebra::distributed::BlockVector<double> ghosted =
      present_blocks(u, discretisation);
    data_out.add_data_vector(ghosted,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    LinearAlgebra::distributed::BlockVector<double> velocity_data;
    const DisplacementPart                          velocity_field("velocity");
    if (velocity)
      {
        velocity_data = present_blocks(*velocity, discretisation);
        data_out.add_data_vector(velocity_data, velocity_field);
      }
    data_out.add_data_vector(cells.von_mises, "von_mises_kirchhoff");
    data_out.add_data_vector(cells.mean_stress, "mean_kirchhoff_stress");
    data_out.add_data_vector(cells.J, "J");
    if (discretisation.dofs_per_block[Block::phase_field] > 0)
      data_out.add_data_vector(cells.crack_driving_force,
                               "crack_driving_force");
    data_out.add_data_vector(body, "body");
    data_out.add_data_vector(rank, "mpi_rank");

    // The tensor fields (3 x 3 in plane strain too) as piecewise constant
    // (DG0) fields: in 3-D vtu as tensors (ParaView shows each as one); in
    // HDF5, whose writer keeps three components of a non-scalar field, and
    // in 2-D, where a tensor of the output has 2 x 2 components, as the six
    // scalars NAME_xx, NAME_yy, NAME_zz, NAME_xy, NAME_xz, NAME_yz; the
    // stress triaxiality sigma_m / sigma_eq of the averaged Cauchy stress
    // as cell data.
    const bool as_tensor = format == OutputFormat::vtu && dim == material_dim;
    const unsigned int n_per =
      as_tensor ? material_dim * material_dim
                : SymmetricTensor<2, material_dim>::n_independent_components;
    const unsigned int n_tensor = tensor_names.size() * n_per;
    FESystem<dim>      fe_tensor(FE_DGQ<dim>(0), n_tensor);
    DoFHandler<dim>    tensor_dofs(tria);
    tensor_dofs.distribute_dofs(fe_tensor);
    LinearAlgebra::distributed::Vector<double> tensors(
      tensor_dofs.locally_owned_dofs(),
      DoFTools::extract_locally_relevant_dofs(tensor_dofs),
      tria.get_communicator());
    Vector<float>                        triaxiality(tria.n_active_cells());
    std::vector<types::global_dof_index> indices(n_tensor);
    for (const auto &cell : tensor_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int i = cell->active_cell_index();
          cell->get_dof_indices(indices);
          const auto fields = tensor_fields(cells, i);
          for (unsigned int k = 0; k < fields.size(); ++k)
            for (unsigned int c = 0; c < n_per; ++c)
              tensors[indices[k * n_per + c]] =
                as_tensor ? fields[k][c / material_dim][c % material_dim]
                          : fields[k].access_raw_entry(c);
          const double equivalent = von_mises(cells.cauchy[i]);
          triaxiality[i] =
            equivalent > 0. ? trace(cells.cauchy[i]) / 3. / equivalent : 0.;
        }
    tensors.update_ghost_values();
    std::vector<std::string> tensor_component_names;
    const char              *xyz = "xyz";
    for (const std::string &name : tensor_names)
      for (unsigned int c = 0; c < n_per; ++c)
        {
          const auto ab =
            SymmetricTensor<2, material_dim>::unrolled_to_component_indices(c);
          tensor_component_names.push_back(
            as_tensor ? name : name + "_" + xyz[ab[0]] + xyz[ab[1]]);
        }
    data_out.add_data_vector(
      tensor_dofs,
      tensors,
      tensor_component_names,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        n_tensor,
        as_tensor ? DataComponentInterpretation::component_is_part_of_tensor
                  : DataComponentInterpretation::component_is_scalar));
    data_out.add_data_vector(triaxiality, "triaxiality");
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
