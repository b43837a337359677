#include <deal.II/base/function_parser.h>

#include <ductile_contact/core/expression.h>
#include <ductile_contact/core/one_line.h>
#include <ductile_contact/core/types.h>

#include <iostream>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  std::string
  expression_error(const std::string                   &expression,
                   const std::string                   &variables,
                   const std::map<std::string, double> &constants)
  {
    std::ostringstream swallowed;
    std::streambuf    *cerr = std::cerr.rdbuf(swallowed.rdbuf());
    std::string        message;
    try
      {
        FunctionParser<dim> function(1);
        const bool time_dependent = variables.find(",t") != std::string::npos;
        function.initialize(variables, expression, constants, time_dependent);
        function.value(Point<dim>());
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        message         = one_line(info.str());
        const auto said = message.find("The parser said: ");
        if (said != std::string::npos)
          message = message.substr(said + 17);
      }
    std::cerr.rdbuf(cerr);
    return message;
  }
} // namespace DuctileContact
