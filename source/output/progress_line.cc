#include <ductile_contact/output/progress_line.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <string>

namespace DuctileContact
{
  ProgressLine::ProgressLine(dealii::ConditionalOStream &out,
                             const double                end_time,
                             const unsigned int          n_steps)
      : out(out)
      , end_time(end_time)
      , n_steps(n_steps)
  {
  }



  void
  ProgressLine::print(const StepProgress &p) const
  {
    const double T = end_time;
    out << "step " << std::setw(4) << p.step << " (~" << p.step << "/"
        << std::max(n_steps, p.step) << ")  t = " << std::setw(10) << std::left
        << p.t << std::right << " Newton " << std::setw(2)
        << p.newton_iterations << " (linear " << p.linear_iterations << ")";
    if (std::isfinite(p.rate))
      out << " rate " << std::fixed << std::setprecision(2) << p.rate
          << std::defaultfloat << std::setprecision(6);
    if (!std::isnan(p.max_s))
      out << (p.alternations > 0
                ? "  alternations " + std::to_string(p.alternations)
                : std::string())
          << "  max s " << std::setprecision(3) << p.max_s
          << std::setprecision(6);
    out << "  min J " << std::setprecision(4) << p.min_J << std::setprecision(6)
        << "  " << std::fixed << std::setprecision(1) << p.elapsed << " s, ~"
        << p.elapsed / p.t * (T - p.t) << " s left" << std::defaultfloat
        << std::setprecision(6) << std::endl;
  }
} // namespace DuctileContact
