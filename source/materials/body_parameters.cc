#include <deal.II/base/utilities.h>

#include <ductile_contact/core/expression.h>
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



  PlasticityParameters
  BodyParameters::material() const
  {
    PlasticityParameters p    = plastic;
    p.shear_modulus           = shear_modulus;
    p.bulk_modulus            = bulk_modulus;
    p.degradation_a           = crack.degradation_a;
    p.residual_stiffness      = crack.residual_stiffness;
    p.volumetric_switch_width = crack.volumetric_switch_width;
    p.degrade_plastic_energy =
      fracture && crack.driver == CrackDriverType::elastic_plastic_energy;
    p.critical_work_density = crack.work_driver.critical_work_density;
    return p;
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
                      "Shear modulus mu of the elastic law, doc/model.md (16) "
                      "[Pa].",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Bulk modulus",
      bulk_modulus,
      "Bulk modulus kappa of the elastic law, doc/model.md (16) "
      "[Pa].",
      Patterns::Double(0.));
    add_option(prm,
               "Elastic law",
               elastic_law,
               elastic_law_names(),
               "'neo-Hooke' is the compressible neo-Hooke law of "
               "doc/model.md (16) at finite strain; 'linear' is small-strain "
               "linear elasticity, psi = kappa/2 (tr eps)^2 + mu |dev eps|^2 "
               "with eps = sym(F) - I (section 2.3), not frame-indifferent: "
               "for comparisons with codes at small strain, in bodies "
               "without plasticity. Fracture/Energy split applies to "
               "both ('spectral' to 'linear' only).");
    prm.add_parameter(
      "Density",
      density,
      "Mass density rho in the reference configuration [kg/m^3]: the "
      "body's inertia with Load stepping/Time integration = Bossak "
      "(ignored in quasi-static runs). 0: no inertia (the body follows "
      "quasi-statically).",
      Patterns::Double(0.));
    prm.add_parameter(
      "Initial velocity",
      initial_velocity,
      "Velocity at t = 0 [m/s], three expressions of x, y, z (reference "
      "coordinates; two of x, y in 2-D) separated by ';'; read with Time "
      "integration = Bossak. "
      "The bodies start stress-free, so the initial acceleration is 0.",
      Patterns::Anything());
    prm.add_parameter(
      "Plasticity",
      plasticity,
      "Whether this body yields: it then carries the hardening field alpha "
      "and the visco-plastic J2 model of doc/model.md section 3 (parameters in "
      "the subsection Plasticity). Without it alpha does not exist here.");
    prm.add_parameter(
      "Fracture",
      fracture,
      "Whether this body can crack: it then carries the phase field s of "
      "doc/model.md section 4 (parameters in the subsection Fracture). Without "
      "it s does not exist here.");

    prm.enter_subsection("Plasticity");
    prm.add_parameter("Initial yield stress",
                      plastic.initial_yield,
                      "y_0 of the hardening law (21) [Pa].",
                      Patterns::Double(0.));
    prm.add_parameter("Saturation yield stress",
                      plastic.saturation_yield,
                      "y_inf of (21) [Pa]; at least y_0.",
                      Patterns::Double(0.));
    prm.add_parameter("Saturation exponent",
                      plastic.saturation_exponent,
                      "eta of (21) [-].",
                      Patterns::Double(0.));
    prm.add_parameter("Linear hardening",
                      plastic.linear_hardening,
                      "h of (21) [Pa].",
                      Patterns::Double(0.));
    prm.add_parameter("Viscosity",
                      plastic.viscosity,
                      "eta_p of (34) and (50) [Pa times pseudo time]; "
                      "positive. Small values approach rate independence.",
                      Patterns::Double(0.));
    add_option(prm,
               "Flow integration",
               plastic.flow_integration,
               flow_integration_names(),
               "How a step's plastic flow updates (C^p)^{-1} (doc/model.md "
               "section 3): 'exponential map' integrates d^p = lambda_p n "
               "exactly along the trial direction, b^e = exp(-2 dt lambda_p "
               "n) b_tr, so that the plastic work is the work of the flow "
               "resistance and the plastic dissipation is >= 0; 'linear' is "
               "the paper's (37), its first-order truncation, whose plastic "
               "work falls short of int yhat dalpha by about y_0/mu "
               "relative (a negative plastic dissipation).");
    add_option(
      prm,
      "Loading condition",
      plastic.loading_condition,
      loading_condition_names(),
      "Where a point flows and how alpha is kept from falling (doc/model.md "
      "sections 3.1-3.2). 'pointwise switch': the paper's (50), the yield "
      "test at each quadrature point, alpha held at alpha_n by a stiff "
      "penalty (Hold stiffness factor) where it fails; the penalty lets "
      "alpha creep below yield beside a plastic zone, a negative local "
      "plastic dissipation of order 1/f, and the Q_p field of alpha can dip "
      "below 0 between its nodes. 'bound': every point follows the same "
      "Perzyna law and alpha >= alpha_n is a bound on the alpha DoFs (a "
      "primal-dual active set, as Coupling/Irreversibility does for s): "
      "the variational inequality of gradient plasticity, whose backward "
      "Euler local plastic dissipation is >= 0 (the trapezoidal plastic "
      "work of the statistics leaves a time-discretisation error, first "
      "order in D_p); with Finite elements/Hardening basis = "
      "Bernstein the bound, and alpha >= 0, hold at every point. Every "
      "plastic body must give the same choice.");
    prm.add_parameter(
      "Hold stiffness factor",
      plastic.hold_stiffness_factor,
      "Loading condition = pointwise switch only: f of the hold of alpha at "
      "points that do not yield, c = f (mu g tr "
      "bbar_tr + yhat'(alpha_n)) (doc/model.md section 3.1, choice 3) [-]; "
      "at least 1. The finite hold lets alpha creep at non-yielding points "
      "beside a plastic zone, where the stress is below yield: their plastic "
      "work falls short of the stored energy, a negative plastic dissipation "
      "of order 1/f (the coarse paper scene: -0.36 J with f = 1, -0.041 J "
      "with f = 10, of 19.5 J plastic work).",
      Patterns::Double(1.));
    prm.add_parameter("Length scale",
                      plastic_length_scale,
                      "l_p of the gradient term y_0 l_p^2 |grad alpha|^2/2 "
                      "of (20) [m]; 0 gives local plasticity.",
                      Patterns::Double(0.));
    prm.leave_subsection();

    declare_fracture(prm);
    prm.leave_subsection();
  }



  void
  BodyParameters::declare_fracture(ParameterHandler &prm)
  {
    prm.enter_subsection("Fracture");
    prm.add_parameter("Critical energy release rate",
                      crack.critical_energy_release_rate,
                      "g_c of (51) [J/m^2].",
                      Patterns::Double(0.));
    prm.add_parameter("Length scale",
                      crack.length_scale,
                      "l_f of the crack functional (3) [m]; with "
                      "Regularisation = second order it is Miehe's l of "
                      "the AT2 functional.",
                      Patterns::Double(0.));
    add_option(prm,
               "Regularisation",
               crack.regularisation,
               regularisation_names(),
               "The crack density gamma (doc/model.md section 4): 'fourth "
               "order' is the paper's (3), s^2/(4 l_f) + l_f/2 |grad s|^2 + "
               "l_f^3/4 (Lap s)^2, discretised by C0 interior penalty "
               "(cells and interior faces); 'second order' is AT2 (Miehe et "
               "al. 2010), s^2/(2 l_f) + l_f/2 |grad s|^2, without face "
               "terms (Interior penalty is not read). For the same "
               "transition zone the second-order l_f is twice the "
               "fourth-order one.");
    add_option(prm,
               "Energy split",
               crack.split,
               energy_split_names(),
               "Which elastic energy of a body without plasticity degrades "
               "with g_k(s) and drives the crack (doc/model.md (17)): "
               "'volumetric-deviatoric' degrades the deviatoric energy and "
               "the volumetric one only in expansion (J > 1), so that a "
               "crack cannot interpenetrate; 'none' degrades the whole "
               "energy, in compression too (for comparisons with codes "
               "without a split); 'spectral' (Elastic law = linear only) "
               "degrades lambda/2 <tr eps>_+^2 + mu |eps_+|^2, the energy "
               "of a positive trace and of the positive principal strains "
               "(Miehe et al. 2010, doc/model.md section 2.3). Bodies with "
               "plasticity always use 'volumetric-deviatoric'.");
    prm.add_parameter("Viscosity",
                      crack.viscosity,
                      "eta_f of (51) [J/m^3 times pseudo time]; 0 gives the "
                      "rate-independent limit.",
                      Patterns::Double(0.));
    prm.add_parameter("Degradation parameter",
                      crack.degradation_a,
                      "a_g of g(s) (doc/model.md section 2); 2 gives "
                      "g(s) = (1 - s)^2. Between 0 and 3 (g must decrease) "
                      "[-].",
                      Patterns::Double(0.));
    prm.add_parameter("Residual stiffness",
                      crack.residual_stiffness,
                      "k of g_k(s) = (1 - k) g(s) + k [-].",
                      Patterns::Double(0.));
    prm.add_parameter("Interior penalty",
                      crack.interior_penalty,
                      "gamma_IP of the C0 interior-penalty face terms of the "
                      "bi-Laplacian; 0 selects the default (d/2) p (p + 1): "
                      "1.5 p (p + 1) in 3-D, p (p + 1) in 2-D (see "
                      "phase_field/c0ip.h for why not p (p + 1) in 3-D) "
                      "[-].",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Volumetric switch width",
      crack.volumetric_switch_width,
      "delta [-]: the volumetric energy of the split (17) degrades with "
      "g(s) for J > 1 and not for J < 1; with delta > 0 the switch is "
      "blended smoothly over 1 - delta < J < 1 + delta (the curvature of the "
      "energy in J goes from kappa to g kappa along a C2 step; the energy "
      "stays convex, the stress beyond the blend is the sharp one), so that "
      "the tangent has no jump at J = 1 (Newton's line search fails at the "
      "jumps once many damaged points sit near J = 1, e.g. in the ductile "
      "notch). Bodies with plasticity only; 0 is the sharp switch of "
      "doc/model.md.",
      Patterns::Double(0., 0.1));
    add_option(prm,
               "Crack driver",
               crack.driver,
               crack_driver_names(),
               "The energy density psi_D whose history maximum drives the "
               "crack in (51), H = -g_k'(s) max psi_D: 'elastic' is psi^+ of "
               "doc/model.md (27), the paper's driver; 'elastic plus plastic "
               "work' is zeta <psi^+ + W_p(alpha) - w_c> with W_p = "
               "int_0^alpha "
               "yhat the plastic work density (Miehe et al. 2015/2016), "
               "not derived from the free energy: its supply of energy is "
               "the statistics column history_driving_work; 'elastic and "
               "plastic energy' is the variational driver psi^+ + "
               "phi(W_p), phi(W_p) ~ <W_p - w_c>: the plastic energy above "
               "w_c is degraded by g_k(s) together with the flow resistance, "
               "so the crack is paid by energy the solid releases "
               "(doc/model.md section 4.3). Both plastic drivers are for "
               "bodies with plasticity: metals whose yield-limited stresses "
               "keep psi^+ far below g_c/(2 l_f) tear only with them.");
    prm.add_parameter("Critical work density",
                      crack.work_driver.critical_work_density,
                      "w_c of the plastic crack drivers [J/m^3]: with "
                      "'elastic plus plastic work' nothing drives the crack "
                      "below it; with 'elastic and plastic energy' the "
                      "plastic energy density W_p above it is degraded and "
                      "drives the crack. Not read with Crack driver = "
                      "elastic.",
                      Patterns::Double(0.));
    prm.add_parameter("Driver factor",
                      crack.work_driver.factor,
                      "zeta of the elastic-plus-plastic crack driver [-]: "
                      "how strongly the work above w_c drives the crack "
                      "(Miehe et al.'s zeta g_c/(l_f psi_c)); positive. "
                      "Read with Crack driver = elastic plus plastic work "
                      "only; it must stay 1 with elastic and plastic "
                      "energy.",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Initial crack",
      crack.initial_crack,
      "A crack present from the start, without meshing a slit: s at t = 0 "
      "as an expression of the reference coordinates x, y, z [m] (muparser "
      "syntax, clipped to [0, 1]; taken at the nodes of s), e.g. 'abs(y - "
      "0.5e-3) < 1e-9 && x <= 0.5e-3' for the nodes on a segment of the "
      "plane y = 0.5 mm, or '(x < 1e-3) * exp(-abs(y) / 1e-5)' for a "
      "profile. Relaxed at zero load before the first step (s at least "
      "these values); the bound s >= s_n of Coupling/Irreversibility keeps "
      "it. Empty: none.",
      Patterns::Anything());
    prm.leave_subsection();
  }



  void
  BodyParameters::check() const
  {
    const std::string prefix = subsection() + "/";
    const auto value = [](const double x) { return Utilities::to_string(x); };
    check_input(shear_modulus > 0.,
                prefix + "Shear modulus",
                value(shear_modulus),
                "it must be positive");
    check_input(bulk_modulus > 0.,
                prefix + "Bulk modulus",
                value(bulk_modulus),
                "it must be positive");
    const auto velocity = Utilities::split_string_list(initial_velocity, ';');
    check_input(velocity.size() == dim,
                prefix + "Initial velocity",
                initial_velocity,
                "it needs " + vector_size_word() +
                  " expressions separated by ';'");
    for (const std::string &part : velocity)
      {
        const std::string error =
          expression_error(part, coordinate_variables());
        check_input(error.empty(),
                    prefix + "Initial velocity",
                    initial_velocity,
                    "'" + part + "' is not an expression of " +
                      coordinate_list() + ": " + error);
      }
    if (plasticity)
      {
        const std::string p = prefix + "Plasticity/";
        check_input(plastic.initial_yield > 0.,
                    p + "Initial yield stress",
                    value(plastic.initial_yield),
                    "it must be positive");
        check_input(plastic.saturation_yield >= plastic.initial_yield,
                    p + "Saturation yield stress",
                    value(plastic.saturation_yield),
                    "it must be at least the initial yield stress " +
                      value(plastic.initial_yield));
        check_input(elastic_law == ElasticLaw::neo_hooke,
                    prefix + "Elastic law",
                    name_of(elastic_law_names(), elastic_law),
                    "a body with plasticity uses 'neo-Hooke' (F = Fe Fp is "
                    "a finite-strain model)");
        check_input(plastic.viscosity > 0.,
                    p + "Viscosity",
                    value(plastic.viscosity),
                    "it must be positive (the hardening equation (50) is "
                    "viscous; choose it small for rate independence)");
      }
    if (fracture)
      {
        const std::string f = prefix + "Fracture/";
        check_input(crack.critical_energy_release_rate > 0.,
                    f + "Critical energy release rate",
                    value(crack.critical_energy_release_rate),
                    "it must be positive");
        check_input(crack.length_scale > 0.,
                    f + "Length scale",
                    value(crack.length_scale),
                    "it must be positive");
        check_input(crack.degradation_a <= 3.,
                    f + "Degradation parameter",
                    value(crack.degradation_a),
                    "0 <= a_g <= 3 (g(s) must decrease from 1 to 0)");
        check_input(crack.residual_stiffness < 1.,
                    f + "Residual stiffness",
                    value(crack.residual_stiffness),
                    "0 <= k < 1");
        check_input(plasticity || crack.volumetric_switch_width == 0.,
                    f + "Volumetric switch width",
                    value(crack.volumetric_switch_width),
                    "it must be 0 for a body without plasticity (the smoothed "
                    "switch is implemented for the elastic-plastic law only)");
        check_input(!plasticity ||
                      crack.split == EnergySplit::volumetric_deviatoric,
                    f + "Energy split",
                    name_of(energy_split_names(), crack.split),
                    "a body with plasticity uses the split "
                    "'volumetric-deviatoric' of its elastic energy");
        check_input(crack.split != EnergySplit::spectral ||
                      elastic_law == ElasticLaw::linear,
                    f + "Energy split",
                    name_of(energy_split_names(), crack.split),
                    "'spectral' is a split of the small strain: it needs " +
                      prefix + "Elastic law = linear");
        check_input(plasticity || crack.driver == CrackDriverType::elastic,
                    f + "Crack driver",
                    name_of(crack_driver_names(), crack.driver),
                    "'elastic' is the only driver of a body without "
                    "plasticity (set Plasticity = true for the plastic "
                    "drivers)");
        const std::string error =
          crack.initial_crack.empty()
            ? ""
            : expression_error(crack.initial_crack, coordinate_variables());
        check_input(error.empty(),
                    f + "Initial crack",
                    crack.initial_crack,
                    "it is not an expression of " + coordinate_list() + ": " +
                      error);
        check_input(crack.driver != CrackDriverType::elastic_plastic_energy ||
                      crack.work_driver.factor == 1.,
                    f + "Driver factor",
                    value(crack.work_driver.factor),
                    "it must be 1 (its default) with Crack driver = elastic "
                    "and plastic energy: that driver is -dPsi/ds of the free "
                    "energy and has no free factor");
      }
  }
} // namespace DuctileContact
