#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/fe/component_mask.h>

#include <ductile_contact/core/expression.h>
#include <ductile_contact/core/types.h>

#include <array>
#include <memory>
#include <string>

namespace DuctileContact
{
  /**
   * Boundary conditions on one boundary id, subsection `Boundary <id>`:
   * fixed displacement components with prescribed values ubar(X, t) [m] and,
   * on the remaining components, a dead-load nominal traction T(X, t) [Pa]
   * (force per unit reference area, T = P N). Boundaries without a
   * subsection are traction free.
   *
   * Functions are muparser expressions of x, y, z (reference coordinates)
   * and t (load-step time), one per component separated by ';'.
   */
  struct BoundaryCondition
  {
    dealii::types::boundary_id boundary_id = 0;

    std::string constrained_components_text;
    std::string displacement_text = zero_vector_expression();
    std::string traction_text     = zero_vector_expression();
    std::string constants_text;

    /// Which of u_x, u_y (, u_z) are prescribed (Dirichlet).
    std::array<bool, dim> constrained{};

    /// ubar: all components (u, alpha, s); alpha and s entries are zero.
    std::unique_ptr<dealii::FunctionParser<dim>> displacement;
    /// T: dim components.
    std::unique_ptr<dealii::FunctionParser<dim>> traction;
    /// False when the traction expression is identically "0; 0; 0".
    bool has_traction = false;

    void
    declare(dealii::ParameterHandler &prm);

    /// Parses the entries into the members above; throws InputError.
    void
    check();

    bool
    has_dirichlet() const;

    /// Component mask over all FE components (u only).
    dealii::ComponentMask
    dirichlet_mask() const;

    /// Traction vector at reference point @p p and time @p t.
    dealii::Tensor<1, dim>
    traction_at(const dealii::Point<dim> &p, const double t) const;

    std::string
    subsection() const;
  };
} // namespace DuctileContact
