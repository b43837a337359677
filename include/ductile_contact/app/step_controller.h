#pragma once

#include <ductile_contact/solver/solver_parameters.h>

#include <algorithm>

namespace DuctileContact
{
  /**
   * The load-step size of the quasi-static pseudo time (subsection `Load
   * stepping`): a failed step is repeated with half the increment
   * (cut-back); the increment grows by `Growth factor` after an easy step
   * (at most `Easy step Newton iterations`) or after `Growth after accepted
   * steps` accepted steps in a row at one increment, never beyond `Time
   * step`. A dynamic run's local error estimate may cut an increment back
   * by more and bound its growth (reject(), accept()).
   */
  class StepController
  {
  public:
    explicit StepController(const LoadSteppingParameters &parameters);

    /// The increment to try from time @p t.
    double
    next_increment(const double t) const;

    /// After the failed attempt @p dt_try from time @p t: the next try is
    /// @p factor times it (a half unless an error estimate asks for less);
    /// false when it would be below `Minimum time step` or the run stalls
    /// (stalled()).
    bool
    reject(const double t, const double dt_try, const double factor = 0.5);

    /// Whether `Maximum failures without progress` failed steps happened
    /// while t advanced by less than 1e-3 Time step.
    bool
    stalled() const
    {
      return parameters.max_stalled_failures > 0 &&
             stalled_failures >= parameters.max_stalled_failures;
    }

    /// The time at which the failures counted by stalled() began.
    double
    stall_time() const
    {
      return stall_start;
    }

    /// After the accepted step @p dt_try that took @p newton_iterations;
    /// the next increment is at most @p largest_factor times @p dt_try (an
    /// error estimate's bound).
    void
    accept(const double       dt_try,
           const unsigned int newton_iterations,
           const double       largest_factor);

    /// Cut-backs of the step being solved.
    unsigned int
    cutbacks() const
    {
      return n_cutbacks_of_step;
    }

    /// The increment after the last reject() or accept().
    double
    increment() const
    {
      return dt;
    }

    /// The controller's state (checkpoints). A loaded increment is capped
    /// at the current Time step (a resumed run may have lowered it).
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &dt &n_cutbacks_of_step &same_increment_steps &last_accepted_dt;
      ar &stall_start                                  &stalled_failures;
      if (Archive::is_loading::value)
        dt = std::min(dt, parameters.time_step);
    }

  private:
    const LoadSteppingParameters &parameters;
    double                        dt;
    unsigned int                  n_cutbacks_of_step   = 0;
    unsigned int                  same_increment_steps = 0;
    double                        last_accepted_dt     = 0.;
    /// Failed steps since stall_start within 1e-3 Time step of it.
    double       stall_start      = -1.;
    unsigned int stalled_failures = 0;
  };
} // namespace DuctileContact
