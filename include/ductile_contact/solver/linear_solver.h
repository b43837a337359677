#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/mumps_solver.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <array>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

namespace DuctileContact
{
  /**
   * How accurate a solve needs to be for its caller, besides `Relative
   * tolerance`: with weights w_b per block b of the coupled vector, an
   * iterative solve may also stop once its residual r = b - K x meets
   *
   *   sqrt(sum_b (w_b |r_b|)^2) <= enough.
   *
   * GMRES on the direct solver's factors then measures its residual in
   * that weighted norm (the relative tolerance too); the AMG solvers,
   * which see the plain norm, stop at |r| <= enough / max_b w_b. Empty
   * weights: the relative tolerance alone. Every block with DoFs needs a
   * positive weight.
   */
  struct SolveAccuracy
  {
    std::vector<double> block_weights;
    double              enough = 0.;
  };

  /**
   * Solves the Newton system K delta = b.
   *
   * Without alpha and s unknowns (both blocks empty), on the displacement
   * block: a sparse direct solver (MUMPS through MumpsSolver, whose analysis
   * is kept while the pattern is, or KLU / MUMPS through Trilinos Amesos), or
   * CG / GMRES preconditioned by ML smoothed-aggregation AMG, whose near-null
   * space is the six rigid-body modes of the displacement DoFs (three
   * translations, three rotations about the support points).
   *
   * With alpha or s unknowns, on the whole coupled [u | alpha | s] system,
   * which is not symmetric in general:
   *  - direct: the nine blocks are copied into one Trilinos matrix over the
   *    global DoF indices (blocks are numbered consecutively) and factorised
   *    by the direct solver; the pattern of that copy is built on the first
   *    solve after setup() and reused, only the values are copied on each
   *    solve;
   *  - cg-amg, gmres-amg: right-preconditioned GMRES with the block
   *    lower-triangular preconditioner BlockTriangularPreconditioner, the
   *    diagonal blocks approximately inverted by the AMG above (u), a scalar
   *    AMG (alpha), and a scalar AMG or a sparse LU (s, `Phase-field
   *    preconditioner`). The preconditioner is rebuilt on every solve.
   */
  class LinearSolver
  {
  public:
    LinearSolver(const LinearSolverParameters &parameters,
                 const Discretisation         &discretisation);

    /**
     * Recomputes the rigid-body modes and forgets the pattern of the
     * monolithic copy; call after every DoF distribution.
     */
    void
    setup();

    /// Returns the number of iterations (1 for the direct solver).
    /// @p same_matrix: K is the matrix of the last solve, values unchanged
    /// (a chord step): its copy for the direct solver and the check of the
    /// factors' pattern are skipped.
    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b,
          const SolveAccuracy                               &accuracy = {},
          bool same_matrix                                            = false);

    /// One line on the direct solver's work so far (analyses,
    /// factorisations, solves and their times), if it kept any.
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
    /// The displacement block alone (alpha and s empty).
    unsigned int
    solve_displacement(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
                       dealii::TrilinosWrappers::MPI::BlockVector        &x,
                       const dealii::TrilinosWrappers::MPI::BlockVector  &b,
                       const SolveAccuracy &accuracy,
                       bool                 same_matrix);

    /// x = A^{-1} b by the Direct solver (MUMPS keeps its analysis, and
    /// with `Factorisation reuse` its factors while they serve); returns the
    /// number of applications of the factors. GMRES on the factors may
    /// also stop once its residual, weighted row by row with @p weights
    /// (plain without them), is below @p enough (as SolveAccuracy says);
    /// with @p same_matrix (A that of the last solve) the factors' pattern
    /// is not checked.
    unsigned int
    solve_direct(const dealii::TrilinosWrappers::SparseMatrix &A,
                 dealii::TrilinosWrappers::MPI::Vector        &x,
                 const dealii::TrilinosWrappers::MPI::Vector  &b,
                 const dealii::TrilinosWrappers::MPI::Vector  *weights,
                 double                                        enough,
                 bool                                          same_matrix);

    /// GMRES preconditioned by the last MUMPS factors; 0 if it did not
    /// reach the tolerance within @p max_iterations, or, with
    /// @p give_up_early, once the rate of its last iterations says it
    /// would need more than twice the iterations left
    /// (ProjectedGmresControl).
    unsigned int
    solve_with_old_factors(const dealii::TrilinosWrappers::SparseMatrix &A,
                           dealii::TrilinosWrappers::MPI::Vector        &x,
                           const dealii::TrilinosWrappers::MPI::Vector  &b,
                           const dealii::TrilinosWrappers::MPI::Vector *weights,
                           double                                       enough,
                           unsigned int max_iterations,
                           bool         give_up_early);

    /// The direct solver on the monolithic copy of the coupled system
    /// (values copied unless @p same_matrix).
    unsigned int
    solve_coupled_direct(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
                         dealii::TrilinosWrappers::MPI::BlockVector        &x,
                         const dealii::TrilinosWrappers::MPI::BlockVector  &b,
                         const SolveAccuracy &accuracy,
                         bool                 same_matrix);

    /// GMRES with the block lower-triangular preconditioner.
    unsigned int
    solve_coupled_iterative(
      const dealii::TrilinosWrappers::BlockSparseMatrix &K,
      dealii::TrilinosWrappers::MPI::BlockVector        &x,
      const dealii::TrilinosWrappers::MPI::BlockVector  &b,
      const SolveAccuracy                               &accuracy);

    /// Stopping tolerance of the solvers that see the plain residual norm:
    /// the relative one, or the SolveAccuracy's bound if looser.
    double
    plain_tolerance(double rhs_norm, const SolveAccuracy &accuracy) const;
    /// ML AMG of the block @p A (elliptic, `AMG smoother` and its sweeps)
    /// with @p aggregation_threshold, and @p modes as its near-null space
    /// (null: the constant, ML's default).
    void
    initialize_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
                   dealii::TrilinosWrappers::PreconditionAMG    &amg,
                   double                    aggregation_threshold,
                   const Epetra_MultiVector *modes = nullptr) const;

    /// Builds #monolithic (pattern and copy positions) from the blocks of K.
    void
    make_monolithic_pattern(
      const dealii::TrilinosWrappers::BlockSparseMatrix &K);

    const LinearSolverParameters &parameters;
    const Discretisation         &discretisation;

    /// Rigid-body modes on the locally owned displacement DoFs.
    std::unique_ptr<Epetra_MultiVector> rigid_body_modes;

    /// The constant and the dim coordinates on the locally owned DoFs of
    /// the phase-field block (block-local numbering): the near-null space
    /// of its AMG. Null without s DoFs.
    std::unique_ptr<Epetra_MultiVector> phase_field_modes;

    /// Makes #phase_field_modes.
    void
    make_phase_field_modes();

    /**
     * The coupled system as one matrix and two vectors over the global DoF
     * indices (locally_owned_dofs), for Amesos. Blocks (I, J) are indexed
     * 3 I + J.
     */
    struct Monolithic
    {
      dealii::TrilinosWrappers::SparseMatrix matrix;
      dealii::TrilinosWrappers::MPI::Vector  x, b;
      /// Row weights of a SolveAccuracy (w_b on the rows of block b).
      dealii::TrilinosWrappers::MPI::Vector weights;

      /// The block matrices the pattern was built from, and their number of
      /// local entries: a tangent re-created with another pattern is noticed.
      std::array<const Epetra_CrsMatrix *, 9> source{};
      std::array<int, 9>                      source_entries{};

      /// Local row of #matrix (and local index of x and b) for each local
      /// row of block row I.
      std::array<std::vector<int>, 3> row;

      /// For each local entry of block (I, J), in the order of its rows and
      /// of Epetra_CrsMatrix::ExtractMyRowView, the position in the row of
      /// #matrix that receives it.
      std::array<std::vector<int>, 9> position;
    };
    std::unique_ptr<Monolithic> monolithic;

    /// Direct solver = mumps: kept between solves (its analysis is redone
    /// only when the pattern changes).
    std::unique_ptr<MumpsSolver> mumps;
    /// Double-precision factors for a matrix that single-precision factors
    /// (Factorisation precision = single) cannot precondition.
    std::unique_ptr<MumpsSolver> fallback;

    /// GMRES iterations the current factors may still serve (`Factorisation
    /// reuse` after a factorisation).
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
