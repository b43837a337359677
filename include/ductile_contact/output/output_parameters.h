#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DuctileContact
{
  /// Subsection `Output`.
  struct OutputParameters
  {
    std::string  directory = "results";
    unsigned int interval  = 1;
    unsigned int verbosity = 1;

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };
} // namespace DuctileContact
