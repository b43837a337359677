#include <deal.II/base/mpi.h>
#include <deal.II/numerics/vector_tools.h>

#include <ductile_contact/discretisation/constraints.h>

#include <cmath>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The prescribed values at time @p t; @p fault names the first
    /// boundary condition with a value that is not finite.
    std::map<types::global_dof_index, double>
    dirichlet_values(const Discretisation                &discretisation,
                     const std::deque<BoundaryCondition> &boundary_conditions,
                     const double                         t,
                     std::string                         &fault)
    {
      std::map<types::global_dof_index, double> values;
      for (const BoundaryCondition &bc : boundary_conditions)
        if (bc.has_dirichlet())
          {
            bc.displacement->set_time(t);
            std::map<types::global_dof_index, double> these;
            VectorTools::interpolate_boundary_values(discretisation.mapping,
                                                     discretisation.dof_handler,
                                                     {{bc.boundary_id,
                                                       bc.displacement.get()}},
                                                     these,
                                                     bc.dirichlet_mask());
            for (auto &[dof, value] : these)
              if (!std::isfinite(value))
                {
                  if (fault.empty())
                    {
                      std::ostringstream s;
                      s << "the prescribed displacement of '" << bc.subsection()
                        << "' is " << (std::isnan(value) ? "NaN" : "Inf")
                        << " at t = " << t;
                      fault = s.str();
                    }
                  value = 0.;
                }
            // A later condition overrides an earlier one on shared DoFs, as
            // when interpolate_boundary_values fills one map.
            for (const auto &[dof, value] : these)
              values[dof] = value;
          }
      return values;
    }
  } // namespace



  std::string
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

    std::string fault;
    const auto  values =
      dirichlet_values(discretisation, boundary_conditions, t, fault);
    for (const auto &[dof, value] : values)
      if (!constraints.is_constrained(dof))
        {
          constraints.add_line(dof);
          if (u != nullptr && fault.empty())
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
    // Every rank knows: the DoFs with the fault may be on one only.
    const MPI_Comm     comm = discretisation.dof_handler.get_communicator();
    const unsigned int first =
      Utilities::MPI::min(fault.empty()
                            ? numbers::invalid_unsigned_int
                            : Utilities::MPI::this_mpi_process(comm),
                          comm);
    return first == numbers::invalid_unsigned_int
             ? std::string()
             : Utilities::MPI::broadcast(comm, fault, first);
  }
} // namespace DuctileContact
