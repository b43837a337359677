#pragma once

#include <ductile_contact/core/option.h>

namespace DuctileContact
{
  /// Finite elements/Phase-field basis: the basis of the s field (the same
  /// Q_p space either way).
  enum class FieldBasis
  {
    lagrange,
    bernstein
  };

  inline const NameTable<FieldBasis> &
  field_basis_names()
  {
    static const NameTable<FieldBasis> t{{FieldBasis::lagrange, "Lagrange"},
                                         {FieldBasis::bernstein, "Bernstein"}};
    return t;
  }
} // namespace DuctileContact
