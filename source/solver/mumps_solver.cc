#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <ductile_contact/solver/mumps_solver.h>

#include <algorithm>
#include <array>
#include <dmumps_c.h>
#include <limits>
#include <metis.h>
#include <smumps_c.h>
#include <stdexcept>
#include <unordered_map>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    void
    call(DMUMPS_STRUC_C &id)
    {
      dmumps_c(&id);
    }

    void
    call(SMUMPS_STRUC_C &id)
    {
      smumps_c(&id);
    }

    /// MUMPS's 1-based parameter arrays.
    template <typename Id>
    int &
    icntl(Id &id, const int i)
    {
      return id.icntl[i - 1];
    }

    template <typename Id>
    int
    infog(const Id &id, const int i)
    {
      return id.infog[i - 1];
    }
  } // namespace

  /// The MUMPS instance of the chosen precision; values and right-hand
  /// sides in single precision are converted copies.
  struct MumpsSolver::Instance
  {
    bool               single = false;
    DMUMPS_STRUC_C     d{};
    SMUMPS_STRUC_C     s{};
    std::vector<float> values;
    /// Single precision: the right-hand side and solution in MUMPS's type.
    std::vector<float> rhs_loc, sol_loc;

    template <typename F>
    void
    visit(F &&f)
    {
      if (single)
        f(s);
      else
        f(d);
    }
  };

  namespace
  {

    /// The MUMPS code of an ordering (ICNTL(7)).
    int
    mumps_ordering(const DirectOrdering ordering)
    {
      switch (ordering)
        {
        case DirectOrdering::metis:
          return 1; // the user's pivot order, PERM_IN
        case DirectOrdering::amd:
          return 0;
        case DirectOrdering::pord:
          return 4;
        case DirectOrdering::automatic:
        case DirectOrdering::pt_scotch: // ICNTL(29) chooses it
          return 7;
        }
      return 7;
    }

    std::string
    mumps_error(const int code)
    {
      switch (code)
        {
        case -8:
        case -9:
        case -14:
        case -15:
          return "work space too small";
        case -10:
          return "numerically singular matrix";
        case -13:
          return "memory allocation failed";
        case -38:
          return "Linear solver/Ordering = pt-scotch needs a MUMPS built "
                 "with PT-Scotch (Debian: libmumps-ptscotch-dev, which "
                 "scripts/install-deps.sh installs; then a fresh build "
                 "directory); this one has none: choose Ordering = metis";
        default:
          return "see the MUMPS user guide, section 'Error diagnostics'";
        }
    }
  } // namespace



  MumpsSolver::MumpsSolver(const MPI_Comm        comm,
                           const Factorisation   factorisation,
                           const DirectOrdering  ordering,
                           const FactorPrecision precision)
      : comm(comm)
      , factorisation(factorisation)
      , ordering(ordering)
      , precision(precision)
      , mumps(std::make_unique<Instance>())
  {
    mumps->single = (precision == FactorPrecision::single_precision);
    mumps->visit([&](auto &id) {
      id.job          = -1;
      id.par          = 1; // rank 0 works too
      id.sym          = (factorisation == Factorisation::ldlt ? 2 : 0);
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
      call(id);
      AssertThrow(infog(id, 1) >= 0,
                  ExcMessage("MUMPS could not be initialised (INFOG(1) = " +
                             std::to_string(infog(id, 1)) + ")"));
      // No output of MUMPS's own: failures become exceptions here.
      icntl(id, 1)  = -1;
      icntl(id, 2)  = -1;
      icntl(id, 3)  = -1;
      icntl(id, 4)  = 0;
      icntl(id, 5)  = 0;  // assembled matrix
      icntl(id, 18) = 3;  // distributed triplets
      icntl(id, 20) = 10; // dense right-hand side, distributed (owned rows)
      icntl(id, 21) = 1;  // solution distributed as MUMPS holds it
      // Parallel analysis with PT-Scotch (MUMPS falls back to a sequential
      // one with Scotch on one rank), or sequential with the given order.
      const bool parallel = ordering == DirectOrdering::pt_scotch;
      icntl(id, 28)       = parallel ? 2 : 1;
      icntl(id, 29)       = parallel ? 1 : 0;
      icntl(id, 7)        = mumps_ordering(ordering);
      icntl(id, 14) = 30; // work space margin over the analysis' estimate, %
    });
  }



  MumpsSolver::~MumpsSolver()
  {
    mumps->visit([](auto &id) {
      id.job = -2;
      call(id);
    });
  }



  void
  MumpsSolver::run(const int job, const std::string &what)
  {
    mumps->visit([&](auto &id) {
      for (unsigned int attempt = 0;; ++attempt)
        {
          id.job = job;
          call(id);
          const int code = infog(id, 1);
          if (code >= 0)
            return;
          if ((code == -8 || code == -9) && attempt < 4)
            {
              icntl(id, 14) *= 2;
              continue;
            }
          throw std::runtime_error(
            "MUMPS " + what + " failed: INFOG(1) = " + std::to_string(code) +
            ", INFOG(2) = " + std::to_string(infog(id, 2)) + " (" +
            mumps_error(code) + ")");
        }
    });
  }



  void
  MumpsSolver::compute_metis_order()
  {
    const int rank = Utilities::MPI::this_mpi_process(comm);
    const int size = Utilities::MPI::n_mpi_processes(comm);

    // The pattern on rank 0.
    const int        n_local = static_cast<int>(row.size());
    std::vector<int> n_entries(size), entry_offsets(size + 1, 0);
    MPI_Gather(&n_local, 1, MPI_INT, n_entries.data(), 1, MPI_INT, 0, comm);
    if (rank == 0)
      for (int p = 0; p < size; ++p)
        entry_offsets[p + 1] = entry_offsets[p] + n_entries[p];
    std::vector<int> all_rows(rank == 0 ? entry_offsets[size] : 0),
      all_columns(all_rows.size());
    MPI_Gatherv(row.data(),
                n_local,
                MPI_INT,
                all_rows.data(),
                n_entries.data(),
                entry_offsets.data(),
                MPI_INT,
                0,
                comm);
    MPI_Gatherv(column.data(),
                n_local,
                MPI_INT,
                all_columns.data(),
                n_entries.data(),
                entry_offsets.data(),
                MPI_INT,
                0,
                comm);
    if (rank != 0)
      return;

    // The graph of K + K^T without the diagonal, in compressed rows.
    idx_t              n = n_global;
    std::vector<idx_t> xadj(n + 1, 0);
    for (std::size_t k = 0; k < all_rows.size(); ++k)
      if (all_rows[k] != all_columns[k])
        {
          ++xadj[all_rows[k]];
          ++xadj[all_columns[k]];
        }
    for (idx_t i = 0; i < n; ++i)
      xadj[i + 1] += xadj[i];
    std::vector<idx_t> adjacency(xadj[n]);
    std::vector<idx_t> fill(xadj.begin(), xadj.end() - 1);
    for (std::size_t k = 0; k < all_rows.size(); ++k)
      if (all_rows[k] != all_columns[k])
        {
          const idx_t i = all_rows[k] - 1, j = all_columns[k] - 1;
          adjacency[fill[i]++] = j;
          adjacency[fill[j]++] = i;
        }
    // Both (i, j) and (j, i) may be stored: remove repeated neighbours.
    idx_t end = 0;
    for (idx_t i = 0; i < n; ++i)
      {
        const auto first = adjacency.begin() + xadj[i];
        const auto last  = adjacency.begin() + xadj[i + 1];
        std::sort(first, last);
        const auto unique_end = std::unique(first, last);
        const auto begin      = end;
        for (auto p = first; p != unique_end; ++p)
          adjacency[end++] = *p;
        xadj[i] = begin;
      }
    xadj[n] = end;

    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    std::vector<idx_t> permutation(n), inverse(n);
    const int          ierr = METIS_NodeND(&n,
                                  xadj.data(),
                                  adjacency.data(),
                                  nullptr,
                                  options,
                                  permutation.data(),
                                  inverse.data());
    AssertThrow(ierr == METIS_OK,
                ExcMessage("METIS_NodeND failed with code " +
                           std::to_string(ierr)));
    // METIS: row i of K is row inverse[i] of the reordered matrix, i.e. the
    // position of unknown i in the pivot order (1-based for MUMPS).
    pivot_order.resize(n);
    for (idx_t i = 0; i < n; ++i)
      pivot_order[i] = static_cast<int>(inverse[i]) + 1;
  }



  namespace
  {
    /// Calls f(i, j, value) for every locally owned entry of @p A that
    /// MUMPS is given (1-based global indices; the upper triangle for
    /// ldlt), row by row.
    template <typename F>
    void
    for_each_triplet(const Epetra_CrsMatrix &A,
                     const Factorisation     factorisation,
                     const F                &f)
    {
      // The global number of each local column, looked up once per column
      // rather than once per entry.
      std::vector<int> column_gid(A.NumMyCols());
      for (int c = 0; c < A.NumMyCols(); ++c)
        column_gid[c] =
          static_cast<int>(TrilinosWrappers::global_column_index(A, c)) + 1;
      for (int r = 0; r < A.NumMyRows(); ++r)
        {
          int     n;
          double *values;
          int    *indices;
          A.ExtractMyRowView(r, n, values, indices);
          const int i =
            static_cast<int>(TrilinosWrappers::global_row_index(A, r)) + 1;
          for (int k = 0; k < n; ++k)
            {
              const int j = column_gid[indices[k]];
              if (factorisation == Factorisation::ldlt && j < i)
                continue;
              f(i, j, values[k]);
            }
        }
    }
  } // namespace



  MumpsSolver::LocalPattern
  MumpsSolver::LocalPattern::of(const Epetra_CrsMatrix &A)
  {
    LocalPattern p;
    for (int r = 0; r < A.NumMyRows(); ++r)
      p.row_gids.push_back(A.RowMap().GID64(r));
    for (int c = 0; c < A.NumMyCols(); ++c)
      p.column_gids.push_back(A.ColMap().GID64(c));
    p.row_start.reserve(A.NumMyRows() + 1);
    p.columns.reserve(A.NumMyNonzeros());
    for (int r = 0; r < A.NumMyRows(); ++r)
      {
        int     n;
        double *values;
        int    *indices;
        A.ExtractMyRowView(r, n, values, indices);
        p.row_start.push_back(static_cast<int>(p.columns.size()));
        p.columns.insert(p.columns.end(), indices, indices + n);
      }
    p.row_start.push_back(static_cast<int>(p.columns.size()));
    return p;
  }



  bool
  MumpsSolver::LocalPattern::matches(const Epetra_CrsMatrix &A) const
  {
    if (static_cast<std::size_t>(A.NumMyRows()) != row_gids.size() ||
        static_cast<std::size_t>(A.NumMyCols()) != column_gids.size() ||
        static_cast<std::size_t>(A.NumMyNonzeros()) != columns.size())
      return false;
    for (int r = 0; r < A.NumMyRows(); ++r)
      if (A.RowMap().GID64(r) != row_gids[r])
        return false;
    for (int c = 0; c < A.NumMyCols(); ++c)
      if (A.ColMap().GID64(c) != column_gids[c])
        return false;
    for (int r = 0; r < A.NumMyRows(); ++r)
      {
        int     n;
        double *values;
        int    *indices;
        A.ExtractMyRowView(r, n, values, indices);
        if (n != row_start[r + 1] - row_start[r] ||
            !std::equal(indices, indices + n, columns.data() + row_start[r]))
          return false;
      }
    return true;
  }



  bool
  MumpsSolver::has_factors_for(const Epetra_CrsMatrix &A) const
  {
    const bool same = factorised && pattern.matches(A);
    return Utilities::MPI::min(same ? 1 : 0, comm) == 1;
  }



  void
  MumpsSolver::factorize(const Epetra_CrsMatrix &A)
  {
    // The owned triplets (1-based global indices), built afresh: comparing
    // them with the last ones tells whether the pattern changed.
    std::vector<int> new_row, new_column;
    new_row.reserve(A.NumMyNonzeros());
    new_column.reserve(A.NumMyNonzeros());
    value.clear();
    value.reserve(A.NumMyNonzeros());
    for_each_triplet(A,
                     factorisation,
                     [&](const int i, const int j, const double v) {
                       new_row.push_back(i);
                       new_column.push_back(j);
                       value.push_back(v);
                     });
    const bool same    = analysed && new_row == row && new_column == column;
    const bool analyse = Utilities::MPI::min(same ? 1 : 0, comm) == 0;

    factorised                  = false;
    pattern                     = LocalPattern::of(A);
    const auto point_to_pattern = [&]() {
      mumps->visit([&](auto &id) {
        id.irn_loc = row.data();
        id.jcn_loc = column.data();
      });
    };
    if (analyse)
      {
        Timer timer;
        row.swap(new_row);
        column.swap(new_column);
        n_global = A.NumGlobalRows();
        mumps->visit([&](auto &id) {
          id.n       = n_global;
          id.nnz_loc = static_cast<MUMPS_INT8>(row.size());
        });
        point_to_pattern();

        owned_rows.resize(A.NumMyRows());
        for (int r = 0; r < A.NumMyRows(); ++r)
          owned_rows[r] =
            static_cast<int>(TrilinosWrappers::global_row_index(A, r));
        irhs_loc.resize(owned_rows.size());
        for (std::size_t r = 0; r < owned_rows.size(); ++r)
          irhs_loc[r] = owned_rows[r] + 1;
        find_row_owners();
        const int rank = Utilities::MPI::this_mpi_process(comm);
        if (ordering == DirectOrdering::metis)
          {
            compute_metis_order();
            mumps->visit([&](auto &id) {
              id.perm_in = (rank == 0 ? pivot_order.data() : nullptr);
            });
          }
        run(1, "analysis");
        analysed = true;
        ++stats.analyses;
        mumps->visit([&](auto &id) {
          if (infog(id, 32) == 2)
            ++stats.parallel_analyses;
        });
        stats.analysis_time += timer.wall_time();
      }

    Timer timer;
    point_to_pattern();
    // The values MUMPS reads: ours, or a single-precision copy.
    if (mumps->single)
      {
        mumps->values.assign(value.begin(), value.end());
        mumps->s.a_loc = mumps->values.data();
      }
    else
      mumps->d.a_loc = value.data();
    run(2, "factorisation");
    // The solution entries MUMPS will hold here (INFO(23)); their rows are
    // known after the first solve.
    mumps->visit([&](auto &id) {
      solution_entries = id.info[22];
      isol_loc.assign(std::max(solution_entries, 1), 0);
      id.lsol_loc = static_cast<int>(isol_loc.size());
    });
    sol_loc.assign(isol_loc.size(), 0.);
    mumps->sol_loc.assign(mumps->single ? isol_loc.size() : 0, 0.f);
    exchange.valid = false;
    factorised     = true;
    ++stats.factorisations;
    stats.factor_time += timer.wall_time();
    mumps->visit([&](auto &id) {
      stats.factor_entries = static_cast<double>(
        infog(id, 29) >= 0 ? infog(id, 29) : -1.e6 * infog(id, 29));
    });
  }



  void
  MumpsSolver::find_row_owners()
  {
    // The owned rows as runs of consecutive numbers [first, end), of every
    // rank: a few runs per rank (one per block of the system).
    std::vector<int> runs;
    for (std::size_t r = 0; r < owned_rows.size(); ++r)
      if (r == 0 || owned_rows[r] != owned_rows[r - 1] + 1)
        {
          if (r > 0)
            runs.push_back(owned_rows[r - 1] + 1);
          runs.push_back(owned_rows[r]);
        }
    if (!owned_rows.empty())
      runs.push_back(owned_rows.back() + 1);
    const std::vector<std::vector<int>> all =
      Utilities::MPI::all_gather(comm, runs);
    row_runs.clear();
    for (unsigned int p = 0; p < all.size(); ++p)
      for (std::size_t k = 0; k + 1 < all[p].size(); k += 2)
        row_runs.push_back(
          std::array<int, 3>{{all[p][k], all[p][k + 1], static_cast<int>(p)}});
    std::sort(row_runs.begin(), row_runs.end());
  }



  int
  MumpsSolver::owner_of(const int row) const
  {
    const auto run =
      std::upper_bound(row_runs.begin(),
                       row_runs.end(),
                       std::array<int, 3>{{row,
                                           std::numeric_limits<int>::max(),
                                           std::numeric_limits<int>::max()}});
    Assert(run != row_runs.begin() && row < (*std::prev(run))[1],
           ExcInternalError());
    return (*std::prev(run))[2];
  }



  void
  MumpsSolver::plan_exchange()
  {
    // Where each solution entry of this rank goes (its row's owner), and
    // where each entry that arrives belongs among the owned rows.
    const int size = Utilities::MPI::n_mpi_processes(comm);
    exchange.send_counts.assign(size, 0);
    std::vector<int> owner(solution_entries);
    for (int k = 0; k < solution_entries; ++k)
      ++exchange.send_counts[owner[k] = owner_of(isol_loc[k] - 1)];
    exchange.send_offsets.assign(size + 1, 0);
    for (int p = 0; p < size; ++p)
      exchange.send_offsets[p + 1] =
        exchange.send_offsets[p] + exchange.send_counts[p];
    exchange.pack_order.resize(solution_entries);
    std::vector<int> fill(exchange.send_offsets.begin(),
                          exchange.send_offsets.end() - 1);
    for (int k = 0; k < solution_entries; ++k)
      exchange.pack_order[fill[owner[k]]++] = k;

    exchange.receive_counts.assign(size, 0);
    MPI_Alltoall(exchange.send_counts.data(),
                 1,
                 MPI_INT,
                 exchange.receive_counts.data(),
                 1,
                 MPI_INT,
                 comm);
    exchange.receive_offsets.assign(size + 1, 0);
    for (int p = 0; p < size; ++p)
      exchange.receive_offsets[p + 1] =
        exchange.receive_offsets[p] + exchange.receive_counts[p];
    std::vector<int> rows(solution_entries),
      arriving(exchange.receive_offsets[size]);
    for (std::size_t k = 0; k < rows.size(); ++k)
      rows[k] = isol_loc[exchange.pack_order[k]] - 1;
    MPI_Alltoallv(rows.data(),
                  exchange.send_counts.data(),
                  exchange.send_offsets.data(),
                  MPI_INT,
                  arriving.data(),
                  exchange.receive_counts.data(),
                  exchange.receive_offsets.data(),
                  MPI_INT,
                  comm);
    std::unordered_map<int, int> local;
    local.reserve(owned_rows.size());
    for (std::size_t r = 0; r < owned_rows.size(); ++r)
      local.emplace(owned_rows[r], static_cast<int>(r));
    exchange.positions.resize(arriving.size());
    for (std::size_t k = 0; k < arriving.size(); ++k)
      exchange.positions[k] = local.at(arriving[k]);
    AssertThrow(arriving.size() == owned_rows.size(),
                ExcMessage("MUMPS's distributed solution does not cover "
                           "every owned row once"));
    exchange.valid = true;
  }



  void
  MumpsSolver::solve(Epetra_MultiVector &x, const Epetra_MultiVector &b)
  {
    AssertThrow(factorised, ExcMessage("MumpsSolver::solve before factorize"));
    AssertThrow(b.MyLength() == static_cast<int>(owned_rows.size()) &&
                  x.MyLength() == b.MyLength(),
                ExcMessage("vectors of another layout than the matrix"));
    Timer     timer;
    const int n_owned = b.MyLength();

    // Each rank hands over its own rows and gets back the solution rows
    // MUMPS holds (ICNTL(20) = 10, ICNTL(21) = 1): no rank gathers a
    // global vector.
    if (mumps->single)
      {
        mumps->rhs_loc.assign(b[0], b[0] + n_owned);
        mumps->s.rhs_loc = mumps->rhs_loc.data();
        mumps->s.sol_loc = mumps->sol_loc.data();
      }
    else
      {
        mumps->d.rhs_loc = b[0];
        mumps->d.sol_loc = sol_loc.data();
      }
    mumps->visit([&](auto &id) {
      id.nrhs     = 1;
      id.nloc_rhs = n_owned;
      id.lrhs_loc = std::max(n_owned, 1);
      id.irhs_loc = irhs_loc.data();
      id.isol_loc = isol_loc.data();
    });
    run(3, "solve");
    if (mumps->single)
      std::copy(mumps->sol_loc.begin(), mumps->sol_loc.end(), sol_loc.begin());

    if (!exchange.valid)
      plan_exchange();
    std::vector<double> packed(exchange.pack_order.size()),
      arriving(exchange.positions.size());
    for (std::size_t k = 0; k < packed.size(); ++k)
      packed[k] = sol_loc[exchange.pack_order[k]];
    MPI_Alltoallv(packed.data(),
                  exchange.send_counts.data(),
                  exchange.send_offsets.data(),
                  MPI_DOUBLE,
                  arriving.data(),
                  exchange.receive_counts.data(),
                  exchange.receive_offsets.data(),
                  MPI_DOUBLE,
                  comm);
    for (std::size_t k = 0; k < arriving.size(); ++k)
      x[0][exchange.positions[k]] = arriving[k];
    const int rank = Utilities::MPI::this_mpi_process(comm);
    stats.bytes_sent +=
      sizeof(double) * (packed.size() - exchange.send_counts[rank]);
    ++stats.solves;
    stats.solve_time += timer.wall_time();
  }
} // namespace DuctileContact
