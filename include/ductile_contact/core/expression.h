#pragma once

#include <ductile_contact/core/types.h>

#include <map>
#include <string>

namespace DuctileContact
{
  /// The reference coordinates that expressions of this build take, in
  /// muparser's form: "x,y,z", or "x,y" in 2-D.
  inline std::string
  coordinate_variables()
  {
    return dim == 2 ? "x,y" : "x,y,z";
  }

  /// The same for messages: "x, y, z" or "x, y".
  inline std::string
  coordinate_list()
  {
    return dim == 2 ? "x, y" : "x, y, z";
  }

  /// A vector expression of zeros, one per coordinate: "0; 0; 0" or "0; 0".
  inline std::string
  zero_vector_expression()
  {
    return dim == 2 ? "0; 0" : "0; 0; 0";
  }

  /// "three", or "two" in 2-D: how many expressions a vector entry needs.
  inline std::string
  vector_size_word()
  {
    return dim == 2 ? "two" : "three";
  }

  /// The parser's message on @p expression, a function of @p variables
  /// ("x,y,z", "x,y,t", ...) with @p constants in muparser's syntax, as one
  /// line; empty if it parses and evaluates at the origin (muparser reports
  /// unknown names only when it evaluates). The parser's own report on
  /// std::cerr is swallowed: the caller's input error says it in its line.
  std::string
  expression_error(const std::string                   &expression,
                   const std::string                   &variables,
                   const std::map<std::string, double> &constants = {});
} // namespace DuctileContact
