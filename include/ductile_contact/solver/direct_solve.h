#pragma once

#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/solver/mumps_solver.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <memory>
#include <mpi.h>
#include <ostream>
#include <utility>

namespace DuctileContact
{
  /// The choices of a DirectSolve.
  struct DirectSolveSettings
  {
    DirectSolver    solver        = DirectSolver::mumps;
    Factorisation   factorisation = Factorisation::lu;
    DirectOrdering  ordering      = DirectOrdering::metis;
    FactorPrecision precision     = FactorPrecision::double_precision;
    /// GMRES iterations the factors of one matrix may serve later matrices
    /// (0: every solve factorises).
    unsigned int reuse_iterations = 0;
    /// Of GMRES on inexact or old factors.
    double relative_tolerance = 1e-8;

    /// Those of the `Linear solver` section.
    static DirectSolveSettings
    of(const LinearSolverParameters &parameters);

    /// Exact double-precision LU factors of every matrix, MUMPS with the
    /// METIS ordering: the solves of the bounds' active-set sweeps.
    static DirectSolveSettings
    exact_lu();

    /// The exact factors of @p parameters' direct solver, for a block of a
    /// preconditioner: LU in double precision, the same package and
    /// ordering, no reuse.
    static DirectSolveSettings
    exact_block_factors(const LinearSolverParameters &parameters);
  };

  /**
   * The sparse direct solve of A x = b for one distributed matrix A, the
   * policy of `Linear solver/Type = direct`:
   *  - MUMPS through MumpsSolver, whose analysis is kept while the pattern
   *    is. With reuse, GMRES preconditioned by the factors of an earlier
   *    matrix solves later systems until it has spent `Factorisation reuse`
   *    iterations or fails within those left; failed reuse backs off
   *    (1, 2, 4, ... solves factorise at once). Single-precision factors
   *    precondition flexible GMRES to the tolerance; a matrix they cannot
   *    precondition is factorised again in double precision.
   *  - KLU or MUMPS through Trilinos Amesos: a new factorisation each time.
   *
   * factorize() and apply() give the factors of one matrix as a linear
   * operator (a block inverse of a preconditioner, the sweeps of an active
   * set); solve() decides itself when to factorise.
   */
  class DirectSolve
  {
  public:
    DirectSolve(MPI_Comm comm, const DirectSolveSettings &settings);

    /// New settings for the next solves: the analysis, factors and reuse
    /// history are kept while the package, factorisation, ordering and
    /// precision stay (the settings of a LinearSolver follow its
    /// parameters).
    void
    configure(const DirectSolveSettings &new_settings);

    /**
     * x = A^{-1} b; returns the applications of the factors (1 for exact
     * factors of A). GMRES on the factors may also stop once its residual,
     * weighted row by row with @p weights (plain without them), is below
     * @p enough; with @p same_matrix (A that of the last solve) the
     * factors' pattern is not checked.
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &A,
          dealii::TrilinosWrappers::MPI::Vector        &x,
          const dealii::TrilinosWrappers::MPI::Vector  &b,
          const dealii::TrilinosWrappers::MPI::Vector  *weights     = nullptr,
          double                                        enough      = 0.,
          bool                                          same_matrix = false);

    /// Factorises @p A (exact factors unless the settings ask for single
    /// precision) for apply().
    void
    factorize(const dealii::TrilinosWrappers::SparseMatrix &A);

    /// y = A^{-1} r with the factors of the last factorize().
    void
    apply(dealii::TrilinosWrappers::MPI::Vector       &y,
          const dealii::TrilinosWrappers::MPI::Vector &r);

    /// Forgets the analysis, the factors and the reuse history (the DoFs
    /// changed).
    void
    reset();

    /// One line on MUMPS' work so far (analyses, factorisations, solves
    /// and their times), if it did any.
    void
    print_summary(std::ostream &out) const;

    /// Factorisations in double precision because single-precision factors
    /// of the same matrix did not bring GMRES to the tolerance.
    unsigned int
    fallback_factorisations() const;

    /// GMRES runs on old factors that missed the tolerance or gave up
    /// early, and the triangular solves they spent.
    std::pair<unsigned int, unsigned int>
    failed_reuse_counts() const;

  private:
    /// The MUMPS solver of the settings, made on first use and again when
    /// they changed.
    MumpsSolver &
    mumps_solver();

    /// solve() through MumpsSolver.
    unsigned int
    solve_mumps(const dealii::TrilinosWrappers::SparseMatrix &A,
                dealii::TrilinosWrappers::MPI::Vector        &x,
                const dealii::TrilinosWrappers::MPI::Vector  &b,
                const dealii::TrilinosWrappers::MPI::Vector  *weights,
                double                                        enough,
                bool                                          same_matrix);

    /// GMRES preconditioned by the last MUMPS factors; 0 if it did not
    /// reach the tolerance within @p max_iterations, or, with
    /// @p give_up_early, once the rate of its last iterations says it
    /// would need more than twice the iterations left.
    unsigned int
    solve_with_old_factors(const dealii::TrilinosWrappers::SparseMatrix &A,
                           dealii::TrilinosWrappers::MPI::Vector        &x,
                           const dealii::TrilinosWrappers::MPI::Vector  &b,
                           const dealii::TrilinosWrappers::MPI::Vector *weights,
                           double                                       enough,
                           unsigned int max_iterations,
                           bool         give_up_early);

    /// The Amesos package of the settings.
    std::string
    amesos_name() const;

    const MPI_Comm      comm;
    DirectSolveSettings settings;

    /// Kept between solves (its analysis is redone only when the pattern
    /// changes).
    std::unique_ptr<MumpsSolver> mumps;
    /// Double-precision factors for a matrix that single-precision factors
    /// cannot precondition.
    std::unique_ptr<MumpsSolver> fallback;
    /// The Amesos solver of the last factorize() (Amesos packages).
    std::unique_ptr<dealii::SolverControl>                  amesos_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> amesos;

    /// GMRES iterations the current factors may still serve.
    unsigned int reuse_iterations_left = 0;

    /// Krylov vectors of the GMRES with old factors before it restarts.
    static constexpr unsigned int gmres_restart = 22;

    /// Solves to factorise at once after old factors failed (doubling with
    /// each failure in a row), and those done so far.
    unsigned int reuses_to_skip = 0, skipped_reuses = 0;

    /// GMRES iterations of the last solve on old factors that converged.
    unsigned int last_reuse_iterations = 0;

    /// GMRES runs on old factors that missed the tolerance within their
    /// budget, and the triangular solves they spent.
    unsigned int failed_reuses = 0, failed_reuse_solves = 0;
  };
} // namespace DuctileContact
