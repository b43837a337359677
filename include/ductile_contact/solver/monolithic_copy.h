#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/discretisation/discretisation.h>

#include <Epetra_CrsMatrix.h>
#include <array>
#include <vector>

namespace DuctileContact
{
  /**
   * The coupled [u | alpha | s] tangent as one Trilinos matrix over the
   * global DoF indices (blocks numbered consecutively), with the vectors
   * over the same rows: what a direct solver factorises. The pattern is
   * built from the blocks' patterns once and kept while the tangent keeps
   * its own; each update copies only the values, entry by entry, into their
   * places in the flat rows.
   */
  class MonolithicCopy
  {
  public:
    explicit MonolithicCopy(const Discretisation &discretisation);

    /**
     * Makes #matrix the copy of @p K: the pattern is rebuilt if K is not
     * the tangent it was built from (another object or another number of
     * entries; collective: all ranks agree), the values are copied unless
     * @p same_matrix says they are those of the last copy. Returns whether
     * the pattern was kept.
     */
    bool
    update(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
           bool                                               same_matrix);

    /// #b from the block vector @p b and #x = 0.
    void
    set_right_hand_side(const dealii::TrilinosWrappers::MPI::BlockVector &b);

    /// #weights: w_I on the rows of block I.
    void
    set_weights(const std::vector<double> &block_weights);

    /// The block vector @p x from #x.
    void
    get_solution(dealii::TrilinosWrappers::MPI::BlockVector &x) const;

    /// Forgets the pattern (the DoFs changed).
    void
    reset();

    dealii::TrilinosWrappers::SparseMatrix matrix;
    dealii::TrilinosWrappers::MPI::Vector  x, b;
    /// Row weights (set_weights()).
    dealii::TrilinosWrappers::MPI::Vector weights;

  private:
    /// Builds the pattern and the copy positions from the blocks of @p K.
    void
    make_pattern(const dealii::TrilinosWrappers::BlockSparseMatrix &K);

    /// Copies the values of @p K's blocks into #matrix.
    void
    copy_values(const dealii::TrilinosWrappers::BlockSparseMatrix &K);

    const Discretisation &discretisation;

    /// Whether #matrix has a pattern.
    bool has_pattern = false;

    /// The block matrices the pattern was built from, and their number of
    /// local entries: a tangent re-created with another pattern is noticed.
    std::array<const Epetra_CrsMatrix *, 9> source{};
    std::array<int, 9>                      source_entries{};

    /// Local row of #matrix (and local index of x and b) for each local row
    /// of block row I.
    std::array<std::vector<int>, 3> row;

    /// For each local entry of block (I, J), in the order of its rows and
    /// of Epetra_CrsMatrix::ExtractMyRowView, the position in the row of
    /// #matrix that receives it. Blocks (I, J) are indexed 3 I + J.
    std::array<std::vector<int>, 9> position;
  };
} // namespace DuctileContact
