// MonolithicCopy: the coupled block tangent copied into one Trilinos
// matrix over the global DoF indices, its pattern built once per tangent
// pattern and its values copied in place.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/exceptions.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <ductile_contact/solver/monolithic_copy.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <utility>

namespace DuctileContact
{
  using namespace dealii;



  MonolithicCopy::MonolithicCopy(const Discretisation &discretisation)
      : discretisation(discretisation)
  {
  }



  void
  MonolithicCopy::reset()
  {
    has_pattern = false;
    source.fill(nullptr);
    source_entries.fill(0);
  }



  bool
  MonolithicCopy::update(const TrilinosWrappers::BlockSparseMatrix &K,
                         const bool                                 same_matrix)
  {
    const unsigned int n_blocks = Block::n_blocks;

    // The pattern is reused while the tangent keeps its own; a tangent
    // re-created after setup() with another pattern is rebuilt here. All
    // ranks must agree: building the pattern is collective.
    bool same = has_pattern;
    for (unsigned int i = 0; same && i < n_blocks * n_blocks; ++i)
      {
        const Epetra_CrsMatrix &A =
          K.block(i / n_blocks, i % n_blocks).trilinos_matrix();
        same = (source[i] == &A && source_entries[i] == A.NumMyNonzeros());
      }
    same =
      Utilities::MPI::min(same ? 1 : 0,
                          discretisation.dof_handler.get_communicator()) == 1;
    if (!same)
      make_pattern(K);
    // Not again for the matrix of the last copy.
    if (!(same_matrix && same))
      copy_values(K);
    return same;
  }



  void
  MonolithicCopy::copy_values(const TrilinosWrappers::BlockSparseMatrix &K)
  {
    // Each block entry into its place in the flat row (a view of the
    // Epetra storage; the pattern is fixed, so no compress is needed).
    // Every entry of the flat pattern comes from one block entry.
    const unsigned int      n_blocks = Block::n_blocks;
    const Epetra_CrsMatrix &flat     = matrix.trilinos_matrix();
    for (unsigned int I = 0; I < n_blocks; ++I)
      for (unsigned int J = 0; J < n_blocks; ++J)
        {
          const Epetra_CrsMatrix &A = K.block(I, J).trilinos_matrix();
          const int              *p = position[n_blocks * I + J].data();
          for (int r = 0; r < A.NumMyRows(); ++r)
            {
              int     n, fn;
              double *values, *fvalues;
              int    *indices, *findices;
              A.ExtractMyRowView(r, n, values, indices);
              flat.ExtractMyRowView(row[I][r], fn, fvalues, findices);
              for (int k = 0; k < n; ++k)
                fvalues[*p++] = values[k];
            }
        }
  }



  void
  MonolithicCopy::set_right_hand_side(
    const TrilinosWrappers::MPI::BlockVector &block_b)
  {
    // Block vectors <-> flat vectors: same owned DoFs, same local order per
    // block as the block matrix rows.
    double *flat_b = b.trilinos_vector()[0];
    for (unsigned int I = 0; I < Block::n_blocks; ++I)
      {
        const Epetra_MultiVector &bI = block_b.block(I).trilinos_vector();
        AssertDimension(static_cast<std::size_t>(bI.MyLength()), row[I].size());
        for (int r = 0; r < bI.MyLength(); ++r)
          flat_b[row[I][r]] = bI[0][r];
      }
    x = 0.;
  }



  void
  MonolithicCopy::set_weights(const std::vector<double> &block_weights)
  {
    weights.reinit(b, true);
    double *flat_w = weights.trilinos_vector()[0];
    for (unsigned int I = 0; I < Block::n_blocks; ++I)
      for (const int r : row[I])
        flat_w[r] = block_weights[I];
  }



  void
  MonolithicCopy::get_solution(
    TrilinosWrappers::MPI::BlockVector &block_x) const
  {
    const double *flat_x = x.trilinos_vector()[0];
    for (unsigned int I = 0; I < Block::n_blocks; ++I)
      {
        Epetra_MultiVector &xI = block_x.block(I).trilinos_vector();
        AssertDimension(static_cast<std::size_t>(xI.MyLength()), row[I].size());
        for (int r = 0; r < xI.MyLength(); ++r)
          xI[0][r] = flat_x[row[I][r]];
      }
  }



  void
  MonolithicCopy::make_pattern(const TrilinosWrappers::BlockSparseMatrix &K)
  {
    const MPI_Comm     comm     = discretisation.dof_handler.get_communicator();
    const IndexSet    &owned    = discretisation.locally_owned_dofs;
    const unsigned int n_blocks = Block::n_blocks;
    AssertThrow(K.n_block_rows() == n_blocks && K.n_block_cols() == n_blocks,
                ExcMessage("The tangent must have 3 x 3 blocks."));

    // Blocks are numbered consecutively: global = offset + block index.
    std::array<types::global_dof_index, Block::n_blocks> offset{};
    for (unsigned int I = 1; I < n_blocks; ++I)
      offset[I] = offset[I - 1] + discretisation.dofs_per_block[I - 1];

    for (auto &p : position)
      p.clear();

    // The graph is built in Epetra: the owned DoFs of a rank are not
    // contiguous (one range per block), which the row-length constructors
    // of TrilinosWrappers::SparsityPattern do not support (they index row
    // lengths by global row from the first owned one). Exact local row
    // lengths (the sum over the block row): allocated once.
    using int_type           = TrilinosWrappers::types::int_type;
    const Epetra_Map map     = owned.make_trilinos_map(comm, false);
    const auto       row_gid = [&](const unsigned int I, const int r) {
      return static_cast<int_type>(
        offset[I] +
        TrilinosWrappers::global_row_index(K.block(I, 0).trilinos_matrix(), r));
    };
    // Calls f(flat global column) for every entry of local row r of block
    // row I, block by block (the order the value copy relies on).
    const auto for_each_column = [&](const unsigned int I,
                                     const int          r,
                                     const auto        &f) {
      for (unsigned int J = 0; J < n_blocks; ++J)
        {
          const Epetra_CrsMatrix &A = K.block(I, J).trilinos_matrix();
          int                     n;
          double                 *values;
          int                    *indices;
          A.ExtractMyRowView(r, n, values, indices);
          for (int k = 0; k < n; ++k)
            f(J,
              offset[J] + TrilinosWrappers::global_column_index(A, indices[k]));
        }
    };
    std::vector<int> row_length(map.NumMyElements(), 0);
    for (unsigned int I = 0; I < n_blocks; ++I)
      for (int r = 0; r < K.block(I, 0).trilinos_matrix().NumMyRows(); ++r)
        {
          const int flat_row = map.LID(row_gid(I, r));
          AssertThrow(flat_row >= 0,
                      ExcMessage("A row of the tangent is not locally owned."));
          for (unsigned int J = 0; J < n_blocks; ++J)
            row_length[flat_row] +=
              K.block(I, J).trilinos_matrix().NumMyEntries(r);
        }

    Epetra_CrsGraph       graph(Copy, map, row_length.data(), true);
    std::vector<int_type> columns;
    for (unsigned int I = 0; I < n_blocks; ++I)
      for (int r = 0; r < K.block(I, 0).trilinos_matrix().NumMyRows(); ++r)
        {
          columns.clear();
          for_each_column(I,
                          r,
                          [&](unsigned int, const types::global_dof_index c) {
                            columns.push_back(static_cast<int_type>(c));
                          });
          const int ierr =
            graph.InsertGlobalIndices(row_gid(I, r),
                                      static_cast<int>(columns.size()),
                                      columns.data());
          AssertThrow(ierr >= 0, LACExceptions::ExcTrilinosError(ierr));
        }
    int ierr = graph.FillComplete(map, map);
    AssertThrow(ierr >= 0, LACExceptions::ExcTrilinosError(ierr));
    ierr = graph.OptimizeStorage();
    AssertThrow(ierr >= 0, LACExceptions::ExcTrilinosError(ierr));
    Epetra_CrsMatrix pattern(Copy, graph);
    ierr = pattern.FillComplete(map, map);
    AssertThrow(ierr >= 0, LACExceptions::ExcTrilinosError(ierr));
    matrix.reinit(pattern, false);
    x.reinit(owned, comm);
    b.reinit(owned, comm);

    const Epetra_CrsMatrix &flat = matrix.trilinos_matrix();
    AssertThrow(b.trilinos_vector().Map().SameAs(flat.RowMap()),
                ExcInternalError());

    // Where each block entry goes: its column's position in the flat row.
    std::vector<std::pair<types::global_dof_index, int>> flat_columns;
    for (unsigned int I = 0; I < n_blocks; ++I)
      {
        const Epetra_CrsMatrix &A0 = K.block(I, 0).trilinos_matrix();
        row[I].resize(A0.NumMyRows());
        for (int r = 0; r < A0.NumMyRows(); ++r)
          {
            const int flat_row = flat.RowMap().LID(row_gid(I, r));
            AssertThrow(flat_row >= 0, ExcInternalError());
            row[I][r] = flat_row;
            int     fn;
            double *fvalues;
            int    *findices;
            flat.ExtractMyRowView(flat_row, fn, fvalues, findices);
            flat_columns.resize(fn);
            for (int k = 0; k < fn; ++k)
              flat_columns[k] = {
                TrilinosWrappers::global_column_index(flat, findices[k]), k};
            std::sort(flat_columns.begin(), flat_columns.end());
            for_each_column(
              I,
              r,
              [&](const unsigned int J, const types::global_dof_index column) {
                const auto p = std::lower_bound(flat_columns.begin(),
                                                flat_columns.end(),
                                                std::make_pair(column, -1));
                AssertThrow(p != flat_columns.end() && p->first == column,
                            ExcInternalError());
                position[n_blocks * I + J].push_back(p->second);
              });
          }
      }

    for (unsigned int I = 0; I < n_blocks; ++I)
      for (unsigned int J = 0; J < n_blocks; ++J)
        {
          const Epetra_CrsMatrix &A        = K.block(I, J).trilinos_matrix();
          source[n_blocks * I + J]         = &A;
          source_entries[n_blocks * I + J] = A.NumMyNonzeros();
        }
    has_pattern = true;
  }
} // namespace DuctileContact
