#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/scatter.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <atomic>
#include <string>
#include <utility>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// Whether any of @p indices is constrained.
    bool
    any_constrained(const std::vector<types::global_dof_index> &indices,
                    const AffineConstraints<double>            &constraints)
    {
      return std::any_of(indices.begin(),
                         indices.end(),
                         [&](const types::global_dof_index i) {
                           return constraints.is_constrained(i);
                         });
    }



    /**
     * K(rows, columns) += matrix for DoFs none of which is constrained.
     * AffineConstraints::distribute_local_to_global() passes every row to
     * Epetra, which looks up each entry's column in a hash table and
     * searches the row for it; here each DoF's local column index is looked
     * up once per block row, the local columns are sorted by it, and each
     * owned row is walked once alongside them (the Epetra rows are sorted
     * after FillComplete). Rows owned by another rank go through Trilinos's
     * non-local storage, as before; rows without an entry are skipped.
     * Every entry receives the same single addition as through
     * AffineConstraints.
     */
    void
    add_unconstrained(const FullMatrix<double>                   &matrix,
                      const std::vector<types::global_dof_index> &rows,
                      const std::vector<types::global_dof_index> &columns,
                      TrilinosWrappers::BlockSparseMatrix        &K)
    {
      using size_type              = TrilinosWrappers::SparseMatrix::size_type;
      const BlockIndices &blocks   = K.get_row_indices();
      const unsigned int  n_rows   = rows.size();
      const unsigned int  n_cols   = columns.size();
      const unsigned int  n_blocks = K.n_block_rows();
      // Work arrays kept between calls (one set per thread).
      thread_local std::vector<std::vector<unsigned int>> row_local, col_local;
      thread_local std::vector<int> row_in_block, col_in_block;
      thread_local std::vector<std::pair<int, unsigned int>> sorted;
      thread_local std::vector<size_type>                    nonlocal_columns;
      thread_local std::vector<double>                       nonlocal_values;
      // Per block: the positions in the local matrix of its DoFs, and each
      // DoF's index within its block.
      const auto sort_into_blocks =
        [&](const std::vector<types::global_dof_index> &dofs,
            std::vector<std::vector<unsigned int>>     &local,
            std::vector<int>                           &in_block) {
          local.resize(n_blocks);
          for (auto &l : local)
            l.clear();
          in_block.resize(dofs.size());
          for (unsigned int k = 0; k < dofs.size(); ++k)
            {
              const auto [b, i] = blocks.global_to_local(dofs[k]);
              local[b].push_back(k);
              in_block[k] = static_cast<int>(i);
            }
        };
      sort_into_blocks(rows, row_local, row_in_block);
      sort_into_blocks(columns, col_local, col_in_block);
      // Contact's local matrices are mostly rows without an entry.
      thread_local std::vector<bool> zero_row;
      zero_row.resize(n_rows);
      for (unsigned int r = 0; r < n_rows; ++r)
        zero_row[r] = std::all_of(&matrix(r, 0),
                                  &matrix(r, 0) + n_cols,
                                  [](const double v) { return v == 0.; });
      for (unsigned int I = 0; I < n_blocks; ++I)
        for (unsigned int J = 0; J < n_blocks && !row_local[I].empty(); ++J)
          {
            if (col_local[J].empty())
              continue;
            TrilinosWrappers::SparseMatrix &block = K.block(I, J);
            // deal.II hands out the Epetra matrix as const only; its values
            // are changed here through the row views, as
            // TrilinosWrappers::SparseMatrix::add() changes them.
            Epetra_CrsMatrix &A =
              const_cast<Epetra_CrsMatrix &>(block.trilinos_matrix());
            // FillComplete sorts each row's local column indices.
            AssertThrow(A.Filled(),
                        ExcMessage("The tangent's pattern is not final."));
            sorted.clear();
            for (const unsigned int k : col_local[J])
              sorted.emplace_back(A.LCID(col_in_block[k]), k);
            std::sort(sorted.begin(), sorted.end());
            for (const unsigned int r : row_local[I])
              {
                if (zero_row[r])
                  continue;
                const int row = A.LRID(row_in_block[r]);
                if (row < 0)
                  {
                    nonlocal_columns.clear();
                    nonlocal_values.clear();
                    for (const unsigned int k : col_local[J])
                      {
                        nonlocal_columns.push_back(col_in_block[k]);
                        nonlocal_values.push_back(matrix(r, k));
                      }
                    block.add(row_in_block[r],
                              nonlocal_columns.size(),
                              nonlocal_columns.data(),
                              nonlocal_values.data(),
                              true,
                              false);
                    continue;
                  }
                int     length;
                double *values;
                int    *entries;
                A.ExtractMyRowView(row, length, values, entries);
                Assert(std::is_sorted(entries, entries + length),
                       ExcInternalError());
                const int *position = entries;
                const int *end      = entries + length;
                for (const auto &[column, k] : sorted)
                  {
                    const double v = matrix(r, k);
                    // A linear walk: the cell's columns are a good part
                    // of the row, and a binary search per entry cost as
                    // much as Epetra's.
                    while (position != end && *position < column)
                      ++position;
                    if (column < 0 || position == end || *position != column)
                      {
                        // Outside the pattern: only a zero may be (local
                        // matrices hold zeros for couplings the pattern
                        // leaves out; AffineConstraints drops zeros too).
                        AssertThrow(v == 0.,
                                    ExcMessage("A tangent entry lies outside "
                                               "the sparsity pattern."));
                        continue;
                      }
                    values[position - entries] += v;
                  }
              }
          }
    }

    /// The Epetra matrix of block (I, J) of @p K, writable (deal.II hands
    /// it out as const only; its values are changed through row views, as
    /// TrilinosWrappers::SparseMatrix::add() changes them).
    Epetra_CrsMatrix &
    epetra_block(TrilinosWrappers::BlockSparseMatrix &K,
                 const unsigned int                   I,
                 const unsigned int                   J)
    {
      auto &A = const_cast<Epetra_CrsMatrix &>(K.block(I, J).trilinos_matrix());
      // FillComplete sorts each row's local column indices.
      AssertThrow(A.Filled(),
                  ExcMessage("The tangent's pattern is not final."));
      return A;
    }
  } // namespace



  std::uint64_t
  new_pattern_id()
  {
    static std::atomic<std::uint64_t> last{0};
    return ++last;
  }



  void
  CellPositions::use(const std::uint64_t pattern, const unsigned int n_cells)
  {
    if (pattern != this->pattern || cells.size() != n_cells)
      {
        cells.assign(n_cells, Cell());
        this->pattern = pattern;
      }
  }



  void
  CellPositions::clear()
  {
    cells.clear();
    pattern = 0;
  }



  void
  CellPositions::find(Cell                                       &c,
                      const std::vector<types::global_dof_index> &indices,
                      TrilinosWrappers::BlockSparseMatrix        &K)
  {
    const BlockIndices &blocks = K.get_row_indices();
    const unsigned int  n      = indices.size();
    c.dofs                     = indices;
    c.row_block.resize(n);
    c.row.resize(n);
    c.column_block.resize(n);
    c.position.assign(n * n, -1);
    std::vector<int> in_block(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto [b, i] = blocks.global_to_local(indices[k]);
        c.row_block[k]    = b;
        c.column_block[k] = b;
        in_block[k]       = static_cast<int>(i);
      }
    // Each column's local index in the column map of block (I, J), looked
    // up once per block row I (a hash search each).
    const unsigned int n_blocks = K.n_block_rows();
    std::vector<int>   column_id(n_blocks * n, -2);
    for (unsigned int r = 0; r < n; ++r)
      {
        const unsigned int I = c.row_block[r];
        c.row[r]             = epetra_block(K, I, 0).LRID(in_block[r]);
        if (c.row[r] < 0)
          continue;
        if (column_id[I * n] == -2)
          for (unsigned int k = 0; k < n; ++k)
            column_id[I * n + k] =
              epetra_block(K, I, c.column_block[k]).LCID(in_block[k]);
        for (unsigned int J = 0; J < n_blocks; ++J)
          {
            Epetra_CrsMatrix &A = epetra_block(K, I, J);
            // The blocks of a block row share its row map.
            AssertThrow(A.LRID(in_block[r]) == c.row[r], ExcInternalError());
            int     length;
            double *values;
            int    *entries;
            A.ExtractMyRowView(c.row[r], length, values, entries);
            for (unsigned int k = 0; k < n; ++k)
              {
                const int column = column_id[I * n + k];
                if (c.column_block[k] != J || column < 0)
                  continue;
                const int *p =
                  std::lower_bound(entries, entries + length, column);
                if (p != entries + length && *p == column)
                  c.position[r * n + k] = static_cast<int>(p - entries);
              }
          }
      }
  }



  void
  CellPositions::add(const unsigned int                          cell,
                     const FullMatrix<double>                   &matrix,
                     const std::vector<types::global_dof_index> &indices,
                     TrilinosWrappers::BlockSparseMatrix        &K)
  {
    AssertIndexRange(cell, cells.size());
    Cell &c = cells[cell];
    if (c.dofs != indices)
      find(c, indices, K);
#ifdef DEBUG
    {
      Cell fresh;
      find(fresh, indices, K);
      Assert(fresh.row == c.row && fresh.position == c.position,
             ExcMessage("The tangent's pattern changed under the same name "
                        "(AssemblyTargets::pattern)."));
    }
#endif
    const unsigned int                 n        = indices.size();
    const unsigned int                 n_blocks = K.n_block_cols();
    thread_local std::vector<double *> row_values;
    row_values.resize(n_blocks);
    for (unsigned int r = 0; r < n; ++r)
      {
        const unsigned int I = c.row_block[r];
        if (c.row[r] < 0)
          {
            // Owned by another rank: Trilinos's non-local storage.
            thread_local FullMatrix<double> one_row;
            one_row.reinit(1, n);
            for (unsigned int k = 0; k < n; ++k)
              one_row(0, k) = matrix(r, k);
            add_unconstrained(one_row, {indices[r]}, indices, K);
            continue;
          }
        for (unsigned int J = 0; J < n_blocks; ++J)
          {
            int  length;
            int *entries;
            epetra_block(K, I, J).ExtractMyRowView(c.row[r],
                                                   length,
                                                   row_values[J],
                                                   entries);
          }
        const double *m        = &matrix(r, 0);
        const int    *position = &c.position[r * n];
        for (unsigned int k = 0; k < n; ++k)
          if (position[k] >= 0)
            row_values[c.column_block[k]][position[k]] += m[k];
          else
            AssertThrow(m[k] == 0.,
                        ExcMessage("A tangent entry lies outside the "
                                   "sparsity pattern."));
      }
  }



  void
  scatter(const FullMatrix<double>                   &matrix,
          const Vector<double>                       &rhs,
          const Vector<double>                       &f_int,
          const std::vector<types::global_dof_index> &indices,
          const AffineConstraints<double>            &constraints,
          const AffineConstraints<double>            &hanging_nodes,
          const AssemblyTargets                      &targets,
          CellPositions                              *positions,
          const unsigned int                          cell)
  {
    if (targets.tangent && !any_constrained(indices, constraints))
      {
        if (positions)
          positions->add(cell, matrix, indices, *targets.tangent);
        else
          add_unconstrained(matrix, indices, indices, *targets.tangent);
        if (targets.newton_rhs)
          targets.newton_rhs->add(indices, rhs);
      }
    else if (targets.tangent)
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
  scatter_matrix_block(const FullMatrix<double>                   &matrix,
                       const std::vector<types::global_dof_index> &rows,
                       const std::vector<types::global_dof_index> &columns,
                       const AffineConstraints<double>            &constraints,
                       TrilinosWrappers::BlockSparseMatrix        &tangent)
  {
    Assert(!any_constrained(rows, constraints) &&
             !any_constrained(columns, constraints),
           ExcMessage("scatter_matrix_block() takes unconstrained DoFs only"));
    (void)constraints;
    add_unconstrained(matrix, rows, columns, tangent);
  }



  void
  zero(const AssemblyTargets &targets)
  {
    if (auto *K = targets.tangent)
      for (unsigned int i = 0; i < K->n_block_rows(); ++i)
        for (unsigned int j = 0; j < K->n_block_cols(); ++j)
          {
            // The values only (deal.II gives no writable access to the
            // Epetra matrix; its pattern stays as it is).
            auto &A =
              const_cast<Epetra_CrsMatrix &>(K->block(i, j).trilinos_matrix());
            const int ierr = A.PutScalar(0.);
            AssertThrow(ierr == 0,
                        ExcMessage("Epetra PutScalar failed: " +
                                   std::to_string(ierr)));
          }
    for (auto *v :
         {targets.newton_rhs, targets.residual, targets.internal_force})
      if (v)
        *v = 0;
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
