#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <ductile_contact/solver/linear_solver.h>
#include <ductile_contact/solver/nonlinear_problem.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <deque>
#include <limits>
#include <string>
#include <vector>

namespace DuctileContact
{
  /// Outcome of one Newton solve.
  struct NewtonReport
  {
    bool         converged         = false;
    unsigned int iterations        = 0;
    unsigned int linear_iterations = 0;
    /// Merit of the iterations whose prescribed values were reached (since
    /// the problem last changed its equations, NonlinearProblem::converged).
    std::vector<double> residual_norms;
    /// Observed order log(r_k+1/r_k)/log(r_k/r_k-1) of the last three
    /// residuals (2 = quadratic); NaN if fewer than three are meaningful.
    double convergence_rate = std::numeric_limits<double>::quiet_NaN();
    /// Relative tangent error of the last Newton update that was checked
    /// (Newton/Check tangent): the one nearest the solution.
    double      tangent_error = std::numeric_limits<double>::quiet_NaN();
    std::string failure;
    /// Points whose own branch differs from the one the accepted state was
    /// solved with (0 unless the state was accepted on a branch cycle,
    /// NewtonSolver::solve()).
    unsigned int branch_conflicts = 0;
  };

  /// Where Newton reports: detail lines (verbosity 2) and its timer
  /// sections ("assembly", "assembly (line search)", "linear solve").
  struct NewtonMonitor
  {
    dealii::ConditionalOStream &out;
    dealii::TimerOutput        &timer;
  };

  /// Wall time Newton's iterations have spent, summed over its solves [s]:
  /// the assemblies (those of the line search included) and the linear
  /// solves (also in the timer's sections "assembly", "assembly (line
  /// search)" and "linear solve").
  struct NewtonTimes
  {
    double assembly = 0., solve = 0.;
  };

  /**
   * Newton's method for R(x) = 0 on a NonlinearProblem, with the
   * prescribed values imposed through the update (so a shortened step
   * still reaches them) and a backtracking line search on the merit
   *
   *   m = sqrt(sum_b (||R_b|| / tol_b)^2),
   *
   * tol_b the block tolerances of ResidualEvaluation. A trial state that is
   * not admissible (an inverted element) is always shortened.
   *
   * Converged when the prescribed values are reached, every block meets
   * its tolerance and the problem accepts the state
   * (NonlinearProblem::converged). Along the line search the branches of
   * non-smooth terms are those of the iterate (R is smooth along the
   * line); a converged state whose own branches differ is assembled again
   * before it is accepted.
   */
  class NewtonSolver
  {
  public:
    using Vector = NonlinearProblem::Vector;

    NewtonSolver(const NewtonParameters &parameters,
                 LinearSolver           &linear_solver,
                 const NewtonMonitor    &monitor);

    /// Solves from @p x (owned entries); on success @p x is the solution.
    /// On failure @p x is unspecified: the caller restores its copy.
    NewtonReport
    solve(NonlinearProblem &problem, Vector &x);

    /// Of the first guesses @p starts (one problem, the same prescribed
    /// values), the index of the one with the smallest merit (the merit
    /// Newton's first iteration from it would see; an inadmissible state
    /// has an infinite one); the first on a tie. One residual assembly per
    /// guess.
    /// The wall time spent so far.
    const NewtonTimes &
    times() const
    {
      return spent;
    }

    std::size_t
    best_start(NonlinearProblem                  &problem,
               const std::vector<const Vector *> &starts);

  private:
    using Norms = std::vector<double>;

    /// Records the merit of a state whose prescribed values are reached and
    /// returns whether it is converged; then also the observed order.
    bool
    converged(NonlinearProblem         &problem,
              const Vector             &x,
              const ResidualEvaluation &evaluation,
              NewtonReport             &report) const;

    /// Solves the Newton system into #delta (with the problem's
    /// constraints distributed), to the accuracy of Newton's fast phase if
    /// @p fast_tolerances (the block tolerances) is given, else to the
    /// linear solver's relative tolerance; @p chord: the matrix is the last
    /// one. Returns why it failed ("" if it did not); @p n_linear is the
    /// linear iterations.
    std::string
    solve_for_update(NonlinearProblem &problem,
                     const Norms      *fast_tolerances,
                     bool              chord,
                     unsigned int     &n_linear);

    /// Whether the state of @p trial (evaluated with its tangent's
    /// branches) is accepted on a branch cycle: it meets the tolerances
    /// while its own branches differ at as many points as at the last such
    /// state of the step (@p conflicting_points, updated), and converged()
    /// holds; then report.branch_conflicts is that number.
    bool
    accepts_branch_cycle(NonlinearProblem         &problem,
                         const Vector             &x,
                         const ResidualEvaluation &trial,
                         unsigned int             &conflicting_points,
                         NewtonReport             &report) const;

    /// Backtracking along #delta from @p x; on success @p x is the
    /// accepted trial and @p trial its evaluation. The merit of a trial is
    /// compared with the largest of #recent_norms' (Line search memory).
    bool
    line_search(NonlinearProblem   &problem,
                Vector             &x,
                const Norms        &norms,
                const Norms        &tolerances,
                const bool          pending,
                double             &step_length,
                ResidualEvaluation &trial);

    /// Newton/Check tangent: |K delta - dR/de| / |K delta| on the compared
    /// rows, dR/de by central quotients of second and fourth order with e
    /// delta of 1e-6, 1e-5, ... the size of x, until the residual's
    /// round-off (@p round_off, by block, of the assembly at x) falls below
    /// 1e-5 of e |K delta| (at most 1e-3 the size of x); the smallest error.
    double
    tangent_error(NonlinearProblem          &problem,
                  const Vector              &x,
                  const std::vector<double> &round_off);

    Norms
    tolerances(const ResidualEvaluation &evaluation) const;

    /// Newton/Linear solve accuracy: with `newton tolerances`, the linear
    /// solve may stop once its residual, in units of @p tolerances (the
    /// merit's norm), is below #linear_fraction_of_tolerance.
    SolveAccuracy
    linear_accuracy(const NonlinearProblem &problem,
                    const Norms            &tolerances) const;

    /// The update's own error then adds at most this to the merit of the
    /// next iterate, whose convergence test asks for 1 per block.
    static constexpr double linear_fraction_of_tolerance = 0.1;

    static double
    merit(const Norms &norms, const Norms &tolerances);

    void
    print(const NonlinearProblem   &problem,
          const unsigned int        iteration,
          const ResidualEvaluation &evaluation,
          const bool                pending) const;

    const NewtonParameters &parameters;
    LinearSolver           &linear_solver;
    NewtonMonitor           monitor;
    NewtonTimes             spent;
    /// Residual norms at the start of the last Newton iterations of the
    /// step, at most Line search memory of them (the newest last).
    std::deque<Norms> recent_norms;

    /// Merit tolerances of the first iterate of the solve (ratios of the
    /// recorded merits are then meaningful).
    Norms  reference;
    Vector delta;
  };
} // namespace DuctileContact
