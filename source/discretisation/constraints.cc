#include <deal.II/numerics/vector_tools.h>

#include <ductile_contact/discretisation/constraints.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    std::map<types::global_dof_index, double>
    dirichlet_values(const Discretisation                &discretisation,
                     const std::deque<BoundaryCondition> &boundary_conditions,
                     const double                         t)
    {
      std::map<types::global_dof_index, double> values;
      for (const BoundaryCondition &bc : boundary_conditions)
        if (bc.has_dirichlet())
          {
            bc.displacement->set_time(t);
            VectorTools::interpolate_boundary_values(discretisation.mapping,
                                                     discretisation.dof_handler,
                                                     {{bc.boundary_id,
                                                       bc.displacement.get()}},
                                                     values,
                                                     bc.dirichlet_mask());
          }
      return values;
    }
  } // namespace



  void
  make_newton_constraints(
    const Discretisation                     &discretisation,
    const std::deque<BoundaryCondition>      &boundary_conditions,
    const double                              t,
    const TrilinosWrappers::MPI::BlockVector *u,
    AffineConstraints<double>                &constraints,
    const std::array<bool, Block::n_blocks>  &frozen)
  {
    constraints.clear();
    constraints.reinit(discretisation.locally_relevant_dofs);
    constraints.merge(discretisation.hanging_node_constraints);

    for (const auto &[dof, value] :
         dirichlet_values(discretisation, boundary_conditions, t))
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          if (u != nullptr)
            constraints.set_inhomogeneity(dof, value - (*u)(dof));
        }

    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      if (frozen[b])
        {
          types::global_dof_index offset = 0;
          for (unsigned int c = 0; c < b; ++c)
            offset += discretisation.dofs_per_block[c];
          for (const auto i : discretisation.relevant_partitioning[b])
            if (!constraints.is_constrained(offset + i))
              constraints.add_line(offset + i);
        }
    constraints.close();
  }
} // namespace DuctileContact
