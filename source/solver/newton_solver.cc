#include <deal.II/lac/solver_control.h>

#include <ductile_contact/core/one_line.h>
#include <ductile_contact/solver/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace DuctileContact
{

  using namespace dealii;

  namespace
  {
    /// A section of the timer whose wall time is also added to @p total
    /// (NewtonSolver::times()).
    class TimedSection
    {
    public:
      TimedSection(TimerOutput &timer, const std::string &name, double &total)
          : scope(timer, name)
          , total(total)
          , start(MPI_Wtime())
      {
      }

      ~TimedSection()
      {
        total += MPI_Wtime() - start;
      }

      TimedSection(const TimedSection &) = delete;
      TimedSection &
      operator=(const TimedSection &) = delete;

    private:
      TimerOutput::Scope scope;
      double            &total;
      const double       start;
    };
  } // namespace

  NewtonSolver::NewtonSolver(const NewtonParameters &parameters,
                             LinearSolver           &linear_solver,
                             const NewtonMonitor    &monitor)
      : parameters(parameters)
      , linear_solver(linear_solver)
      , monitor(monitor)
  {
  }



  NewtonSolver::Norms
  NewtonSolver::tolerances(const ResidualEvaluation &evaluation) const
  {
    Norms tol(evaluation.norms.size());
    for (unsigned int b = 0; b < tol.size(); ++b)
      tol[b] = parameters.relative_tolerance * evaluation.relative_scale[b] +
               parameters.absolute_tolerance * evaluation.absolute_scale[b];
    return tol;
  }



  double
  NewtonSolver::merit(const Norms &norms, const Norms &tolerances)
  {
    // The norms in units of the tolerances; blocks without a tolerance
    // (no unknowns) do not count.
    double sum = 0;
    for (unsigned int b = 0; b < norms.size(); ++b)
      if (tolerances[b] > 0.)
        sum += (norms[b] / tolerances[b]) * (norms[b] / tolerances[b]);
    return std::sqrt(sum);
  }



  void
  NewtonSolver::print(const NonlinearProblem   &problem,
                      const unsigned int        iteration,
                      const ResidualEvaluation &evaluation,
                      const bool                pending) const
  {
    const Norms  &n     = evaluation.norms;
    const double  scale = evaluation.relative_scale[0];
    std::ostream &out   = monitor.out.get_stream();
    if (!monitor.out.is_active())
      return;
    out << "      Newton " << std::setw(2) << iteration
        << ": |R| = " << std::scientific << std::setprecision(3) << n[0]
        << ", |R|/|f_int| = " << (scale > 0 ? n[0] / scale : 0.);
    if (problem.n_nonempty_blocks() > 1)
      {
        const Norms                    tol   = tolerances(evaluation);
        const std::vector<std::string> names = problem.block_names();
        out << "; in tolerances:";
        for (unsigned int b = 0; b < n.size(); ++b)
          if (problem.block_solved(b))
            out << " " << names[b] << " " << n[b] / tol[b];
      }
    const std::string state = problem.describe();
    if (!state.empty())
      out << "; " << state;
    // Points whose branch (e.g. loading or yielding) the state contradicts:
    // the next line is then the residual with the state's own branches.
    if (evaluation.branch_changes > 0)
      out << "; branches of the last tangent differ at "
          << evaluation.branch_changes << " points";
    out << (pending ? ", Dirichlet data pending" : "") << std::defaultfloat
        << std::endl;
  }



  bool
  NewtonSolver::converged(NonlinearProblem         &problem,
                          const Vector             &x,
                          const ResidualEvaluation &evaluation,
                          NewtonReport             &report) const
  {
    const Norms &n = evaluation.norms;
    report.residual_norms.push_back(merit(n, reference));
    const Norms tol = tolerances(evaluation);
    for (unsigned int b = 0; b < n.size(); ++b)
      if (n[b] > tol[b])
        return false;
    if (!problem.converged(x, tol))
      {
        // The equations changed: the rate is that of the iterations after.
        report.residual_norms.clear();
        return false;
      }
    report.converged = true;

    // The observed order from the last three merits above the round-off
    // floor: a residual at that floor says nothing about the rate, so the
    // rate stays undefined (nan) when fewer than three lie above it.
    const double floor = merit(evaluation.round_off, reference);
    const auto  &h     = report.residual_norms;
    std::size_t  k     = h.size();
    while (k >= 3 && h[k - 1] <= floor)
      --k;
    if (k >= 3 && h[k - 1] > 0 && h[k - 2] > 0 && h[k - 3] > 0 &&
        h[k - 2] != h[k - 3])
      report.convergence_rate =
        std::log(h[k - 1] / h[k - 2]) / std::log(h[k - 2] / h[k - 3]);
    return true;
  }



  double
  NewtonSolver::tangent_error(NonlinearProblem          &problem,
                              const Vector              &x,
                              const std::vector<double> &round_off)
  {
    Vector k_delta = problem.system_rhs();
    problem.compared_product(delta, k_delta);
    const double size     = delta.linfty_norm();
    const double k_d_norm = k_delta.l2_norm();
    if (!(size > 0.) || !(k_d_norm > 0.))
      return std::numeric_limits<double>::quiet_NaN();
    // Each residual carries about |round_off| of round-off, which the
    // quotient divides by 2e: its share of the ratio is below
    // |round_off| / (e |K d|). Near convergence |K d| is many orders below
    // the terms summed into R, and a step of 1e-6 the size of x measures
    // that round-off (1e-3 and more on the paper's scene), not the
    // tangent; a longer step meets more kinks that no frozen branch
    // removes (mortar segments changing shape) and more of R's curvature.
    // So the quotients are taken with steps of 1e-6, 1e-5, ... of |x| until
    // the round-off share is below 1e-5 (at most 1e-3 of |x|), and the
    // smallest error counts: a wrong tangent shows at every step.
    double round_off_norm = 0.;
    for (const double r : round_off)
      round_off_norm += r * r;
    round_off_norm      = std::sqrt(round_off_norm);
    const double x_size = std::max(x.linfty_norm(), size);
    // R at x + k e d for k = 1, -1, 2, -2; the central quotients of
    // second order, (R_1 - R_-1) / 2e, and fourth, (8 (R_1 - R_-1) - (R_2 -
    // R_-2)) / 12e: the second meets fewer kinks, the fourth less of R's
    // curvature, so both count.
    const auto errors_at = [&](const double e, Vector &second, Vector &fourth) {
      Vector r = k_delta;
      second   = 0.;
      fourth   = 0.;
      for (const double k : {1., -1., 2., -2.})
        {
          Vector trial = x;
          trial.add(k * e, delta);
          problem.compared_residual(trial, r);
          const double sign = k > 0. ? 1. : -1.;
          if (std::abs(k) < 1.5)
            {
              second.add(sign / (2. * e), r);
              fourth.add(sign * 8. / (12. * e), r);
            }
          else
            fourth.add(-sign / (12. * e), r);
        }
      second -= k_delta;
      fourth -= k_delta;
      return std::make_pair(second.l2_norm() / k_d_norm,
                            fourth.l2_norm() / k_d_norm);
    };
    std::ostringstream text;
    text << std::scientific << std::setprecision(2);
    double error = std::numeric_limits<double>::infinity();
    Vector best = k_delta, second = k_delta, fourth = k_delta;
    for (double relative_step = 1e-6; relative_step < 1.5e-3;
         relative_step *= 10.)
      {
        const double e                = relative_step * x_size / size;
        const auto [error_2, error_4] = errors_at(e, second, fourth);
        text << (relative_step > 1.5e-6 ? ", " : "at steps ") << relative_step
             << ": " << error_2 << " / " << error_4;
        for (const auto &[error_e, difference] :
             {std::make_pair(error_2, &second),
              std::make_pair(error_4, &fourth)})
          if (error_e < error || std::isnan(error_e))
            {
              error = error_e;
              best  = *difference;
            }
        if (round_off_norm / (e * k_d_norm) <= 1e-5 || std::isnan(error))
          break;
      }
    text << " of |x| (second / fourth order); the smallest";
    // By block as well: rows of small absolute size hide their errors in
    // the global ratio.
    const std::vector<std::string> names = problem.block_names();
    text << ", by block:";
    for (unsigned int b = 0; b < k_delta.n_blocks(); ++b)
      if (k_delta.block(b).size() > 0)
        text << " " << names[b] << " "
             << best.block(b).l2_norm() /
                  std::max(k_delta.block(b).l2_norm(),
                           std::numeric_limits<double>::min());
    monitor.out << "        tangent check: |K d - dR/de| / |K d| = "
                << std::scientific << std::setprecision(2) << error << " ("
                << text.str() << ")" << std::defaultfloat << std::endl;
    return error;
  }



  SolveAccuracy
  NewtonSolver::linear_accuracy(const NonlinearProblem &problem,
                                const Norms            &tolerances) const
  {
    SolveAccuracy accuracy;
    if (parameters.linear_accuracy != LinearAccuracy::newton_tolerances)
      return accuracy;
    // The residual in units of the tolerances, as the merit measures it; a
    // block with DoFs but no tolerance leaves the relative one alone.
    const Vector &rhs = problem.system_rhs();
    accuracy.block_weights.resize(tolerances.size(), 0.);
    for (unsigned int b = 0; b < tolerances.size(); ++b)
      if (rhs.block(b).size() > 0)
        {
          if (!(tolerances[b] > 0.))
            return {};
          accuracy.block_weights[b] = 1. / tolerances[b];
        }
    accuracy.enough = linear_fraction_of_tolerance;
    return accuracy;
  }



  bool
  NewtonSolver::line_search(NonlinearProblem   &problem,
                            Vector             &x,
                            const Norms        &norms,
                            const Norms        &tol,
                            const bool          pending,
                            double             &step_length,
                            ResidualEvaluation &trial_evaluation)
  {
    // Shorten while the state is not admissible or, once the prescribed
    // values are reached, while the merit does not fall below the largest
    // of the last iterations' (Line search memory; recent_norms ends with
    // `norms`). The residual of the accepted state also decides
    // convergence, so a converged step never assembles a tangent it does
    // not use.
    double r = merit(norms, tol);
    for (const Norms &n : recent_norms)
      r = std::max(r, merit(n, tol));
    step_length = 1.;
    for (unsigned int ls = 0; ls <= parameters.max_line_search_steps;
         ++ls, step_length *= 0.5)
      {
        Vector trial = x;
        trial.add(step_length, delta);
        {
          TimedSection scope(monitor.timer,
                             "assembly (line search)",
                             spent.assembly);
          trial_evaluation = problem.assemble_residual(trial);
        }
        const Norms &trial_n   = trial_evaluation.norms;
        const double trial_r   = merit(trial_n, tol);
        const bool   decreases = pending || !parameters.line_search ||
                               trial_r <= (1. - 1e-4 * step_length) * r;
        if (trial_evaluation.admissible && std::isfinite(trial_r) && decreases)
          {
            x = trial;
            return true;
          }
        const bool admissible = trial_evaluation.admissible;
        monitor.out << "        line search: step " << step_length
                    << (!admissible ? " " + trial_evaluation.inadmissible
                                    : " does not reduce |R| (merit ratio " +
                                        std::to_string(trial_r / r) + ";")
                    << std::scientific << std::setprecision(2);
        if (admissible)
          for (unsigned int b = 0; b < norms.size(); ++b)
            if (tol[b] > 0. && norms[b] > 0.)
              monitor.out << " " << problem.block_names()[b] << " "
                          << trial_n[b] / norms[b];
        monitor.out << (!admissible ? "" : " by block)") << std::defaultfloat
                    << std::endl;
      }
    return false;
  }



  std::size_t
  NewtonSolver::best_start(NonlinearProblem                  &problem,
                           const std::vector<const Vector *> &starts)
  {
    problem.begin_solve();
    std::size_t        best       = 0;
    double             best_merit = std::numeric_limits<double>::infinity();
    std::ostringstream merits;
    for (std::size_t i = 0; i < starts.size(); ++i)
      {
        problem.begin_iteration(*starts[i]);
        ResidualEvaluation evaluation;
        {
          TimerOutput::Scope scope(monitor.timer, "assembly (first guess)");
          evaluation = problem.assemble_right_hand_side(*starts[i]);
        }
        const double m = evaluation.admissible
                           ? merit(evaluation.norms, tolerances(evaluation))
                           : std::numeric_limits<double>::infinity();
        merits << (i == 0 ? "" : ", ") << m;
        if (m < best_merit)
          {
            best       = i;
            best_merit = m;
          }
      }
    monitor.out << "      first guesses: merits " << merits.str()
                << "; starting from guess " << best + 1 << std::endl;
    return best;
  }



  std::string
  NewtonSolver::solve_for_update(NonlinearProblem &problem,
                                 const Norms      *fast_tolerances,
                                 const bool        chord,
                                 unsigned int     &n_linear)
  {
    try
      {
        TimedSection scope(monitor.timer, "linear solve", spent.solve);
        delta = 0;
        n_linear =
          linear_solver.solve(problem.system_matrix(),
                              delta,
                              problem.system_rhs(),
                              fast_tolerances != nullptr &&
                                  problem.keeps_tangent()
                                ? linear_accuracy(problem, *fast_tolerances)
                                : SolveAccuracy(),
                              chord,
                              problem.constrained_rows());
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream s;
        s << "the iterative linear solver did not converge in " << e.last_step
          << " iterations (residual " << e.last_residual << ")";
        return s.str();
      }
    catch (const std::exception &e)
      {
        return "the linear solver failed: " + one_line(e.what());
      }
    problem.distribute(delta);
    if (!std::isfinite(delta.l2_norm()))
      return "the linear solve returned an update that is not finite (NaN "
             "or Inf)";
    return "";
  }



  bool
  NewtonSolver::accepts_branch_cycle(NonlinearProblem         &problem,
                                     const Vector             &x,
                                     const ResidualEvaluation &trial,
                                     unsigned int &conflicting_points,
                                     NewtonReport &report) const
  {
    // A state that meets the tolerances with its tangent's branches while
    // its own differ at some points, for the second time in the step at as
    // many points: Newton alternates between the branches of points on
    // their switch, where no state agrees with either. It is accepted as
    // solved (doc/model.md section 6.2).
    if (trial.branch_changes == 0)
      return false;
    const Norms tol = tolerances(trial);
    for (unsigned int b = 0; b < tol.size(); ++b)
      if (trial.norms[b] > tol[b])
        return false;
    if (trial.branch_changes != conflicting_points)
      {
        conflicting_points = trial.branch_changes;
        return false;
      }
    if (!converged(problem, x, trial, report))
      return false;
    monitor.out << "        the branches alternate at " << conflicting_points
                << " points on their switch: the state that meets the "
                   "tolerances with its tangent's branches is accepted"
                << std::endl;
    report.branch_conflicts = conflicting_points;
    return true;
  }



  NewtonReport
  NewtonSolver::solve(NonlinearProblem &problem, Vector &x)
  {
    NewtonReport report;
    problem.begin_solve();
    delta.reinit(problem.system_rhs(), true);

    // Whether the last accepted state was reached with frozen branches that
    // its own state contradicts: its residual is then not the true one,
    // which the next assembly computes.
    bool branches_changed = false;
    // Whether this iteration keeps the last tangent (Tangent update).
    bool chord = false;
    // Whether the last update was a full step that cut the merit 10-fold,
    // or there was none yet: Newton's fast phase, where the linear solves
    // may stop early (Linear solve accuracy); in a damped or slow phase,
    // and while the problem's rows follow the iterate (keeps_tangent()
    // false: the phase-field bound's active set), they go to the relative
    // tolerance. prm/sent_coarse.prm's crack phase stalled without either
    // rule (benchmarks/performance/results.md).
    bool fast = true;
    // Points that disagreed with the branches of a state that met the
    // tolerances with them (0: none such state yet in this step).
    unsigned int conflicting_points = 0;
    for (unsigned int it = 0;; ++it)
      {
        const bool         pending = problem.begin_iteration(x);
        ResidualEvaluation evaluation;
        {
          TimedSection scope(monitor.timer, "assembly", spent.assembly);
          evaluation = chord ? problem.assemble_right_hand_side(x)
                             : problem.assemble_system(x);
        }
        Norms       n   = evaluation.norms;
        const Norms tol = tolerances(evaluation);
        double      r   = merit(n, tol);
        if (it == 0)
          reference = tol;
        report.iterations = it;
        if (it == 0 || branches_changed)
          print(problem, it, evaluation, pending);
        if (!evaluation.admissible)
          {
            report.failure = evaluation.inadmissible;
            return report;
          }
        if (!std::isfinite(r))
          {
            report.failure = "residual is not finite";
            return report;
          }
        // From the second iteration on, convergence is decided right after
        // the line search; only the start of a step is checked here.
        if ((it == 0 || branches_changed) && !pending &&
            converged(problem, x, evaluation, report))
          return report;
        if (chord && !problem.keeps_tangent())
          {
            // converged() changed the equations here: their tangent.
            TimedSection scope(monitor.timer, "assembly", spent.assembly);
            evaluation = problem.assemble_system(x);
            chord      = false;
          }
        if (chord)
          monitor.out << "        chord step: the last tangent kept"
                      << std::endl;
        n = problem.modify_linear_system(x);
        r = merit(n, tol);
        if (it == 0)
          recent_norms.clear();
        recent_norms.push_back(n);
        while (recent_norms.size() > parameters.line_search_memory)
          recent_norms.pop_front();

        unsigned int n_linear = 0;
        report.failure =
          solve_for_update(problem, fast ? &tol : nullptr, chord, n_linear);
        report.linear_iterations += n_linear;
        if (!report.failure.empty())
          return report;
        if (parameters.check_tangent && !pending && !chord)
          report.tangent_error =
            tangent_error(problem, x, evaluation.round_off);

        double             step_length = 1.;
        ResidualEvaluation trial;
        if (!line_search(problem, x, n, tol, pending, step_length, trial))
          {
            if (chord)
              {
                // The kept tangent leads nowhere here: a full iteration
                // from the same state before the step counts as failed.
                monitor.out << "        chord step failed: a full iteration"
                            << std::endl;
                chord = false;
                continue;
              }
            report.failure =
              "line search found no admissible step" +
              (trial.admissible ? std::string() : ": " + trial.inadmissible);
            return report;
          }
        monitor.out << "        linear iterations " << n_linear
                    << (step_length < 1
                          ? ", step length " + std::to_string(step_length)
                          : std::string())
                    << std::endl;

        const bool still_pending = pending && step_length < 1.;
        print(problem, it + 1, trial, still_pending);
        report.iterations        = it + 1;
        branches_changed         = trial.branch_changes > 0;
        const double trial_merit = merit(trial.norms, tol);
        const bool   full_step   = !still_pending && step_length == 1.;
        fast                     = full_step && 10. * trial_merit <= r;
        // After a full Newton step that reduced the merit 100-fold, its
        // tangent serves the next iteration too, and the one after while
        // each such chord step reduces the merit 10-fold.
        chord = parameters.tangent_update == TangentUpdate::chord &&
                full_step && (chord ? 10. : 100.) * trial_merit <= r &&
                problem.keeps_tangent();
        if (!still_pending && !branches_changed &&
            converged(problem, x, trial, report))
          return report;
        if (!still_pending &&
            accepts_branch_cycle(problem, x, trial, conflicting_points, report))
          return report;
        if (it + 1 == parameters.max_iterations)
          {
            report.failure = "no convergence in " + std::to_string(it + 1) +
                             " Newton iterations";
            return report;
          }
      }
  }
} // namespace DuctileContact
