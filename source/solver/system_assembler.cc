#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/physics/elasticity/standard_tensors.h>

#include <ductile_contact/materials/neo_hooke.h>
#include <ductile_contact/solver/system_assembler.h>

namespace DuctileContact
{
  using namespace dealii;

  SystemAssembler::SystemAssembler(
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies,
    const std::deque<BoundaryCondition> &boundary_conditions)
      : discretisation(discretisation)
      , bodies(bodies)
      , boundary_conditions(boundary_conditions)
  {
  }



  AssemblyInfo
  SystemAssembler::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                            const double                              t,
                            const AffineConstraints<double> &constraints,
                            const AssemblyTargets           &targets) const
  {
    const bool with_tangent = (targets.tangent != nullptr);
    if (targets.tangent)
      *targets.tangent = 0;
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        *v = 0;

    // Traction boundaries, looked up per face.
    std::map<types::boundary_id, const BoundaryCondition *> tractions;
    for (const BoundaryCondition &bc : boundary_conditions)
      if (bc.has_traction)
        tractions[bc.boundary_id] = &bc;

    hp::FEValues<dim>     hp_fe_values(discretisation.mapping,
                                   discretisation.fe_collection,
                                   discretisation.quadrature,
                                   update_gradients | update_JxW_values);
    hp::FEFaceValues<dim> hp_face_values(discretisation.mapping,
                                         discretisation.fe_collection,
                                         discretisation.face_quadrature,
                                         update_values |
                                           update_quadrature_points |
                                           update_JxW_values);

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_f_int, cell_rhs, cell_magnitude;
    std::vector<types::global_dof_index> dof_indices;
    std::vector<Tensor<2, dim>>          grad_u;
    std::vector<unsigned int>            u_dofs, u_component;
    std::vector<Tensor<1, dim>>          shape_grad;
    std::vector<Tensor<2, dim>>          grad_times_A; // w_i[c][D]

    AssemblyInfo info;
    info.min_J = std::numeric_limits<double>::max();

    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_fe_values.get_present_fe_values();
          const FiniteElement<dim> &fe   = cell->get_fe();
          const unsigned int        n_dofs = fe.n_dofs_per_cell();
          const unsigned int        n_q    = fe_values.n_quadrature_points;
          const BodyParameters     &body   = *bodies.at(cell->material_id());

          cell_matrix.reinit(n_dofs, n_dofs);
          cell_f_int.reinit(n_dofs);
          cell_magnitude.reinit(n_dofs);
          cell_rhs.reinit(n_dofs);
          dof_indices.resize(n_dofs);
          cell->get_dof_indices(dof_indices);

          u_dofs.clear();
          u_component.clear();
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c < dim)
                {
                  u_dofs.push_back(i);
                  u_component.push_back(c);
                }
            }
          const unsigned int n_u = u_dofs.size();
          shape_grad.resize(n_u);
          grad_times_A.resize(n_u);

          grad_u.resize(n_q);
          fe_values[discretisation.displacement].get_function_gradients(u,
                                                                        grad_u);

          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Tensor<2, dim> F =
                Physics::Elasticity::StandardTensors<dim>::I + grad_u[q];
              const double J = determinant(F);
              info.min_J     = std::min(info.min_J, J);
              if (!(J > 0.))
                {
                  info.inverted = true;
                  continue;
                }
              const MaterialResponse m   = neo_hooke(F,
                                                   body.shear_modulus,
                                                   body.bulk_modulus,
                                                   with_tangent);
              const double           JxW = fe_values.JxW(q);
              info.stored_energy += m.psi * JxW;

              for (unsigned int k = 0; k < n_u; ++k)
                {
                  shape_grad[k]       = fe_values.shape_grad(u_dofs[k], q);
                  const unsigned a    = u_component[k];
                  const double   term = (m.P[a] * shape_grad[k]) * JxW;
                  cell_f_int(u_dofs[k]) += term;
                  // F = I + Grad u holds Grad u to eps in absolute terms,
                  // so P carries errors of eps times the moduli.
                  cell_magnitude(u_dofs[k]) +=
                    (std::abs(term) + (body.shear_modulus + body.bulk_modulus) *
                                        shape_grad[k].norm() * JxW);
                  if (with_tangent)
                    for (unsigned int c = 0; c < dim; ++c)
                      for (unsigned int D = 0; D < dim; ++D)
                        {
                          double sum = 0;
                          for (unsigned int B = 0; B < dim; ++B)
                            sum += shape_grad[k][B] * m.A[a][B][c][D];
                          grad_times_A[k][c][D] = sum * JxW;
                        }
                }
              if (with_tangent)
                for (unsigned int k = 0; k < n_u; ++k)
                  for (unsigned int l = 0; l < n_u; ++l)
                    cell_matrix(u_dofs[k], u_dofs[l]) +=
                      grad_times_A[k][u_component[l]] * shape_grad[l];
            }

          info.force_magnitude += cell_magnitude.norm_sqr();

          // R = f_int - f_ext; the Newton right-hand side is -R.
          for (unsigned int i = 0; i < n_dofs; ++i)
            cell_rhs(i) = -cell_f_int(i);

          if (!tractions.empty())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                {
                  const auto it = tractions.find(cell->face(f)->boundary_id());
                  if (it == tractions.end())
                    continue;
                  hp_face_values.reinit(cell, f);
                  const FEFaceValues<dim> &fv =
                    hp_face_values.get_present_fe_values();
                  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                    {
                      const Tensor<1, dim> T =
                        it->second->traction_at(fv.quadrature_point(q), t);
                      for (unsigned int k = 0; k < n_u; ++k)
                        cell_rhs(u_dofs[k]) += fv.shape_value(u_dofs[k], q) *
                                               T[u_component[k]] * fv.JxW(q);
                    }
                }

          if (with_tangent)
            constraints.distribute_local_to_global(cell_matrix,
                                                   cell_rhs,
                                                   dof_indices,
                                                   *targets.tangent,
                                                   *targets.newton_rhs);
          else if (targets.newton_rhs)
            constraints.distribute_local_to_global(cell_rhs,
                                                   dof_indices,
                                                   *targets.newton_rhs);
          if (targets.residual)
            {
              cell_rhs *= -1.;
              constraints.distribute_local_to_global(cell_rhs,
                                                     dof_indices,
                                                     *targets.residual);
            }
          // Condensed with the hanging-node constraints only: then the sum
          // of f_int over the DoFs of a boundary is the force through it
          // even where the boundary carries hanging nodes.
          if (targets.internal_force)
            discretisation.hanging_node_constraints.distribute_local_to_global(
              cell_f_int, dof_indices, *targets.internal_force);
        }

    if (targets.tangent)
      targets.tangent->compress(VectorOperation::add);
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        v->compress(VectorOperation::add);

    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    info.inverted       = Utilities::MPI::max(info.inverted ? 1 : 0, comm) > 0;
    info.min_J          = Utilities::MPI::min(info.min_J, comm);
    info.stored_energy  = Utilities::MPI::sum(info.stored_energy, comm);
    info.force_magnitude =
      std::sqrt(Utilities::MPI::sum(info.force_magnitude, comm));
    return info;
  }
} // namespace DuctileContact
