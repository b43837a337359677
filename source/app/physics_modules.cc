#include <ductile_contact/app/physics_modules.h>
#include <ductile_contact/contact/contact_problem.h>

namespace DuctileContact
{
  std::vector<std::unique_ptr<PhysicsModule>>
  make_physics_modules(
    const RunParameters  &parameters,
    const Discretisation &discretisation,
    const std::map<dealii::types::material_id, const BodyParameters *> &bodies)
  {
    std::vector<std::unique_ptr<PhysicsModule>> modules;
    if (!parameters.contact_pairs.empty())
      modules.push_back(std::make_unique<ContactProblem>(
        parameters.contact_pairs, discretisation, bodies));
    return modules;
  }
} // namespace DuctileContact
