#pragma once
// The contact history of an impact run, from its statistics: shared by
// dynamics_bar_impact.cc and dynamics_rigid_bounce.cc.
#include "tests.h"

#include <cmath>

namespace Testing
{
  /// When contact pair 1 closed and opened, and what it carried.
  struct ContactEvents
  {
    unsigned int closings = 0, openings = 0;
    /// The start times of the steps in which the contact closed and opened
    /// (the last of each).
    double closed = 0., opened = 0.;
    /// The last step that ends at or before #opened.
    std::size_t release = 0;
    /// Mean |contact1_force_z| over the steps ending more than @p margin
    /// after #closed and before #opened.
    double mean_force = 0.;
  };

  inline ContactEvents
  contact_events(const Table &stats, const double margin)
  {
    const auto   &t      = stats.at("time");
    const auto   &active = stats.at("contact1_active_nodes");
    const auto   &force  = stats.at("contact1_force_z");
    ContactEvents e;
    for (std::size_t s = 1; s < t.size(); ++s)
      {
        if (active[s] > 0 && active[s - 1] == 0)
          {
            ++e.closings;
            e.closed = t[s - 1];
          }
        if (active[s] == 0 && active[s - 1] > 0)
          {
            ++e.openings;
            e.opened = t[s - 1];
          }
      }
    double       sum = 0.;
    unsigned int n   = 0;
    for (std::size_t s = 0; s < t.size(); ++s)
      {
        if (t[s] > e.closed + margin && t[s] < e.opened - margin)
          {
            sum += std::abs(force[s]);
            ++n;
          }
        if (t[s] <= e.opened)
          e.release = s;
      }
    e.mean_force = sum / n;
    return e;
  }

  /// The mean rate of @p column from step @p from to the last step.
  inline double
  mean_rate_after(const Table       &stats,
                  const std::string &column,
                  const std::size_t  from)
  {
    const auto &t = stats.at("time");
    const auto &c = stats.at(column);
    return (c.back() - c[from]) / (t.back() - t[from]);
  }
} // namespace Testing
