#pragma once

#include <deal.II/base/types.h>

#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/modules/physics_module.h>

#include <map>
#include <memory>
#include <vector>

namespace DuctileContact
{
  /// The physics modules a scene asks for, in the order they assemble: the
  /// mortar contact pairs (ContactProblem) if it has any. The one place
  /// that names them; everything else sees PhysicsModule.
  std::vector<std::unique_ptr<PhysicsModule>>
  make_physics_modules(
    const RunParameters  &parameters,
    const Discretisation &discretisation,
    const std::map<dealii::types::material_id, const BodyParameters *> &bodies);
} // namespace DuctileContact
