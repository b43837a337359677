// DirectSolve: the sparse direct solve of one matrix (MUMPS with its
// analysis kept and factors reused through GMRES, or Trilinos Amesos), for
// the Newton systems of `Linear solver/Type = direct` and the bounds'
// active-set sweeps.
#include <deal.II/lac/exceptions.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <ductile_contact/solver/direct_solve.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace DuctileContact
{
  using namespace dealii;



  DirectSolveSettings
  DirectSolveSettings::of(const LinearSolverParameters &parameters)
  {
    DirectSolveSettings s;
    s.solver             = parameters.direct_solver;
    s.factorisation      = parameters.factorisation;
    s.ordering           = parameters.ordering;
    s.precision          = parameters.precision;
    s.reuse_iterations   = parameters.reuse_iterations;
    s.relative_tolerance = parameters.relative_tolerance;
    return s;
  }



  DirectSolveSettings
  DirectSolveSettings::exact_lu()
  {
    return DirectSolveSettings();
  }



  DirectSolveSettings
  DirectSolveSettings::exact_block_factors(
    const LinearSolverParameters &parameters)
  {
    DirectSolveSettings s;
    s.solver   = parameters.direct_solver;
    s.ordering = parameters.ordering;
    return s;
  }



  DirectSolve::DirectSolve(const MPI_Comm             comm,
                           const DirectSolveSettings &settings)
      : comm(comm)
      , settings(settings)
  {
  }



  void
  DirectSolve::configure(const DirectSolveSettings &new_settings)
  {
    settings = new_settings;
  }



  void
  DirectSolve::reset()
  {
    mumps.reset();
    fallback.reset();
    amesos.reset();
    amesos_control.reset();
    reuse_iterations_left = 0;
    reuses_to_skip        = 0;
    skipped_reuses        = 0;
    failed_reuses         = 0;
    failed_reuse_solves   = 0;
    last_reuse_iterations = 0;
  }



  MumpsSolver &
  DirectSolve::mumps_solver()
  {
    if (!mumps || !mumps->made_for(settings.factorisation,
                                   settings.ordering,
                                   settings.precision))
      mumps = std::make_unique<MumpsSolver>(comm,
                                            settings.factorisation,
                                            settings.ordering,
                                            settings.precision);
    return *mumps;
  }



  std::string
  DirectSolve::amesos_name() const
  {
    return settings.solver == DirectSolver::amesos_klu ? "Amesos_Klu"
                                                       : "Amesos_Mumps";
  }



  unsigned int
  DirectSolve::solve(const TrilinosWrappers::SparseMatrix &A,
                     TrilinosWrappers::MPI::Vector        &x,
                     const TrilinosWrappers::MPI::Vector  &b,
                     const TrilinosWrappers::MPI::Vector  *weights,
                     const double                          enough,
                     const bool                            same_matrix)
  {
    if (settings.solver == DirectSolver::mumps)
      return solve_mumps(A, x, b, weights, enough, same_matrix);
    SolverControl                                  control(1, 0.);
    TrilinosWrappers::SolverDirect::AdditionalData data(false, amesos_name());
    TrilinosWrappers::SolverDirect                 direct(control, data);
    direct.solve(A, x, b);
    return 1;
  }



  void
  DirectSolve::factorize(const TrilinosWrappers::SparseMatrix &A)
  {
    if (settings.solver == DirectSolver::mumps)
      {
        mumps_solver().factorize(A.trilinos_matrix());
        return;
      }
    amesos_control = std::make_unique<SolverControl>(1, 0.);
    amesos         = std::make_unique<TrilinosWrappers::SolverDirect>(
      *amesos_control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, amesos_name()));
    amesos->initialize(A);
  }



  void
  DirectSolve::apply(TrilinosWrappers::MPI::Vector       &y,
                     const TrilinosWrappers::MPI::Vector &r)
  {
    if (settings.solver == DirectSolver::mumps)
      {
        Assert(mumps && mumps->has_factors(),
               ExcMessage("DirectSolve::apply() before factorize()"));
        mumps->solve(y.trilinos_vector(), r.trilinos_vector());
        return;
      }
    Assert(amesos, ExcMessage("DirectSolve::apply() before factorize()"));
    amesos->solve(y, r);
  }



  void
  DirectSolve::print_summary(std::ostream &out) const
  {
    if (!mumps)
      return;
    const MumpsSolver::Statistics &s = mumps->statistics();
    out << "MUMPS (" << name_of(factorisation_names(), settings.factorisation)
        << ", " << name_of(direct_ordering_names(), settings.ordering)
        << " ordering, "
        << name_of(factor_precision_names(), settings.precision)
        << " precision): " << s.analyses << " analyses (" << s.parallel_analyses
        << " on all ranks) " << s.analysis_time << " s, " << s.factorisations
        << " factorisations " << s.factor_time << " s, " << s.solves
        << " solves " << s.solve_time << " s ("
        << (s.solves > 0 ? s.bytes_sent / s.solves : 0.)
        << " bytes of solution sent per solve by this rank); "
        << s.factor_entries << " entries in the last factors; " << failed_reuses
        << " GMRES runs on old factors missed the tolerance ("
        << failed_reuse_solves << " solves)";
    if (fallback)
      out << "; " << fallback->statistics().factorisations
          << " double-precision factorisations where the single-precision "
             "factors did not converge";
    out << std::endl;
  }



  unsigned int
  DirectSolve::fallback_factorisations() const
  {
    return fallback ? fallback->statistics().factorisations : 0;
  }



  std::pair<unsigned int, unsigned int>
  DirectSolve::failed_reuse_counts() const
  {
    return {failed_reuses, failed_reuse_solves};
  }



  unsigned int
  DirectSolve::solve_mumps(const TrilinosWrappers::SparseMatrix &A,
                           TrilinosWrappers::MPI::Vector        &x,
                           const TrilinosWrappers::MPI::Vector  &b,
                           const TrilinosWrappers::MPI::Vector  *weights,
                           const double                          enough,
                           const bool                            same_matrix)
  {
    mumps_solver();
    // Old factors serve until GMRES has made `Factorisation reuse`
    // iterations with them in all, or fails within those left. When
    // the factors of the previous matrix fail, the next 1, 2, 4, ...
    // solves factorise at once. Old factors are not tried when fewer
    // iterations are left than the last solve with them needed (most
    // such tries ran out of budget). Counts, not times: the same run
    // takes the same path.
    if (reuse_iterations_left > 0 &&
        reuse_iterations_left >= last_reuse_iterations &&
        skipped_reuses >= reuses_to_skip &&
        (same_matrix ? mumps->has_factors()
                     : mumps->has_factors_for(A.trilinos_matrix())))
      {
        const bool fresh = reuse_iterations_left == settings.reuse_iterations;
        const unsigned int solves_before = mumps->statistics().solves;
        const unsigned int n             = solve_with_old_factors(
          A, x, b, weights, enough, reuse_iterations_left, true);
        if (n == 0)
          {
            ++failed_reuses;
            failed_reuse_solves += mumps->statistics().solves - solves_before;
          }
        if (n > 0)
          {
            reuse_iterations_left -= std::min(n, reuse_iterations_left);
            reuses_to_skip        = 0;
            last_reuse_iterations = n;
            return n;
          }
        // The matrix changes too fast for reuse now: back off. Older
        // factors may just be old.
        if (fresh)
          {
            reuses_to_skip = std::max(1u, 2 * reuses_to_skip);
            skipped_reuses = 0;
          }
      }
    else
      ++skipped_reuses;
    mumps->factorize(A.trilinos_matrix());
    reuse_iterations_left = settings.reuse_iterations;
    if (mumps->exact())
      {
        mumps->solve(x.trilinos_vector(), b.trilinos_vector());
        return 1;
      }
    // Single-precision factors of this matrix: GMRES to the tolerance,
    // within the reuse budget (one restart cycle if reuse is off).
    const unsigned int n =
      solve_with_old_factors(A,
                             x,
                             b,
                             weights,
                             enough,
                             std::max(settings.reuse_iterations, gmres_restart),
                             false);
    if (n > 0)
      {
        reuse_iterations_left -= std::min(n, reuse_iterations_left);
        return n;
      }
    // Too ill-conditioned for them: double-precision factors, exact.
    if (!fallback)
      fallback = std::make_unique<MumpsSolver>(comm,
                                               settings.factorisation,
                                               settings.ordering);
    fallback->factorize(A.trilinos_matrix());
    fallback->solve(x.trilinos_vector(), b.trilinos_vector());
    reuse_iterations_left = 0;
    return 1;
  }



  namespace
  {
    /**
     * Stops GMRES on old factors once it cannot make its budget: from the
     * 5th iteration on, if the residual, falling at the mean rate of the
     * last 5 iterations, would need more than twice the iterations left to
     * reach the tolerance. Such runs (the factors of a matrix that has
     * changed too much) reduce the residual by 1e1-1e2 in their first
     * iterations where the tolerance asks for 1e8, and ran out the whole
     * budget: on prm/sent_coarse.prm 51 runs spent 2623 of 6186 triangular
     * solves. With the rule 79 runs give up, after 860 solves in all (of
     * 4507), with 229 factorisations instead of 255; the same Newton
     * iterations and answers, 370 s instead of 410 (benchmarks/performance,
     * where the rules tried are compared on logged histories). The check
     * values are global norms, so every rank stops at the same iteration.
     */
    class ProjectedGmresControl : public SolverControl
    {
    public:
      ProjectedGmresControl(const unsigned int max_iterations,
                            const double       tolerance,
                            const bool         give_up_early)
          : SolverControl(max_iterations, tolerance, false, false)
          , give_up_early(give_up_early)
      {
      }

      State
      check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        history.push_back(value);
        constexpr unsigned int window = 5;
        if (state != iterate || !give_up_early || step < window ||
            history.size() <= window)
          return state;
        const double before = history[history.size() - 1 - window];
        if (!(value > 0.) || !(before > 0.))
          return state;
        const double rate   = std::pow(value / before, 1. / window);
        const double needed = rate < 1.
                                ? std::log(tolerance() / value) / std::log(rate)
                                : std::numeric_limits<double>::infinity();
        if (needed > 2. * (max_steps() - step))
          lcheck = failure;
        return lcheck;
      }

    private:
      const bool          give_up_early;
      std::vector<double> history;
    };
  } // namespace



  unsigned int
  DirectSolve::solve_with_old_factors(
    const TrilinosWrappers::SparseMatrix &A,
    TrilinosWrappers::MPI::Vector        &x,
    const TrilinosWrappers::MPI::Vector  &b,
    const TrilinosWrappers::MPI::Vector  *weights,
    const double                          enough,
    const unsigned int                    max_iterations,
    const bool                            give_up_early)
  {
    // The factors of an earlier matrix P as a right preconditioner of the
    // row-weighted system W A x = W b (W the diagonal of the weights, the
    // identity without them), as P W^-1: GMRES then tests the true
    // residual ||W (b - A x)||, and x is the solution of A x = b.
    // GMRES starts from r = b - A x with x = 0 here: the first product
    // with x is zero, not computed (one mat-vec per solve, ~2 % of
    // prm/block_on_plate.prm).
    struct WeightedMatrix
    {
      const TrilinosWrappers::SparseMatrix &A;
      const TrilinosWrappers::MPI::Vector  *weights;
      const TrilinosWrappers::MPI::Vector  *zero_start;
      mutable bool                          started = false;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        if (!started && &src == zero_start)
          {
            started = true;
            dst     = 0.;
            return;
          }
        started = true;
        A.vmult(dst, src);
        if (weights)
          dst.scale(*weights);
      }
    };
    struct OldFactors
    {
      MumpsSolver                          *mumps;
      const TrilinosWrappers::MPI::Vector  *inverse_weights;
      mutable TrilinosWrappers::MPI::Vector unweighted;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        if (!inverse_weights)
          {
            mumps->solve(dst.trilinos_vector(), src.trilinos_vector());
            return;
          }
        unweighted = src;
        unweighted.scale(*inverse_weights);
        mumps->solve(dst.trilinos_vector(), unweighted.trilinos_vector());
      }
    };
    TrilinosWrappers::MPI::Vector weighted_b, inverse_weights;
    if (weights)
      {
        weighted_b = b;
        weighted_b.scale(*weights);
        inverse_weights = *weights;
        for (auto &w : inverse_weights)
          w = 1. / w;
      }
    const TrilinosWrappers::MPI::Vector &rhs = weights ? weighted_b : b;
    ProjectedGmresControl                control(
      max_iterations,
      std::max(settings.relative_tolerance * rhs.l2_norm(), enough),
      give_up_early);
    const WeightedMatrix matrix{A, weights, &x};
    const OldFactors     factors{mumps.get(),
                             weights ? &inverse_weights : nullptr,
                                 {}};
    x = 0.;
    try
      {
        if (mumps->exact())
          {
            SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
              control,
              SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                gmres_restart, true));
            gmres.solve(matrix, x, rhs, factors);
          }
        else
          {
            // Single-precision triangular solves round their result, so
            // the preconditioner is not one fixed linear map: flexible
            // GMRES keeps the preconditioned vectors, and its residual
            // stays the true one.
            SolverFGMRES<TrilinosWrappers::MPI::Vector> fgmres(
              control,
              SolverFGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                gmres_restart));
            fgmres.solve(matrix, x, rhs, factors);
          }
      }
    catch (const SolverControl::NoConvergence &)
      {
        return 0;
      }
    return std::max(1u, control.last_step());
  }
} // namespace DuctileContact
