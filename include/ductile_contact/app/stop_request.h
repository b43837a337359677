#pragma once

#include <deal.II/base/mpi.h>

namespace DuctileContact
{
  /**
   * SIGTERM (a scheduler's time limit) and SIGINT (Ctrl-C) do not end a run
   * at once: the handlers installed here only note the signal, and the
   * load-step loop ends the run after the step it is in, with a checkpoint
   * when checkpoints are on and its output (exit code 3, doc/output.md).
   * A second signal of the same kind ends the process at once.
   */
  void
  install_stop_handlers();

  /// Whether a stop signal reached any rank (collective).
  bool
  stop_requested(const MPI_Comm comm);
} // namespace DuctileContact
