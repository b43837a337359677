#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <ductile_contact/materials/neo_hooke.h>
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
                        const TrilinosWrappers::MPI::BlockVector &u)
  {
    const auto   &tria = discretisation.triangulation;
    Vector<float> equivalent_stress(tria.n_active_cells()),
      mean_stress(tria.n_active_cells()), jacobian(tria.n_active_cells()),
      body(tria.n_active_cells()), rank(tria.n_active_cells());

    hp::FEValues<dim>           hp_fe_values(discretisation.mapping,
                                   discretisation.fe_collection,
                                   discretisation.quadrature,
                                   update_gradients | update_JxW_values);
    std::vector<Tensor<2, dim>> grad_u;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_fe_values.get_present_fe_values();
          const BodyParameters &b        = *bodies.at(cell->material_id());
          grad_u.resize(fe_values.n_quadrature_points);
          fe_values[discretisation.displacement].get_function_gradients(u,
                                                                        grad_u);
          double volume = 0, vm = 0, p = 0, J = 0;
          for (unsigned int q = 0; q < grad_u.size(); ++q)
            {
              const Tensor<2, dim> F =
                Physics::Elasticity::StandardTensors<dim>::I + grad_u[q];
              const MaterialResponse m =
                neo_hooke(F, b.shear_modulus, b.bulk_modulus, false);
              const double JxW = fe_values.JxW(q);
              volume += JxW;
              vm += von_mises(m.tau) * JxW;
              p += trace(m.tau) / 3. * JxW;
              J += m.J * JxW;
            }
          const auto i         = cell->active_cell_index();
          equivalent_stress[i] = vm / volume;
          mean_stress[i]       = p / volume;
          jacobian[i]          = J / volume;
          body[i]              = cell->material_id();
          rank[i]              = tria.locally_owned_subdomain();
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
    data_out.add_data_vector(equivalent_stress, "von_mises_kirchhoff");
    data_out.add_data_vector(mean_stress, "mean_kirchhoff_stress");
    data_out.add_data_vector(jacobian, "J");
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
