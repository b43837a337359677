#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ductile_contact/app/checkpoint_parameters.h>
#include <ductile_contact/contact/contact_parameters.h>
#include <ductile_contact/coupled/coupling_parameters.h>
#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/field_basis.h>
#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/mesh/mesh_parameters.h>
#include <ductile_contact/output/output_parameters.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace DuctileContact
{
  /**
   * The command line's overrides "A/B/Entry = value" (--set) as .prm text:
   * subsection A, subsection B, set Entry = value, end, end. Throws
   * InputError for an override without '=' or without an entry name.
   */
  std::string
  overrides_as_prm(const std::vector<std::string> &overrides);

  /**
   * The entry `Dimension` of the input file @p file_name with the --set
   * @p overrides, read alone; nothing when the file cannot be read or the
   * value is not 2 or 3 (the full parse then says why).
   */
  std::optional<unsigned int>
  input_dimension(const std::string              &file_name,
                  const std::vector<std::string> &overrides);

  /**
   * Every input of a run. The in-class defaults of the structs are the only
   * defaults (entries are bound with ParameterHandler::add_parameter).
   *
   * The numbers of `Body <id>`, `Boundary <id>` and `Contact pair <n>`
   * subsections depend on the file: a first, tolerant pass reads
   * `Bodies/Material ids`, `Boundary conditions/Boundary ids` and
   * `Contact/Pairs`, then every subsection is declared
   * and the file is parsed strictly (unknown entries are errors).
   */
  struct RunParameters
  {
    /// `Dimension`: 3, or 2 for plane strain; always the build's dim once
    /// parsed (the program hands other inputs to the other build).
    unsigned int dimension = dim;
    /// `Out-of-plane state` of a 2-D run: plane strain or plane stress.
    OutOfPlane     out_of_plane = OutOfPlane::plane_strain;
    MeshParameters mesh;
    unsigned int   fe_degree         = 2;
    FieldBasis     phase_field_basis = FieldBasis::lagrange;
    FieldBasis     hardening_basis   = FieldBasis::lagrange;
    // deques: entries are bound by address, so elements must not move.
    std::deque<BodyParameters>    bodies;
    std::deque<BoundaryCondition> boundary_conditions;
    /// Empty: the scene runs no contact code.
    std::deque<ContactPairParameters> contact_pairs;
    LoadSteppingParameters            load_stepping;
    NewtonParameters                  newton;
    CouplingParameters                coupling;
    LinearSolverParameters            linear_solver{dim};
    OutputParameters                  output;
    CheckpointParameters              checkpoint;

    dealii::ParameterHandler prm;

    /// Parses and checks @p file_name; throws InputError or deal.II's
    /// parameter exceptions. With an empty name, only declares (defaults).
    void
    parse(const std::string              &file_name,
          const std::vector<std::string> &overrides = {});

    /// Same as parse(), from text (used by tests).
    void
    parse_string(const std::string &text);

    /// The body with this material id; throws if unknown.
    const BodyParameters &
    body(const dealii::types::material_id id) const;

  private:
    void
    declare(const std::vector<unsigned int> &material_ids,
            const std::vector<unsigned int> &boundary_ids,
            const std::vector<unsigned int> &contact_pair_numbers);

    void
    check();

    /// Plasticity/Loading condition of the plastic bodies (one choice for
    /// all); sets coupling.hardening_bound.
    void
    check_loading_conditions();

    /// Mesh/Adaptive refinement against the bodies and contact pairs.
    void
    check_adaptive_refinement() const;

    std::vector<unsigned int> material_ids{0};
    std::vector<unsigned int> boundary_ids;
    std::vector<unsigned int> contact_pair_numbers;
  };
} // namespace DuctileContact
