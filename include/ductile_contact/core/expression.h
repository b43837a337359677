#pragma once

#include <map>
#include <string>

namespace DuctileContact
{
  /// The parser's message on @p expression, a function of @p variables
  /// ("x,y,z" or "x,y,z,t") with @p constants in muparser's syntax, as one
  /// line; empty if it parses and evaluates at the origin (muparser reports
  /// unknown names only when it evaluates). The parser's own report on
  /// std::cerr is swallowed: the caller's input error says it in its line.
  std::string
  expression_error(const std::string                   &expression,
                   const std::string                   &variables,
                   const std::map<std::string, double> &constants = {});
} // namespace DuctileContact
