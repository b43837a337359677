#pragma once

#include <type_traits>

namespace DuctileContact
{
  /**
   * The value of a plain number or of a Sacado forward-mode AD number or
   * expression (its val()), for branches on values in code templated on
   * the number type (the plastic update, the contact geometry).
   */
  template <typename Number>
  inline double
  value_of(const Number &x)
  {
    if constexpr (std::is_arithmetic_v<Number>)
      return x;
    else
      return x.val();
  }
} // namespace DuctileContact
