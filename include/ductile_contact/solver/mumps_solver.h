#pragma once

#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <array>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

namespace DuctileContact
{
  /**
   * A sparse direct solver for a distributed Epetra matrix through the C
   * interface of MUMPS (the matrix handed over distributed, one triplet per
   * owned entry; right-hand side and solution distributed: each rank hands
   * over its owned rows, MUMPS returns the solution rows it holds, and one
   * all-to-all exchange brings them to their owners, so that no rank holds
   * a global vector). The analysis is MUMPS's parallel one with the
   * PT-Scotch ordering (DirectOrdering::pt_scotch, on two or more ranks:
   * no rank gathers the pattern), sequential otherwise: with the METIS
   * ordering, rank 0 gathers the pattern once per analysis, computes the
   * order and MUMPS analyses there.
   *
   * The analysis (ordering and symbolic factorisation) depends only on the
   * sparsity pattern; it is done when factorize() sees a pattern other than
   * the last one and reused otherwise, so that a Newton iteration pays for
   * the numerical factorisation and the triangular solves only.
   *
   * With FactorPrecision::single_precision the factors are those of SMUMPS
   * (the values and right-hand sides converted): about half the
   * factorisation time and half the memory traffic of a triangular solve;
   * solve() is then exact to ~1e-7 only and serves as a preconditioner
   * (exact() tells which).
   */
  class MumpsSolver
  {
  public:
    /// Time and count of each phase since construction.
    struct Statistics
    {
      unsigned int analyses = 0;
      /// Of these, the ones MUMPS did on all ranks (INFOG(32) = 2).
      unsigned int parallel_analyses = 0;
      unsigned int factorisations    = 0;
      unsigned int solves            = 0;
      double       analysis_time     = 0.;
      double       factor_time       = 0.;
      double       solve_time        = 0.;
      /// Entries of the factors (MUMPS INFOG(29)) of the last one.
      double factor_entries = 0.;
      /// Bytes of solution entries this rank sent to other ranks.
      double bytes_sent = 0.;
    };

    MumpsSolver(MPI_Comm        comm,
                Factorisation   factorisation,
                DirectOrdering  ordering,
                FactorPrecision precision = FactorPrecision::double_precision);
    ~MumpsSolver();
    MumpsSolver(const MumpsSolver &) = delete;
    MumpsSolver &
    operator=(const MumpsSolver &) = delete;

    /// Factorises @p A (collective), after a new analysis if its pattern
    /// differs from that of the last call on any rank.
    void
    factorize(const Epetra_CrsMatrix &A);

    /// Whether factors exist and were made from a matrix with the pattern
    /// of @p A (collective; compares the local index arrays, O(entries)).
    bool
    has_factors_for(const Epetra_CrsMatrix &A) const;

    /// Whether factors exist (of the matrix factorised last).
    bool
    has_factors() const
    {
      return factorised;
    }

    /// x = A^{-1} b with the last factorisation; @p b and @p x have the row
    /// map of A.
    void
    solve(Epetra_MultiVector &x, const Epetra_MultiVector &b);

    const Statistics &
    statistics() const
    {
      return stats;
    }

    /// Whether this solver was made with these settings.
    bool
    made_for(const Factorisation   f,
             const DirectOrdering  o,
             const FactorPrecision p) const
    {
      return f == factorisation && o == ordering && p == precision;
    }

    /// Whether solve() is exact to round-off (double-precision factors of
    /// the matrix factorised last); single-precision factors need GMRES.
    bool
    exact() const
    {
      return precision == FactorPrecision::double_precision;
    }

  private:
    /// Calls MUMPS with @p job and throws with MUMPS's error codes on
    /// failure; a workspace too small (INFOG(1) = -8, -9) is enlarged and
    /// the job repeated.
    void
    run(int job, const std::string &what);

    /// The METIS pivot order of the pattern in #row, #column (rank 0 only).
    void
    compute_metis_order();

    MPI_Comm        comm;
    Factorisation   factorisation;
    DirectOrdering  ordering;
    FactorPrecision precision;
    int             n_global = 0;

    /// The MUMPS instance (DMUMPS_STRUC_C or SMUMPS_STRUC_C, opaque here).
    struct Instance;
    std::unique_ptr<Instance> mumps;

    /// The pattern of the matrix factorised last as Epetra holds it: global
    /// numbers of the owned rows and of the local columns, the local column
    /// indices row by row (has_factors_for() compares these arrays, ~5x
    /// faster than the triplets).
    struct LocalPattern
    {
      std::vector<long long> row_gids, column_gids;
      std::vector<int>       row_start, columns;

      static LocalPattern
      of(const Epetra_CrsMatrix &A);
      bool
      matches(const Epetra_CrsMatrix &A) const;
    };
    LocalPattern pattern;

    /// Owned triplets, 1-based global indices (upper triangle for ldlt).
    std::vector<int>    row, column;
    std::vector<double> value;
    bool                analysed   = false;
    bool                factorised = false;

    /// The runs [first, end) of consecutive global rows owned by each rank
    /// (first, end, rank), sorted: who owns a row, for the solution
    /// exchange.
    void
    find_row_owners();
    int
    owner_of(int row) const;

    /// The exchange plan of the distributed solution (isol_loc, known after
    /// the first solve of a factorisation).
    void
    plan_exchange();

    /// Global rows owned here (0-based, in the order of the vectors' local
    /// indices) and MUMPS's 1-based copy of them (IRHS_LOC).
    std::vector<int>                owned_rows, irhs_loc;
    std::vector<std::array<int, 3>> row_runs;
    /// The solution entries MUMPS holds here (SOL_LOC) and their global
    /// rows, 1-based (ISOL_LOC).
    std::vector<double> sol_loc;
    std::vector<int>    isol_loc;
    /// How many of them there are (INFO(23) of the factorisation).
    int solution_entries = 0;
    /// From MUMPS's solution rows to the owners' rows: the entries sent to
    /// each rank (counts, offsets, and the order of the local entries),
    /// and the local row of each entry that arrives.
    struct Exchange
    {
      std::vector<int> send_counts, send_offsets, pack_order;
      std::vector<int> receive_counts, receive_offsets, positions;
      bool             valid = false;
    } exchange;
    std::vector<int> pivot_order;

    Statistics stats;
  };
} // namespace DuctileContact
