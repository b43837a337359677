#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/scatter.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  scatter(const FullMatrix<double>                   &matrix,
          const Vector<double>                       &rhs,
          const Vector<double>                       &f_int,
          const std::vector<types::global_dof_index> &indices,
          const AffineConstraints<double>            &constraints,
          const AffineConstraints<double>            &hanging_nodes,
          const AssemblyTargets                      &targets)
  {
    if (targets.tangent)
      constraints.distribute_local_to_global(
        matrix, rhs, indices, *targets.tangent, *targets.newton_rhs);
    else if (targets.newton_rhs)
      constraints.distribute_local_to_global(rhs, indices, *targets.newton_rhs);
    if (targets.residual)
      {
        dealii::Vector<double> r = rhs;
        r *= -1.;
        constraints.distribute_local_to_global(r, indices, *targets.residual);
      }
    // Condensed with the hanging-node constraints only: then the sum of
    // f_int over the DoFs of a boundary is the force through it even
    // where the boundary carries hanging nodes.
    if (targets.internal_force)
      hanging_nodes.distribute_local_to_global(f_int,
                                               indices,
                                               *targets.internal_force);
  }



  void
  compress(const AssemblyTargets &targets)
  {
    if (targets.tangent)
      targets.tangent->compress(VectorOperation::add);
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        v->compress(VectorOperation::add);
  }
} // namespace DuctileContact
