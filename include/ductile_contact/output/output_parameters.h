#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ductile_contact/core/types.h>

#include <string>
#include <vector>

namespace DuctileContact
{
  /// Subsection `Output`.
  struct OutputParameters
  {
    std::string  directory = "results";
    unsigned int interval  = 1;
    unsigned int verbosity = 1;
    /// Probe points as written in the input, and parsed by check().
    std::string                     probe_points_text;
    std::vector<dealii::Point<dim>> probe_points;

    void
    declare(dealii::ParameterHandler &prm);
    /// Checks the entries and parses Probe points.
    void
    check();
  };
} // namespace DuctileContact
