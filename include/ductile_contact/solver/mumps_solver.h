#pragma once

#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

namespace DuctileContact
{
  /**
   * A sparse direct solver for a distributed Epetra matrix through the C
   * interface of MUMPS (the matrix handed over distributed, one triplet per
   * owned entry; right-hand side and solution gathered on rank 0).
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
      unsigned int analyses       = 0;
      unsigned int factorisations = 0;
      unsigned int solves         = 0;
      double       analysis_time  = 0.;
      double       factor_time    = 0.;
      double       solve_time     = 0.;
      /// Entries of the factors (MUMPS INFOG(29)) of the last one.
      double factor_entries = 0.;
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

    /// Global rows owned here (in the order of the vectors' local indices),
    /// and on rank 0 the counts and offsets of every rank's rows.
    std::vector<int>    owned_rows;
    std::vector<int>    counts, offsets, gathered_rows;
    std::vector<double> gathered, rhs;
    std::vector<int>    pivot_order;

    Statistics stats;
  };
} // namespace DuctileContact
