#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <limits>

namespace DuctileContact
{
  /// What one progress line shows of an accepted step.
  struct StepProgress
  {
    unsigned int step              = 0;
    double       t                 = 0.;
    unsigned int newton_iterations = 0, linear_iterations = 0;
    double       rate = std::numeric_limits<double>::quiet_NaN();
    /// Alternations of a staggered step (0: none shown).
    unsigned int alternations = 0;
    /// Largest phase field (NaN: no body cracks).
    double max_s = std::numeric_limits<double>::quiet_NaN();
    double min_J = 1.;
    /// Wall time since the start of the run [s].
    double elapsed = 0.;
  };

  /**
   * The one line per accepted load step on screen: step k of about N,
   * time, Newton and linear iterations, the observed order, alternations
   * and max s where a body cracks, min J, the wall time so far and an
   * estimate of the time left (linear in the pseudo time).
   */
  class ProgressLine
  {
  public:
    ProgressLine(dealii::ConditionalOStream &out,
                 const double                end_time,
                 const unsigned int          n_steps);

    void
    print(const StepProgress &progress) const;

  private:
    dealii::ConditionalOStream &out;
    const double                end_time;
    const unsigned int          n_steps;
  };
} // namespace DuctileContact
