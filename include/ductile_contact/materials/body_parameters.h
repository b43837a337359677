#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>

namespace DuctileContact
{
  /**
   * One body of a scene: the cells with a given material_id, its material
   * parameters and the physics it carries. Subsection `Body <material id>`.
   *
   * Elastic law: compressible neo-Hooke, model.md (16) at s = 0 with shear
   * modulus mu and bulk modulus kappa [Pa].
   */
  struct BodyParameters
  {
    dealii::types::material_id material_id   = 0;
    std::string                name          = "body";
    double                     shear_modulus = 80.e9;
    double                     bulk_modulus  = 160.e9;

    /// Whether the body carries the hardening field alpha (plasticity).
    bool plasticity = false;
    /// Whether the body carries the crack phase field s (fracture).
    bool fracture = false;

    void
    declare(dealii::ParameterHandler &prm);

    /// Throws InputError for invalid or not yet supported values.
    void
    check() const;

    /// "Body <id>": the subsection name, used in messages.
    std::string
    subsection() const;
  };
} // namespace DuctileContact
