#include <ductile_contact/coupled/coupling_parameters.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  CouplingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    add_option(
      prm,
      "Strategy",
      strategy,
      coupling_strategy_names(),
      "How the displacement/hardening fields and the phase field are solved "
      "together: monolithic (Newton with the exact coupled tangent), "
      "staggered (alternate minimisation iterated to the Newton tolerances "
      "on every field), or monolithic-staggered (monolithic; a step where "
      "it fails is redone staggered before the step is cut back: past a "
      "limit point, e.g. when a crack runs unstably, there is no nearby "
      "equilibrium for Newton to find, while the alternation walks to the "
      "cracked state).");
    prm.add_parameter("Maximum staggered iterations",
                      max_staggered_iterations,
                      "Alternations per load step before the step is cut "
                      "back (staggered and monolithic-staggered).",
                      Patterns::Integer(1, 100000));
    prm.add_parameter(
      "Staggered acceleration depth",
      acceleration_depth,
      "Anderson acceleration of the staggered alternation: the phase field "
      "that the next (u, alpha) sub-solve starts from combines the last m+1 "
      "phase-field solves so as to minimise the change of s over an "
      "alternation (m = this depth; 0 = plain alternate minimisation). The "
      "converged state is the same; it only takes fewer alternations.",
      Patterns::Integer(0, 50));
    add_option(
      prm,
      "Irreversibility",
      irreversibility,
      irreversibility_names(),
      "How the crack is kept from healing (doc/model.md section 2). history: "
      "the "
      "crack driver uses the largest psi^+ a point has had (Miehe's history "
      "field); this keeps the driving force from falling but does not by "
      "itself keep s from falling (the gradient and bi-Laplacian terms of "
      "the neighbours act on it too). bound: s >= its value of the last "
      "accepted step at every phase-field DoF, by a primal-dual active set "
      "inside Newton's method (engaged when a converged state violates it; "
      "the rows of the DoFs on the bound carry the bound, their residual is "
      "the bound's reaction and must be >= 0), with the driver from the "
      "current psi^+. history and bound: both.");
    prm.leave_subsection();
  }



  void
  CouplingParameters::check() const
  {
  }
} // namespace DuctileContact
