#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <vector>

namespace DuctileContact
{
  /**
   * Block lower-triangular (block Gauss-Seidel) preconditioner of the coupled
   * tangent K = [K_ij] on the blocks [u | alpha | s]:
   *
   *   P = [ A_uu    0     0   ]      y_i = A_ii^{-1} (r_i - sum_{j<i} K_ij y_j)
   *       [ K_au  A_aa    0   ]
   *       [ K_su  K_sa  A_ss  ]
   *
   * applied by forward substitution, where A_ii^{-1} is an approximate
   * inverse of the diagonal block K_ii (one AMG V-cycle, or a sparse LU)
   * given by the caller. The off-diagonal blocks are those of K, so P is
   * exact in the block-triangular part and ignores only the upper blocks
   * K_ij, j > i. It is a fixed linear operator when the A_ii^{-1} are, as
   * GMRES requires. Blocks without an inverse (empty blocks) are skipped.
   *
   * Holds references to K and to whatever the inverses capture: both must
   * outlive it.
   */
  class BlockTriangularPreconditioner
  {
  public:
    /// y = A_ii^{-1} r for one diagonal block.
    using BlockInverse =
      std::function<void(dealii::TrilinosWrappers::MPI::Vector       &y,
                         const dealii::TrilinosWrappers::MPI::Vector &r)>;

    /**
     * @p inverses has one entry per block of @p K; an empty std::function
     * marks a block without unknowns.
     */
    BlockTriangularPreconditioner(
      const dealii::TrilinosWrappers::BlockSparseMatrix &K,
      const std::vector<BlockInverse>                   &inverses);

    /// dst = P^{-1} src.
    void
    vmult(dealii::TrilinosWrappers::MPI::BlockVector       &dst,
          const dealii::TrilinosWrappers::MPI::BlockVector &src) const;

  private:
    const dealii::TrilinosWrappers::BlockSparseMatrix &K;
    const std::vector<BlockInverse>                    inverses;

    /// Right-hand side r_i - sum_{j<i} K_ij y_j and one product, per block.
    mutable std::vector<dealii::TrilinosWrappers::MPI::Vector> rhs, product;
  };
} // namespace DuctileContact
