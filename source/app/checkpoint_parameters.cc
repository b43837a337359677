#include <ductile_contact/app/checkpoint_parameters.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  CheckpointParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.add_parameter(
      "Interval",
      interval,
      "Write a checkpoint every this many accepted load steps (into "
      "Output/Directory/checkpoints); 0: never. 'ductile-contact --resume "
      "FILE.prm' continues from the newest complete one, on any number of "
      "ranks. A SIGTERM or SIGINT also writes one (after the current step) "
      "when this is above 0.",
      Patterns::Integer(0));
    prm.add_parameter("Keep",
                      keep,
                      "How many of the newest complete checkpoints are kept; "
                      "older ones are deleted.",
                      Patterns::Integer(1));
    prm.leave_subsection();
  }
} // namespace DuctileContact
