#include <deal.II/base/exceptions.h>

#include <ductile_contact/solver/block_preconditioner.h>

namespace DuctileContact
{
  using namespace dealii;

  BlockTriangularPreconditioner::BlockTriangularPreconditioner(
    const TrilinosWrappers::BlockSparseMatrix &K,
    const std::vector<BlockInverse>           &inverses)
      : K(K)
      , inverses(inverses)
      , rhs(inverses.size())
      , product(inverses.size())
  {
    AssertDimension(inverses.size(), K.n_block_rows());
    AssertDimension(inverses.size(), K.n_block_cols());
    // Work vectors with the row partition of each block, made once: the
    // preconditioner is applied once per Krylov iteration.
    for (unsigned int i = 0; i < inverses.size(); ++i)
      if (inverses[i])
        {
          const auto &A = K.block(i, i);
          rhs[i].reinit(A.locally_owned_range_indices(),
                        A.get_mpi_communicator());
          product[i].reinit(rhs[i], true);
        }
  }



  void
  BlockTriangularPreconditioner::vmult(
    TrilinosWrappers::MPI::BlockVector       &dst,
    const TrilinosWrappers::MPI::BlockVector &src) const
  {
    for (unsigned int i = 0; i < inverses.size(); ++i)
      {
        if (!inverses[i])
          continue;
        rhs[i] = src.block(i);
        for (unsigned int j = 0; j < i; ++j)
          if (inverses[j])
            {
              K.block(i, j).vmult(product[i], dst.block(j));
              rhs[i] -= product[i];
            }
        inverses[i](dst.block(i), rhs[i]);
      }
  }
} // namespace DuctileContact
