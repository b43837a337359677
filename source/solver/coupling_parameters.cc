#include <ductile_contact/solver/coupling_parameters.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  CouplingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    prm.add_parameter(
      "Strategy",
      strategy,
      "How the displacement/hardening fields and the phase field are solved "
      "together: monolithic (Newton with the exact coupled tangent) or "
      "staggered (alternate minimisation iterated to the Newton tolerances "
      "on every field).",
      Patterns::Selection("monolithic|staggered"));
    prm.add_parameter("Maximum staggered iterations",
                      max_staggered_iterations,
                      "Alternations per load step before the step is cut "
                      "back (staggered strategy only).",
                      Patterns::Integer(1, 100000));
    prm.leave_subsection();
  }



  void
  CouplingParameters::check() const
  {
  }
} // namespace DuctileContact
