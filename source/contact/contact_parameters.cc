#include <ductile_contact/contact/contact_parameters.h>
#include <ductile_contact/core/input_error.h>

namespace DuctileContact
{
  using namespace dealii;

  std::string
  ContactPairParameters::subsection() const
  {
    return "Contact pair " + std::to_string(number);
  }



  void
  ContactPairParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection());
    prm.add_parameter("Slave boundary id",
                      slave_boundary_id,
                      "Boundary id of the slave surface (the finer mesh): "
                      "its nodes carry the contact pressure.",
                      Patterns::Integer(0, 254));
    prm.add_parameter("Master boundary id",
                      master_boundary_id,
                      "Boundary id of the master surface.",
                      Patterns::Integer(0, 254));
    prm.add_parameter("Friction coefficient",
                      friction_coefficient,
                      "Coulomb coefficient mu_c [-] (0: frictionless).",
                      Patterns::Double(0.));
    prm.add_parameter("Tangential penalty factor",
                      tangential_penalty_factor,
                      "Tangential (stick) penalty of the regularised Coulomb "
                      "law, eps_T = factor x E / h with E and h as for the "
                      "normal penalty [-]: a sticking node slips elastically "
                      "by t_T / eps_T.",
                      Patterns::Double(1e-6));
    prm.add_parameter("Penalty factor",
                      penalty_factor,
                      "Normal penalty of the augmented Lagrangian, eps_N = "
                      "factor x E / h with E the smaller Young's modulus of "
                      "the two bodies and h the smallest slave face size "
                      "[-]. It "
                      "sets how fast the multiplier updates converge, not "
                      "the answer.",
                      Patterns::Double(1e-6));
    prm.add_parameter("Search radius",
                      search_radius,
                      "Enlargement of the face bounding boxes in the search "
                      "for candidate master faces, done at the start of "
                      "every load step [m]; the candidates fix the matrix "
                      "couplings of the step. 0: half the smallest slave "
                      "face size (the reach within which an overlap counts) "
                      "plus twice the largest predicted motion of a slave "
                      "and of a master node in the step, at least a quarter "
                      "of that face size. A master face that comes within "
                      "reach during a step without being a candidate fails "
                      "the step, and the radius doubles for the rest of the "
                      "run.",
                      Patterns::Double(0.));
    prm.add_parameter("Penetration tolerance",
                      penetration_tolerance,
                      "Largest nodal penetration -g_j / A_j accepted at the "
                      "end of a load step, relative to the smallest slave "
                      "face size [-].",
                      Patterns::Double(0.));
    add_option(
      prm,
      "Multiplier basis",
      multiplier_basis,
      multiplier_basis_names(),
      "Basis Phi_j of the contact pressure on the slave faces: dual "
      "(biorthogonal to the face shape functions, Wohlmuth: the nodal "
      "pressures are the N_j-weighted averages of the pressure field and "
      "condense node by node) or standard (Phi_j = N_j, needs the augmented "
      "Lagrangian). On a curved surface give the curve "
      "(Mesh/Gmsh/Curved boundaries): a polygon's nodal pressures "
      "alternate between vertex and mid-side nodes with either basis.");
    add_option(
      prm,
      "Enforcement",
      enforcement,
      contact_enforcement_names(),
      "How the contact conditions are enforced: augmented Lagrangian "
      "(penalty eps_N on the weighted gaps, Newton for fixed multipliers, "
      "Uzawa updates until the penetration is below the tolerance; "
      "friction regularised by eps_T) or semi-smooth Newton (the dual "
      "multipliers condensed from the slave rows; active set, stick and "
      "slip resolved in the one Newton loop by complementarity functions "
      "with c_N = eps_N and c_T = eps_T; zero weighted gap on the active "
      "set, exact stick; needs the dual multiplier basis and a slave "
      "surface without hanging nodes; a slave DoF fixed by a Dirichlet "
      "condition transmits no contact traction, which suits symmetry "
      "planes and rollers whose direction is tangential to the "
      "surface).");
    prm.add_parameter("Maximum augmentations",
                      max_augmentations,
                      "Multiplier (Uzawa) updates per load step before the "
                      "step counts as failed and is cut back.",
                      Patterns::Integer(1, 1000));
    prm.leave_subsection();
  }



  void
  ContactPairParameters::check() const
  {
    const std::string s = subsection() + "/";
    check_input(slave_boundary_id != master_boundary_id,
                s + "Master boundary id",
                std::to_string(master_boundary_id),
                "a boundary id different from the slave boundary id");
    check_input(penetration_tolerance > 0.,
                s + "Penetration tolerance",
                std::to_string(penetration_tolerance),
                "a positive number");
    check_input(enforcement != ContactEnforcement::semi_smooth_newton ||
                  multiplier_basis == MultiplierBasis::dual,
                s + "Multiplier basis",
                name_of(multiplier_basis_names(), multiplier_basis),
                "dual with Enforcement = semi-smooth Newton (the "
                "multipliers are condensed with the diagonal D)");
  }
} // namespace DuctileContact
