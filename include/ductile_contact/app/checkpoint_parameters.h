#pragma once

#include <deal.II/base/parameter_handler.h>

namespace DuctileContact
{
  /// Subsection `Checkpoint` (doc/output.md, "Checkpoints and resume").
  struct CheckpointParameters
  {
    /// Accepted load steps between checkpoints; 0: none.
    unsigned int interval = 0;
    /// How many complete checkpoints stay on disk (the newest ones).
    unsigned int keep = 2;

    void
    declare(dealii::ParameterHandler &prm);
  };
} // namespace DuctileContact
