#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/assembly_data.h>

#include <cstdint>
#include <vector>

namespace DuctileContact
{
  /// A name for a newly built sparsity pattern (AssemblyTargets::pattern):
  /// never 0, never the same twice in a run.
  std::uint64_t
  new_pattern_id();

  /**
   * Where the entries of each cell's local matrix lie in the tangent's
   * rows, kept for one sparsity pattern (AssemblyTargets::pattern): the
   * first assembly with a pattern finds them (a binary search per entry),
   * every later one adds K(indices, indices) += matrix in place, one
   * addition per entry. add_unconstrained() (scatter.cc) instead walks the
   * whole matrix row (~375 entries for a quad9 displacement row) for the
   * 81 entries of a cell row: on prm/two_bodies.prm 4.9 % of all samples
   * of a run against 2.7 % now (the assembly 8.1 -> 7.9 s of 17 s). For
   * cells none of whose DoFs is constrained (scatter()); rows owned by
   * another rank go through Trilinos's non-local storage as before.
   * Memory: 4 bytes per local matrix entry (26 kB per quad9 displacement
   * cell, 73 kB with alpha and s).
   */
  class CellPositions
  {
  public:
    /// Keeps the positions if they were found for @p pattern, else forgets
    /// them; @p n_cells active cells.
    void
    use(const std::uint64_t pattern, const unsigned int n_cells);

    /// Forgets every cell's positions (the mesh changed).
    void
    clear();

    /// K(indices, indices) += @p matrix for the active cell @p cell.
    void
    add(const unsigned int                                  cell,
        const dealii::FullMatrix<double>                   &matrix,
        const std::vector<dealii::types::global_dof_index> &indices,
        dealii::TrilinosWrappers::BlockSparseMatrix        &K);

  private:
    struct Cell
    {
      /// The DoFs the positions were found for.
      std::vector<dealii::types::global_dof_index> dofs;
      /// Per row: its block, its local row in that block (-1: owned by
      /// another rank).
      std::vector<unsigned int> row_block;
      std::vector<int>          row;
      /// Per column: its block.
      std::vector<unsigned int> column_block;
      /// Per entry (row-major): its place in the Epetra row of the block
      /// (row block, column block), -1 outside the pattern.
      std::vector<int> position;
    };

    /// Fills @p c for the cell DoFs @p indices.
    static void
    find(Cell                                               &c,
         const std::vector<dealii::types::global_dof_index> &indices,
         dealii::TrilinosWrappers::BlockSparseMatrix        &K);

    std::uint64_t     pattern = 0;
    std::vector<Cell> cells;
  };

  /**
   * Adds one local contribution to every requested target: tangent and
   * Newton right-hand side -R (condensed with the Newton @p constraints),
   * the residual R = -@p rhs, and @p f_int condensed with the
   * @p hanging_nodes constraints only. Used by the
   * bulk assembly (cells and C0IP faces) and by contact. With
   * @p positions (kept for targets.pattern) the tangent entries of an
   * unconstrained local matrix go to the places kept for the active cell
   * @p cell.
   */
  void
  scatter(const dealii::FullMatrix<double>                   &matrix,
          const dealii::Vector<double>                       &rhs,
          const dealii::Vector<double>                       &f_int,
          const std::vector<dealii::types::global_dof_index> &indices,
          const dealii::AffineConstraints<double>            &constraints,
          const dealii::AffineConstraints<double>            &hanging_nodes,
          const AssemblyTargets                              &targets,
          CellPositions     *positions = nullptr,
          const unsigned int cell      = 0);

  /// K(rows, columns) += @p matrix (rows.size() x columns.size()) where
  /// none of the DoFs is constrained by @p constraints (then scatter()
  /// would add the same entries, and no right-hand side changes): a block
  /// of a few rows and many columns without the square local matrix.
  void
  scatter_matrix_block(
    const dealii::FullMatrix<double>                   &matrix,
    const std::vector<dealii::types::global_dof_index> &rows,
    const std::vector<dealii::types::global_dof_index> &columns,
    const dealii::AffineConstraints<double>            &constraints,
    dealii::TrilinosWrappers::BlockSparseMatrix        &tangent);

  /// Starts an assembly into @p targets: zeroes every matrix and vector it
  /// holds. The matrix is zeroed in place: deal.II's `K = 0` compresses
  /// first, which sends the whole non-local pattern across the ranks (all
  /// zeros after the compress() that ends every assembly): ~5 ms per tangent
  /// on prm/two_bodies.prm for nothing. An assembly that does not end with
  /// compress() ends the run (nothing catches an exception from it), so the
  /// non-local part is zero here.
  void
  zero(const AssemblyTargets &targets);

  /// Ends an assembly into @p targets: compresses (adds across ranks) every
  /// matrix and vector it holds. Used after the bulk and after the contact
  /// terms.
  void
  compress(const AssemblyTargets &targets);
} // namespace DuctileContact
