#include <ductile_contact/app/step_controller.h>

#include <algorithm>

namespace DuctileContact
{
  StepController::StepController(const LoadSteppingParameters &parameters)
      : parameters(parameters)
      , dt(parameters.time_step)
  {
  }



  double
  StepController::next_increment(const double t) const
  {
    return std::min(dt, parameters.end_time - t);
  }



  bool
  StepController::reject(const double t,
                         const double dt_try,
                         const double factor)
  {
    dt = factor * dt_try;
    ++n_cutbacks_of_step;
    if (stalled_failures == 0 || t - stall_start > 1.e-3 * parameters.time_step)
      {
        stall_start      = t;
        stalled_failures = 0;
      }
    ++stalled_failures;
    return dt >= parameters.minimum_time_step && !stalled();
  }



  void
  StepController::accept(const double       dt_try,
                         const unsigned int newton_iterations,
                         const double       largest_factor)
  {
    // A run of accepted steps at one increment; a cut-back or a change of
    // the increment starts a new run.
    same_increment_steps =
      (n_cutbacks_of_step == 0 && dt_try == last_accepted_dt)
        ? same_increment_steps + 1
        : 1;
    last_accepted_dt   = dt_try;
    n_cutbacks_of_step = 0;
    if (newton_iterations <= parameters.easy_newton_steps ||
        (parameters.steps_before_growth > 0 &&
         same_increment_steps >= parameters.steps_before_growth))
      {
        dt = std::min(dt_try * parameters.growth_factor, parameters.time_step);
        same_increment_steps = 0;
      }
    else
      dt = dt_try;
    dt = std::min(dt, largest_factor * dt_try);
  }
} // namespace DuctileContact
