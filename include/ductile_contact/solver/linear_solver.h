#pragma once

#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_MultiVector.h>
#include <memory>

namespace DuctileContact
{
  /**
   * Solves the Newton system K delta = b on the displacement block with a
   * sparse direct solver (Trilinos Amesos: KLU or MUMPS) or with CG / GMRES
   * preconditioned by ML smoothed-aggregation AMG, whose near-null space is
   * the six rigid-body modes of the displacement DoFs (three translations,
   * three rotations about the support points).
   *
   * The alpha and s blocks are empty until their equations exist; solving a
   * system with non-empty ones is refused.
   */
  class LinearSolver
  {
  public:
    LinearSolver(const LinearSolverParameters &parameters,
                 const Discretisation         &discretisation);

    /// Recomputes the rigid-body modes; call after every DoF distribution.
    void
    setup();

    /// Returns the number of iterations (1 for the direct solver).
    unsigned int
    solve(const dealii::TrilinosWrappers::BlockSparseMatrix &K,
          dealii::TrilinosWrappers::MPI::BlockVector        &x,
          const dealii::TrilinosWrappers::MPI::BlockVector  &b);

  private:
    const LinearSolverParameters &parameters;
    const Discretisation         &discretisation;

    /// Rigid-body modes on the locally owned displacement DoFs.
    std::unique_ptr<Epetra_MultiVector> rigid_body_modes;
  };
} // namespace DuctileContact
