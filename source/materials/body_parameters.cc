#include <deal.II/base/utilities.h>

#include <ductile_contact/core/input_error.h>
#include <ductile_contact/materials/body_parameters.h>

namespace DuctileContact
{
  using namespace dealii;

  std::string
  BodyParameters::subsection() const
  {
    return "Body " + Utilities::to_string(material_id);
  }



  void
  BodyParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection());
    prm.add_parameter("Name",
                      name,
                      "A name for the body, used on screen and in output.",
                      Patterns::Anything());
    prm.add_parameter("Shear modulus",
                      shear_modulus,
                      "Shear modulus mu of the neo-Hooke law, model.md (16) "
                      "[Pa].",
                      Patterns::Double(0.));
    prm.add_parameter("Bulk modulus",
                      bulk_modulus,
                      "Bulk modulus kappa of the neo-Hooke law, model.md (16) "
                      "[Pa].",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Plasticity",
      plasticity,
      "Whether this body yields (carries the hardening field alpha). Not "
      "available yet: the plasticity equations are issue #4.");
    prm.add_parameter(
      "Fracture",
      fracture,
      "Whether this body can crack (carries the phase field s). Not "
      "available yet: the phase-field equations are issue #3.");
    prm.leave_subsection();
  }



  void
  BodyParameters::check() const
  {
    const std::string prefix = subsection() + "/";
    check_input(shear_modulus > 0.,
                prefix + "Shear modulus",
                Utilities::to_string(shear_modulus),
                "it must be positive");
    check_input(bulk_modulus > 0.,
                prefix + "Bulk modulus",
                Utilities::to_string(bulk_modulus),
                "it must be positive");
    // The FE layout already carries alpha and s (see Discretisation), but
    // their equations do not exist yet: refuse rather than run a body whose
    // plasticity or fracture would silently do nothing.
    check_input(!plasticity,
                prefix + "Plasticity",
                "true",
                "plasticity is not implemented yet (issue #4); use false");
    check_input(!fracture,
                prefix + "Fracture",
                "true",
                "fracture is not implemented yet (issue #3); use false");
  }
} // namespace DuctileContact
