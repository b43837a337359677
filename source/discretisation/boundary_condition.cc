#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/core/expression.h>
#include <ductile_contact/core/input_error.h>
#include <ductile_contact/discretisation/boundary_condition.h>

#include <algorithm>
#include <map>

namespace DuctileContact
{
  using namespace dealii;

  std::string
  BoundaryCondition::subsection() const
  {
    return "Boundary " + Utilities::to_string(boundary_id);
  }



  void
  BoundaryCondition::declare(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection());
    prm.add_parameter(
      "Constrained components",
      constrained_components_text,
      "Displacement components prescribed on this boundary (Dirichlet), a "
      "comma-separated subset of x, y, z (x, y in 2-D); empty: none. The "
      "other components "
      "carry the traction below.",
      Patterns::Anything());
    prm.add_parameter(
      "Displacement",
      displacement_text,
      "Prescribed displacement ubar(x, y, z, t) [m], three expressions "
      "separated by ';' (x, y, z are reference coordinates, t the load-step "
      "time; in 2-D two expressions of x, y, t); only the constrained "
      "components are used.",
      Patterns::Anything());
    prm.add_parameter(
      "Traction",
      traction_text,
      "Dead-load nominal traction T(x, y, z, t) [Pa] (force per reference "
      "area; in 2-D per unit thickness), three expressions separated by "
      "';' (two in 2-D); applied to the components that are not "
      "constrained.",
      Patterns::Anything());
    prm.add_parameter("Function constants",
                      constants_text,
                      "Constants usable in the expressions above, as "
                      "'name=value, name=value' (pi is predefined).",
                      Patterns::Anything());
    prm.leave_subsection();
  }



  namespace
  {
    std::map<std::string, double>
    parse_constants(const std::string &text, const std::string &entry)
    {
      std::map<std::string, double> constants{{"pi", numbers::PI}};
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          if (item.empty())
            continue;
          const auto kv = Utilities::split_string_list(item, '=');
          check_input(kv.size() == 2 && !kv[0].empty(),
                      entry,
                      text,
                      "constants must read 'name=value, name=value'");
          try
            {
              constants[kv[0]] = Utilities::string_to_double(kv[1]);
            }
          catch (...)
            {
              throw InputError(entry,
                               text,
                               "the value of '" + kv[0] + "' must be a number");
            }
        }
      return constants;
    }



    std::unique_ptr<FunctionParser<dim>>
    parse_vector_function(const std::string                   &expressions,
                          const unsigned int                   n_padding,
                          const std::map<std::string, double> &constants,
                          const std::string                   &entry)
    {
      const auto parts = Utilities::split_string_list(expressions, ';');
      check_input(parts.size() == dim,
                  entry,
                  expressions,
                  "it needs " + vector_size_word() +
                    " expressions separated by ';'");
      static const char *const which[]   = {"first", "second", "third"};
      const std::string        variables = coordinate_variables() + ",t";
      for (unsigned int d = 0; d < dim; ++d)
        {
          const std::string message =
            expression_error(parts[d], variables, constants);
          check_input(message.empty(),
                      entry,
                      expressions,
                      "its " + std::string(which[d]) + " expression, '" +
                        parts[d] + "', is not an expression of " +
                        coordinate_list() +
                        ", t and the Constants: " + message);
        }
      std::string padded = expressions;
      for (unsigned int i = 0; i < n_padding; ++i)
        padded += "; 0";
      auto function = std::make_unique<FunctionParser<dim>>(dim + n_padding);
      function->initialize(variables, padded, constants, true);
      return function;
    }
  } // namespace



  void
  BoundaryCondition::check()
  {
    const std::string prefix = subsection() + "/";

    constrained = {};
    for (const std::string &c :
         Utilities::split_string_list(constrained_components_text, ','))
      {
        check_input(c.size() == 1 && c[0] >= 'x' && c[0] < 'x' + char(dim),
                    prefix + "Constrained components",
                    constrained_components_text,
                    "it must be a comma-separated subset of " +
                      coordinate_list());
        constrained[c[0] - 'x'] = true;
      }

    const auto constants =
      parse_constants(constants_text, prefix + "Function constants");
    displacement = parse_vector_function(displacement_text,
                                         Component::n_components - dim,
                                         constants,
                                         prefix + "Displacement");
    traction =
      parse_vector_function(traction_text, 0, constants, prefix + "Traction");

    std::string stripped;
    for (const char ch : traction_text)
      if (ch != ' ')
        stripped += ch;
    std::string zero;
    for (const char ch : zero_vector_expression())
      if (ch != ' ')
        zero += ch;
    has_traction = (stripped != zero);
  }



  bool
  BoundaryCondition::has_dirichlet() const
  {
    return std::find(constrained.begin(), constrained.end(), true) !=
           constrained.end();
  }



  ComponentMask
  BoundaryCondition::dirichlet_mask() const
  {
    std::vector<bool> mask(Component::n_components, false);
    for (unsigned int d = 0; d < dim; ++d)
      mask[Component::first_displacement + d] = constrained[d];
    return ComponentMask(mask);
  }



  Tensor<1, dim>
  BoundaryCondition::traction_at(const Point<dim> &p, const double t) const
  {
    traction->set_time(t);
    Tensor<1, dim> T;
    for (unsigned int d = 0; d < dim; ++d)
      T[d] = constrained[d] ? 0. : traction->value(p, d);
    return T;
  }
} // namespace DuctileContact
