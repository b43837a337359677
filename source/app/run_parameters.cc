#include <deal.II/base/utilities.h>

#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    void
    declare_lists(ParameterHandler          &prm,
                  std::vector<unsigned int> &material_ids,
                  std::vector<unsigned int> &boundary_ids,
                  std::vector<unsigned int> &contact_pairs)
    {
      prm.enter_subsection("Bodies");
      prm.add_parameter(
        "Material ids",
        material_ids,
        "Material ids of the bodies of the scene; each needs a subsection "
        "'Body <id>' with its material (box: 0; two bodies: 0 = plate, 1 = "
        "block; gmsh: the physical volume tags).",
        Patterns::List(Patterns::Integer(0, 255), 1, 256, ","));
      prm.leave_subsection();
      prm.enter_subsection("Boundary conditions");
      prm.add_parameter(
        "Boundary ids",
        boundary_ids,
        "Boundary ids that carry conditions; each needs a subsection "
        "'Boundary <id>'. Boundaries not listed are traction free.",
        Patterns::List(Patterns::Integer(0, 254), 0, 255, ","));
      prm.leave_subsection();
      prm.enter_subsection("Contact");
      prm.add_parameter(
        "Pairs",
        contact_pairs,
        "Numbers n of the contact pairs; each needs a subsection 'Contact "
        "pair <n>'. Empty: no contact.",
        Patterns::List(Patterns::Integer(1, 1000), 0, 1000, ","));
      prm.leave_subsection();
    }



    /// The entry `Dimension`, read alone by input_dimension() and with
    /// every other entry by RunParameters::declare().
    void
    declare_dimension(ParameterHandler &prm, unsigned int &dimension)
    {
      prm.add_parameter(
        "Dimension",
        dimension,
        "Space dimension of the scene: 3, or 2 for plane strain (the mesh in "
        "the x-y plane, u_z = 0; the material point stays three-dimensional, "
        "with tau_33 and the out-of-plane plastic stretch; forces, energies "
        "and works per unit thickness). Read before every "
        "other entry: ductile-contact runs a 2-D input in its plane-strain "
        "build, ductile-contact-2d.",
        Patterns::Integer(2, 3));
    }



    void
    check_unique(const std::vector<unsigned int> &ids, const std::string &entry)
    {
      const std::set<unsigned int> unique(ids.begin(), ids.end());
      std::ostringstream           text;
      for (unsigned int i = 0; i < ids.size(); ++i)
        text << (i ? ", " : "") << ids[i];
      check_input(unique.size() == ids.size(),
                  entry,
                  text.str(),
                  "every id may appear only once");
    }
  } // namespace



  void
  RunParameters::declare(const std::vector<unsigned int> &material_id_list,
                         const std::vector<unsigned int> &boundary_id_list,
                         const std::vector<unsigned int> &pair_list)
  {
    material_ids         = material_id_list;
    boundary_ids         = boundary_id_list;
    contact_pair_numbers = pair_list;

    declare_dimension(prm, dimension);
    add_option(prm,
               "Out-of-plane state",
               out_of_plane,
               out_of_plane_names(),
               "With Dimension = 2: 'plane strain' holds the out-of-plane "
               "stretch, F_33 = 1 (a thick body); 'plane stress' frees it "
               "so that P_33 = 0 at every material point (a thin sheet; "
               "doc/model.md section 2.2), for every material law. Forces, "
               "energies and works stay per unit reference thickness. "
               "Dimension = 3 refuses 'plane stress'.");
    mesh.declare(prm);

    prm.enter_subsection("Finite elements");
    prm.add_parameter("Polynomial degree",
                      fe_degree,
                      "Degree p of the FE_Q elements of every field (u, "
                      "alpha, s). The fourth-order phase field needs p >= 2.",
                      Patterns::Integer(1, 4));
    add_option(prm,
               "Phase-field basis",
               phase_field_basis,
               field_basis_names(),
               "Basis of the phase field s (the same Q_p space either way). "
               "Lagrange: FE_Q, the DoFs are nodal values, and the bound "
               "s_n <= s <= 1 (Coupling/Irreversibility) holds at the nodes; "
               "the fourth-order field can exceed 1 between them. Bernstein: "
               "the DoFs are Bernstein coefficients, of which s is a convex "
               "combination at every point, so the bound holds everywhere; an "
               "initial crack and coarsening take the field's values at the "
               "Greville points (doc/model.md section 4.2).");
    add_option(prm,
               "Hardening basis",
               hardening_basis,
               field_basis_names(),
               "Basis of the plastic strain alpha (the same Q_p space either "
               "way). Lagrange: nodal values, between which the field can "
               "dip below its nodes' values (below 0 next to a plastic zone). "
               "Bernstein: coefficients, of which alpha is a convex "
               "combination, so that the bound alpha_n <= alpha of "
               "Plasticity/Loading condition = bound holds at every point, "
               "and alpha >= 0 with it (doc/model.md section 3.2).");
    prm.leave_subsection();

    declare_lists(prm, material_ids, boundary_ids, contact_pair_numbers);

    bodies.clear();
    for (const unsigned int id : material_ids)
      {
        bodies.emplace_back();
        bodies.back().material_id = id;
        bodies.back().declare(prm);
      }
    boundary_conditions.clear();
    for (const unsigned int id : boundary_ids)
      {
        boundary_conditions.emplace_back();
        boundary_conditions.back().boundary_id = id;
        boundary_conditions.back().declare(prm);
      }
    contact_pairs.clear();
    for (const unsigned int n : contact_pair_numbers)
      {
        contact_pairs.emplace_back();
        contact_pairs.back().number = n;
        contact_pairs.back().declare(prm);
      }

    load_stepping.declare(prm);
    newton.declare(prm);
    coupling.declare(prm);
    linear_solver.declare(prm);
    output.declare(prm);
    checkpoint.declare(prm);
  }



  void
  RunParameters::parse_string(const std::string &text)
  {
    // Pass 1: find out which Body / Boundary subsections exist.
    std::vector<unsigned int> mids{0}, bids, pairs;
    {
      ParameterHandler first_pass;
      declare_lists(first_pass, mids, bids, pairs);
      first_pass.parse_input_from_string(text, "", true);
    }
    check_unique(mids, "Bodies/Material ids");
    check_unique(bids, "Boundary conditions/Boundary ids");
    check_unique(pairs, "Contact/Pairs");

    // Pass 2: the full, strict parse.
    prm.clear();
    declare(mids, bids, pairs);
    prm.parse_input_from_string(text, "", false);
    for (BodyParameters &b : bodies)
      b.plane_stress = out_of_plane == OutOfPlane::plane_stress;
    check();
  }



  std::string
  overrides_as_prm(const std::vector<std::string> &overrides)
  {
    std::string text;
    for (const std::string &o : overrides)
      {
        const auto equal = o.find('=');
        if (equal == std::string::npos)
          throw InputError("--set '" + o +
                           "': expected \"Subsection/Entry = value\"");
        const std::vector<std::string> path =
          Utilities::split_string_list(o.substr(0, equal), '/');
        const std::string value = Utilities::trim(o.substr(equal + 1));
        if (path.empty() || path.back().empty())
          throw InputError("--set '" + o + "': no entry name before '='");
        for (std::size_t k = 0; k + 1 < path.size(); ++k)
          text += "subsection " + path[k] + "\n";
        text += "set " + path.back() + " = " + value + "\n";
        for (std::size_t k = 0; k + 1 < path.size(); ++k)
          text += "end\n";
      }
    return text;
  }



  /// Mesh/Gmsh/File name of @p text (the file with its overrides) as an
  /// absolute path, if it is given and relative: a relative name is read
  /// from the folder of the input file @p file_name, wherever the program is
  /// started. Returned as a subsection to append; empty if nothing changes.
  std::string
  mesh_file_relative_to(const std::string &text, const std::string &file_name)
  {
    ParameterHandler mesh;
    std::string      name;
    mesh.enter_subsection("Mesh");
    mesh.enter_subsection("Gmsh");
    mesh.add_parameter("File name", name);
    mesh.leave_subsection();
    mesh.leave_subsection();
    mesh.parse_input_from_string(text, "", true);
    namespace fs = std::filesystem;
    if (name.empty() || fs::path(name).is_absolute())
      return "";
    const fs::path folder = fs::path(file_name).parent_path();
    const fs::path path   = fs::absolute(folder / name).lexically_normal();
    return "subsection Mesh\nsubsection Gmsh\nset File name = " +
           path.string() + "\nend\nend\n";
  }



  std::optional<unsigned int>
  input_dimension(const std::string              &file_name,
                  const std::vector<std::string> &overrides)
  {
    try
      {
        std::ifstream in(file_name);
        if (!in)
          return std::nullopt;
        std::stringstream text;
        text << in.rdbuf() << "\n" << overrides_as_prm(overrides);
        unsigned int     dimension = dim;
        ParameterHandler prm;
        declare_dimension(prm, dimension);
        prm.parse_input_from_string(text.str(), "", true);
        return dimension;
      }
    catch (...)
      {
        return std::nullopt;
      }
  }



  void
  RunParameters::parse(const std::string              &file_name,
                       const std::vector<std::string> &overrides)
  {
    if (file_name.empty())
      {
        // Defaults only, with one example Body, Boundary and Contact pair
        // subsection so that --print-parameters documents their entries.
        declare({0}, {0}, {1});
        return;
      }
    std::ifstream in(file_name);
    if (!in)
      throw InputError("the input file '" + file_name + "' cannot be opened");
    std::stringstream text;
    text << in.rdbuf();
    // Empty, or comments only.
    bool        has_entries = false;
    std::string line;
    for (std::istringstream lines(text.str()); std::getline(lines, line);)
      has_entries =
        has_entries || !Utilities::trim(line.substr(0, line.find('#'))).empty();
    if (!has_entries)
      throw InputError("the input file '" + file_name +
                       "' is empty (a run needs at least its scene and "
                       "boundary conditions; 'ductile-contact "
                       "--print-parameters' lists every entry)");
    const std::string input = text.str() + "\n" + overrides_as_prm(overrides);
    parse_string(input + mesh_file_relative_to(input, file_name));
  }



  void
  RunParameters::check_loading_conditions()
  {
    // The bound alpha_n <= alpha acts on the whole alpha block, so the
    // plastic bodies must agree on it.
    const BodyParameters *first = nullptr;
    for (const BodyParameters &b : bodies)
      if (b.plasticity)
        {
          if (first == nullptr)
            first = &b;
          const auto name = [](const BodyParameters &body) {
            return name_of(loading_condition_names(),
                           body.plastic.loading_condition);
          };
          check_input(b.plastic.loading_condition ==
                        first->plastic.loading_condition,
                      b.subsection() + "/Plasticity/Loading condition",
                      name(b),
                      "every plastic body must give the same choice (" +
                        first->subsection() +
                        "/Plasticity/Loading condition is '" + name(*first) +
                        "'): the bound alpha_n <= alpha acts on the whole "
                        "alpha field");
        }
    coupling.hardening_bound =
      first != nullptr &&
      first->plastic.loading_condition == LoadingCondition::bound;
  }



  void
  RunParameters::check()
  {
    check_input(dimension == dim,
                "Dimension",
                std::to_string(dimension),
                "this program is the " + std::to_string(dim) +
                  "-D build; run 'ductile-contact', which hands the input "
                  "to the build of its dimension");
    check_input(dim == 2 || out_of_plane == OutOfPlane::plane_strain,
                "Out-of-plane state",
                name_of(out_of_plane_names(), out_of_plane),
                "plane stress needs Dimension = 2");
    mesh.check();
    for (const BodyParameters &b : bodies)
      b.check();
    for (BoundaryCondition &bc : boundary_conditions)
      bc.check();
    const bool phase_field =
      std::any_of(bodies.begin(), bodies.end(), [](const BodyParameters &b) {
        return b.fracture;
      });
    const bool fourth_order =
      std::any_of(bodies.begin(), bodies.end(), [](const BodyParameters &b) {
        return b.fracture &&
               b.crack.regularisation == Regularisation::fourth_order;
      });
    check_input(!fourth_order || fe_degree >= 2,
                "Finite elements/Polynomial degree",
                std::to_string(fe_degree),
                "it must be at least 2 when a body has a fourth-order phase "
                "field (the C0IP terms of the fourth-order crack functional "
                "need second derivatives inside the cells; "
                "Fracture/Regularisation = second order works with 1)");
    for (const BodyParameters &b : bodies)
      check_input(!b.fracture || b.crack.initial_crack.empty() ||
                    coupling.irreversibility != Irreversibility::history,
                  b.subsection() + "/Fracture/Initial crack",
                  b.crack.initial_crack,
                  "an initial crack needs the bound s >= s_n "
                  "(Coupling/Irreversibility = bound or history and bound); "
                  "with history alone it would heal");
    check_loading_conditions();
    for (const ContactPairParameters &c : contact_pairs)
      {
        c.check();
        // The staggered solves of s freeze u, and the semi-smooth Newton
        // method condenses the contact tractions from the free u rows.
        check_input(c.enforcement != ContactEnforcement::semi_smooth_newton ||
                      !phase_field ||
                      coupling.strategy == CouplingStrategy::monolithic,
                    c.subsection() + "/Enforcement",
                    name_of(contact_enforcement_names(), c.enforcement),
                    "augmented Lagrangian when a body has a phase field and "
                    "Coupling/Strategy is " +
                      name_of(coupling_strategy_names(), coupling.strategy) +
                      " (its phase-field solves hold the displacements, "
                      "from whose rows the semi-smooth Newton method takes "
                      "the contact tractions); or Coupling/Strategy = "
                      "monolithic");
      }
    check_adaptive_refinement();
    load_stepping.check();
    check_input(
      load_stepping.time_integration == TimeIntegration::quasi_static ||
        std::any_of(bodies.begin(),
                    bodies.end(),
                    [](const BodyParameters &b) { return b.density > 0.; }),
      "Load stepping/Time integration",
      name_of(time_integration_names(), load_stepping.time_integration),
      "a dynamic run needs a body with Density > 0 (every Body <id>/Density "
      "is 0, so nothing has inertia)");
    newton.check();
    coupling.check();
    linear_solver.check();
    output.check();
  }



  void
  RunParameters::check_adaptive_refinement() const
  {
    const auto &a = mesh.adaptive;
    if (!a.enabled)
      return;
    const std::string prefix = "Mesh/Adaptive refinement/";
    const auto        any    = [&](bool BodyParameters::*field) {
      return std::any_of(bodies.begin(),
                         bodies.end(),
                         [&](const BodyParameters &b) { return b.*field; });
    };
    check_input(a.phase_field_threshold == 0. || any(&BodyParameters::fracture),
                prefix + "Phase-field threshold",
                Utilities::to_string(a.phase_field_threshold),
                "0 when no body has Fracture = true (there is no s)");
    check_input(a.hardening_threshold == 0. || any(&BodyParameters::plasticity),
                prefix + "Hardening threshold",
                Utilities::to_string(a.hardening_threshold),
                "0 when no body has Plasticity = true (there is no alpha)");
  }



  const BodyParameters &
  RunParameters::body(const types::material_id id) const
  {
    for (const BodyParameters &b : bodies)
      if (b.material_id == id)
        return b;
    throw InputError("Bodies/Material ids",
                     Utilities::to_string(static_cast<unsigned int>(id)),
                     "the mesh has cells with this material id, but it is not "
                     "listed (add it and a subsection 'Body " +
                       Utilities::to_string(static_cast<unsigned int>(id)) +
                       "')");
  }
} // namespace DuctileContact
