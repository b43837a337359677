#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
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

  /// K(rows, columns) += @p matrix (rows.size() x columns.size()) where
  /// none of the DoFs is constrained by @p constraints (then scatter()
  /// would add the same entries, and no right-hand side changes): a block
  /// of a few rows and many columns without the square local matrix.
  void
  scatter_matrix_block(
    const dealii::FullMatrix<double>                   &matrix,
    const std::vector<dealii::types::global_dof_index> &rows,
    const std::vector<dealii::types::global_dof_index> &columns,
    const dealii::AffineConstraints<double>            &constraints,
    dealii::TrilinosWrappers::BlockSparseMatrix        &tangent);

  /// Starts an assembly into @p targets: zeroes every matrix and vector it
  /// holds. The matrix is zeroed in place: deal.II's `K = 0` compresses
  /// first, which sends the whole non-local pattern across the ranks (all
  /// zeros after the compress() that ends every assembly): ~5 ms per tangent
  /// on prm/two_bodies.prm for nothing. An assembly that does not end with
  /// compress() ends the run (nothing catches an exception from it), so the
  /// non-local part is zero here.
  void
  zero(const AssemblyTargets &targets);

  /// Ends an assembly into @p targets: compresses (adds across ranks) every
  /// matrix and vector it holds. Used after the bulk and after the contact
  /// terms.
  void
  compress(const AssemblyTargets &targets);
} // namespace DuctileContact
