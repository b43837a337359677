#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <ductile_contact/core/expression.h>
#include <ductile_contact/materials/crack_driver.h>
#include <ductile_contact/materials/plasticity.h>
#include <ductile_contact/phase_field/regularisation.h>

#include <string>

namespace DuctileContact
{
  /**
   * Crack phase-field parameters of a body (doc/model.md section 4, (3) and
   * (51)), subsection `Body <id>/Fracture`. SI units.
   */
  struct FractureParameters
  {
    /// g_c: critical energy release rate [J/m^2].
    double critical_energy_release_rate = 2.7e3;
    /// l_f: regularisation length of gamma (3) [m].
    double length_scale = 7.5e-6;
    /// The crack density gamma: the paper's fourth-order (3) or AT2.
    Regularisation regularisation = Regularisation::fourth_order;
    /// The split (17) of an elastic body's energy, or none.
    EnergySplit split = EnergySplit::volumetric_deviatoric;
    /// eta_f: viscosity of (51) [J/m^3 times pseudo time].
    double viscosity = 0.;
    /// a_g of the degradation g(s); 2 gives g = (1 - s)^2.
    double degradation_a = MaterialDefaults::degradation_a;
    /// k of g_k(s) = (1 - k) g(s) + k.
    double residual_stiffness = MaterialDefaults::residual_stiffness;
    /// gamma_IP of the C0IP face terms; 0 selects 1.5 p (p + 1).
    double interior_penalty = 0.;
    /// delta: half-width in J of the smoothed tension/compression switch
    /// of the split (17) (bodies with plasticity; 0: the sharp switch).
    double volumetric_switch_width = MaterialDefaults::volumetric_switch_width;
    /// The energy that drives the crack (crack_driving_energy()).
    CrackDriverType driver = CrackDriverType::elastic;
    /// w_c and zeta of the elastic-plus-plastic driver.
    PlasticWorkDriver work_driver;
    /// s at the start as an expression of the reference coordinates x, y,
    /// z [m], clipped to [0, 1] (set_initial_crack()); empty: none.
    std::string initial_crack;
  };

  /**
   * Body k/Elastic law: neo-Hooke (doc/model.md (16), finite strain) or
   * small-strain linear elasticity (section 2.3, for comparisons with codes
   * at small strain; bodies without plasticity).
   */
  enum class ElasticLaw
  {
    neo_hooke,
    linear
  };

  inline const NameTable<ElasticLaw> &
  elastic_law_names()
  {
    static const NameTable<ElasticLaw> t{{ElasticLaw::neo_hooke, "neo-Hooke"},
                                         {ElasticLaw::linear, "linear"}};
    return t;
  }

  /**
   * `Out-of-plane state` of a 2-D run (doc/model.md section 2.2): plane
   * strain (F_33 = 1) or plane stress (P_33 = 0, the stretch F_33 solved at
   * every material point, plane_stress()).
   */
  enum class OutOfPlane
  {
    plane_strain,
    plane_stress
  };

  inline const NameTable<OutOfPlane> &
  out_of_plane_names()
  {
    static const NameTable<OutOfPlane> t{
      {OutOfPlane::plane_strain, "plane strain"},
      {OutOfPlane::plane_stress, "plane stress"}};
    return t;
  }

  /**
   * One body of a scene: the cells with a given material_id, its material
   * parameters and the physics it carries. Subsection `Body <material id>`.
   *
   * Elastic law: compressible neo-Hooke, doc/model.md (16) with shear modulus
   * mu and bulk modulus kappa [Pa] (or, with Elastic law = linear, small-
   * strain linear elasticity, section 2.3); with `Fracture` degraded by
   * g_k(s) with the split (17); with `Plasticity` the visco-plastic J2 model
   * of doc/model.md section 3 with the hardening field alpha.
   */
  struct BodyParameters
  {
    dealii::types::material_id material_id   = 0;
    std::string                name          = "body";
    double                     shear_modulus = MaterialDefaults::shear_modulus;
    double                     bulk_modulus  = MaterialDefaults::bulk_modulus;
    ElasticLaw                 elastic_law   = ElasticLaw::neo_hooke;

    /// Mass density in the reference configuration [kg/m^3] (inertia in
    /// dynamic runs only; 0: none).
    double density = 0.;
    /// v(X) at t = 0 [m/s]: three muparser expressions of x, y, z
    /// separated by ';'.
    std::string initial_velocity = zero_vector_expression();

    /// Plane stress (P_33 = 0, plane_stress()) instead of plane strain:
    /// not an entry of the body, set from `Out-of-plane state` of a 2-D run.
    bool plane_stress = false;

    /// Whether the body carries the hardening field alpha (plasticity).
    bool plasticity = false;
    /// Whether the body carries the crack phase field s (fracture).
    bool fracture = false;

    /// Hardening law (21) and viscosity (34); its moduli and degradation
    /// members are not read: material() takes them from this body.
    PlasticityParameters plastic;
    /// l_p of the gradient term of (20)/(50) [m].
    double plastic_length_scale = 0.;

    FractureParameters crack;

    /// The plasticity parameters with this body's moduli and degradation.
    PlasticityParameters
    material() const;

    void
    declare(dealii::ParameterHandler &prm);

    /// The subsection Fracture of declare().
    void
    declare_fracture(dealii::ParameterHandler &prm);

    /// Throws InputError for invalid values.
    void
    check() const;

    /// "Body <id>": the subsection name, used in messages.
    std::string
    subsection() const;
  };
} // namespace DuctileContact
