#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/assembly/assembly_data.h>

#include <vector>

namespace DuctileContact
{
  /**
   * Adds one local contribution to every requested target: tangent and
   * Newton right-hand side -R (condensed with the Newton @p constraints),
   * the residual R = -@p rhs, and @p f_int condensed with the
   * @p hanging_nodes constraints only. Used by the
   * bulk assembly (cells and C0IP faces) and by contact.
   */
  void
  scatter(const dealii::FullMatrix<double>                   &matrix,
          const dealii::Vector<double>                       &rhs,
          const dealii::Vector<double>                       &f_int,
          const std::vector<dealii::types::global_dof_index> &indices,
          const dealii::AffineConstraints<double>            &constraints,
          const dealii::AffineConstraints<double>            &hanging_nodes,
          const AssemblyTargets                              &targets);

  /// Ends an assembly into @p targets: compresses (adds across ranks) every
  /// matrix and vector it holds. Used after the bulk and after the contact
  /// terms.
  void
  compress(const AssemblyTargets &targets);
} // namespace DuctileContact
