#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_MultiVector.h>
#include <Epetra_RowMatrix.h>
#include <memory>

namespace DuctileContact
{
  /**
   * ML smoothed-aggregation AMG of an elliptic block @p A with the
   * `Linear solver` section's smoother and sweeps, @p aggregation_threshold,
   * higher-order settings for elements of @p degree > 1, and @p modes as
   * its near-null space (null: the constant, ML's default).
   */
  void
  initialize_amg(const dealii::TrilinosWrappers::SparseMatrix &A,
                 dealii::TrilinosWrappers::PreconditionAMG    &amg,
                 const LinearSolverParameters                 &parameters,
                 unsigned int                                  degree,
                 double                    aggregation_threshold,
                 const Epetra_MultiVector *modes = nullptr);

  /// The same for a matrix built outside deal.II (its map that of the
  /// block's rows, as @p modes').
  void
  initialize_amg(const Epetra_RowMatrix                    &A,
                 dealii::TrilinosWrappers::PreconditionAMG &amg,
                 const LinearSolverParameters              &parameters,
                 unsigned int                               degree,
                 double                    aggregation_threshold,
                 const Epetra_MultiVector *modes = nullptr);

  /**
   * The rigid-body modes on the locally owned displacement DoFs (block-local
   * numbers), the near-null space of the displacement AMG: the dim
   * translations e_r and a rotation in each coordinate plane (i, j), u_i =
   * -x_j, u_j = x_i, at the support points; with @p per_body a set of
   * them per body (zero off the body): bodies that touch through contact
   * alone move rigidly against each other at little energy (a sliding
   * block, a cantilever under its indenter).
   */
  std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes(const Discretisation &discretisation, bool per_body);

  /**
   * The constant and the dim coordinates on the locally owned DoFs of the
   * phase-field block (block-local numbers): the near-null space of its AMG,
   * which the fourth-order part does not see. Null without s DoFs.
   */
  std::unique_ptr<Epetra_MultiVector>
  make_phase_field_modes(const Discretisation &discretisation);
} // namespace DuctileContact
