// LinearSolver: the monolithic matrix of the coupled [u | alpha | s] system
// (one Epetra matrix over all blocks) and its solves, by the sparse direct
// solver (with GMRES on old factors) or by GMRES with the block
// preconditioner.
#include <deal.II/lac/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_solver.h>

#include <ductile_contact/solver/block_preconditioner.h>
#include <ductile_contact/solver/linear_solver.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace DuctileContact
{
  using namespace dealii;



  void
  LinearSolver::make_monolithic_pattern(
    const TrilinosWrappers::BlockSparseMatrix &K)
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

    monolithic    = std::make_unique<Monolithic>();
    Monolithic &m = *monolithic;

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
          const int row = map.LID(row_gid(I, r));
          AssertThrow(row >= 0,
                      ExcMessage("A row of the tangent is not locally owned."));
          for (unsigned int J = 0; J < n_blocks; ++J)
            row_length[row] += K.block(I, J).trilinos_matrix().NumMyEntries(r);
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
    m.matrix.reinit(pattern, false);
    m.x.reinit(owned, comm);
    m.b.reinit(owned, comm);

    const Epetra_CrsMatrix &flat = m.matrix.trilinos_matrix();
    AssertThrow(m.b.trilinos_vector().Map().SameAs(flat.RowMap()),
                ExcInternalError());

    // Where each block entry goes: its column's position in the flat row.
    std::vector<std::pair<types::global_dof_index, int>> flat_columns;
    for (unsigned int I = 0; I < n_blocks; ++I)
      {
        const Epetra_CrsMatrix &A0 = K.block(I, 0).trilinos_matrix();
        m.row[I].resize(A0.NumMyRows());
        for (int r = 0; r < A0.NumMyRows(); ++r)
          {
            const int row = flat.RowMap().LID(row_gid(I, r));
            AssertThrow(row >= 0, ExcInternalError());
            m.row[I][r] = row;
            int     fn;
            double *fvalues;
            int    *findices;
            flat.ExtractMyRowView(row, fn, fvalues, findices);
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
                m.position[n_blocks * I + J].push_back(p->second);
              });
          }
      }

    for (unsigned int I = 0; I < n_blocks; ++I)
      for (unsigned int J = 0; J < n_blocks; ++J)
        {
          const Epetra_CrsMatrix &A          = K.block(I, J).trilinos_matrix();
          m.source[n_blocks * I + J]         = &A;
          m.source_entries[n_blocks * I + J] = A.NumMyNonzeros();
        }
  }



  unsigned int
  LinearSolver::solve_coupled_direct(
    const TrilinosWrappers::BlockSparseMatrix &K,
    TrilinosWrappers::MPI::BlockVector        &x,
    const TrilinosWrappers::MPI::BlockVector  &b,
    const SolveAccuracy                       &accuracy,
    const bool                                 same_matrix)
  {
    const unsigned int n_blocks = Block::n_blocks;

    // The pattern is reused while the tangent keeps its own; a tangent
    // re-created after setup() with another pattern is rebuilt here. All
    // ranks must agree: building the pattern is collective.
    bool same = (monolithic != nullptr);
    for (unsigned int i = 0; same && i < n_blocks * n_blocks; ++i)
      {
        const Epetra_CrsMatrix &A =
          K.block(i / n_blocks, i % n_blocks).trilinos_matrix();
        same = (monolithic->source[i] == &A &&
                monolithic->source_entries[i] == A.NumMyNonzeros());
      }
    same =
      Utilities::MPI::min(same ? 1 : 0,
                          discretisation.dof_handler.get_communicator()) == 1;
    if (!same)
      make_monolithic_pattern(K);
    Monolithic &m = *monolithic;

    // Values: each block entry into its place in the flat row (a view of
    // the Epetra storage; the pattern is fixed, so no compress is needed).
    // Every entry of the flat pattern comes from one block entry. Not again
    // for the matrix of the last solve.
    const Epetra_CrsMatrix &flat        = m.matrix.trilinos_matrix();
    const bool              copy_values = !(same_matrix && same);
    for (unsigned int I = 0; copy_values && I < n_blocks; ++I)
      for (unsigned int J = 0; J < n_blocks; ++J)
        {
          const Epetra_CrsMatrix &A = K.block(I, J).trilinos_matrix();
          const int *position       = m.position[n_blocks * I + J].data();
          for (int r = 0; r < A.NumMyRows(); ++r)
            {
              int     n, fn;
              double *values, *fvalues;
              int    *indices, *findices;
              A.ExtractMyRowView(r, n, values, indices);
              flat.ExtractMyRowView(m.row[I][r], fn, fvalues, findices);
              for (int k = 0; k < n; ++k)
                fvalues[*position++] = values[k];
            }
        }

    // Block vectors <-> flat vectors: same owned DoFs, same local order per
    // block as the block matrix rows.
    double *flat_b = m.b.trilinos_vector()[0];
    for (unsigned int I = 0; I < n_blocks; ++I)
      {
        const Epetra_MultiVector &bI = b.block(I).trilinos_vector();
        AssertDimension(static_cast<std::size_t>(bI.MyLength()),
                        m.row[I].size());
        for (int r = 0; r < bI.MyLength(); ++r)
          flat_b[m.row[I][r]] = bI[0][r];
      }
    m.x = 0.;

    const bool weighted = !accuracy.block_weights.empty();
    if (weighted)
      {
        m.weights.reinit(m.b, true);
        double *flat_w = m.weights.trilinos_vector()[0];
        for (unsigned int I = 0; I < n_blocks; ++I)
          for (const int r : m.row[I])
            flat_w[r] = accuracy.block_weights[I];
      }
    const unsigned int n_solves = solve_direct(m.matrix,
                                               m.x,
                                               m.b,
                                               weighted ? &m.weights : nullptr,
                                               accuracy.enough,
                                               same_matrix && same);

    const double *flat_x = m.x.trilinos_vector()[0];
    for (unsigned int I = 0; I < n_blocks; ++I)
      {
        Epetra_MultiVector &xI = x.block(I).trilinos_vector();
        AssertDimension(static_cast<std::size_t>(xI.MyLength()),
                        m.row[I].size());
        for (int r = 0; r < xI.MyLength(); ++r)
          xI[0][r] = flat_x[m.row[I][r]];
      }
    return n_solves;
  }



  unsigned int
  LinearSolver::solve_coupled_iterative(
    const TrilinosWrappers::BlockSparseMatrix &K,
    TrilinosWrappers::MPI::BlockVector        &x,
    const TrilinosWrappers::MPI::BlockVector  &b,
    const SolveAccuracy                       &accuracy)
  {
    using Inverse = BlockTriangularPreconditioner::BlockInverse;
    std::vector<Inverse> inverses(Block::n_blocks);

    // u: the AMG of the displacement-only solver.
    TrilinosWrappers::PreconditionAMG amg_u;
    initialize_amg(K.block(Block::displacement, Block::displacement),
                   amg_u,
                   parameters.aggregation_threshold,
                   rigid_body_modes.get());
    inverses[Block::displacement] = [&](auto &y, const auto &r) {
      amg_u.vmult(y, r);
    };

    // alpha, s: scalar elliptic blocks (mass + Laplacian, + C0IP for s).
    TrilinosWrappers::PreconditionAMG amg_alpha;
    if (discretisation.dofs_per_block[Block::hardening] > 0)
      {
        // The constant is its near-null space, ML's default.
        initialize_amg(K.block(Block::hardening, Block::hardening),
                       amg_alpha,
                       parameters.aggregation_threshold);
        inverses[Block::hardening] = [&](auto &y, const auto &r) {
          amg_alpha.vmult(y, r);
        };
      }

    TrilinosWrappers::PreconditionAMG amg_s;
    SolverControl                     direct_control(1, 0.);
    TrilinosWrappers::SolverDirect    direct_s(
      direct_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                     parameters.amesos_name()));
    if (discretisation.dofs_per_block[Block::phase_field] > 0)
      {
        const auto &A = K.block(Block::phase_field, Block::phase_field);
        if (parameters.phase_field_preconditioner ==
            PhaseFieldPreconditioner::direct)
          {
            direct_s.initialize(A);
            inverses[Block::phase_field] = [&](auto &y, const auto &r) {
              direct_s.solve(y, r);
            };
          }
        else
          {
            // 0.02 beats 1e-4 for the C0IP block (shared docs,
            // performance.md). Near-null space: the constant and the
            // coordinates, which the fourth-order part does not see. With
            // the constant alone the aggregates interpolate the linear
            // functions badly: in the plane-strain paper scene the
            // iterations grew 12-fold from the mesh refined once to three
            // times, against 3-fold (benchmarks/iterative_solver).
            initialize_amg(A, amg_s, 0.02, phase_field_modes.get());
            inverses[Block::phase_field] = [&](auto &y, const auto &r) {
              amg_s.vmult(y, r);
            };
          }
      }

    const BlockTriangularPreconditioner preconditioner(K, inverses);

    // Right preconditioning: the stopping test is on the true residual
    // ||b - K x||, as the relative tolerance promises.
    SolverControl control(parameters.max_iterations,
                          plain_tolerance(b.l2_norm(), accuracy));
    SolverGMRES<TrilinosWrappers::MPI::BlockVector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::BlockVector>::AdditionalData(
        parameters.gmres_restart, true));
    gmres.solve(K, x, b, preconditioner);
    return control.last_step();
  }
} // namespace DuctileContact
