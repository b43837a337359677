#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ductile_contact/solver/constrained_rows.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <Epetra_MultiVector.h>
#include <memory>

namespace DuctileContact
{
  /**
   * Approximate inverse of the displacement block A inside the Krylov
   * solvers: one V-cycle of ML smoothed-aggregation AMG on A, or, where A
   * holds constraint rows (ConstrainedNodes) and `Constrained rows =
   * eliminate`, a block factorisation that takes the constrained
   * components out first. With Q the nodal frames (identity elsewhere), the
   * rotated block splits into the constrained components c and the rest r,
   *
   *   Q A Q^T = [ C_cc  C_cr ]     x_r = S^-1 (b_r - A_rc W b_c)
   *             [ A_rc  A_rr ],    x_c = W (b_c - C_cr x_r),
   *
   *   S = A_rr - A_rc W C_cr,   W = diag(C_cc)^-1,
   *
   * (b = Q r, the result Q^T x) with S^-1 one AMG V-cycle on S. S is the
   * stiffness of the bodies tied by the constraints (for contact: the
   * slave's normal motion given by the master's through the mortar
   * projection D^-1 M), an elliptic operator as the AMG assumes; the
   * constraint rows themselves, which are not, never reach it. With the
   * exact C_cc^-1 and S^-1 this is the exact inverse; W ignores the
   * coupling of neighbouring nodes' constrained components (through the
   * derivatives of normals and mortar weights), which the outer Krylov
   * iteration makes up for.
   */
  class DisplacementPreconditioner
  {
  public:
    DisplacementPreconditioner();
    ~DisplacementPreconditioner();

    /**
     * Builds it for @p A with the AMG of initialize_amg() (@p degree, @p
     * modes: the near-null space on A's rows, null: the constant);
     * eliminates the components of @p nodes (null or empty: none) when
     * @p parameters ask for it. Collective.
     */
    void
    initialize(const dealii::TrilinosWrappers::SparseMatrix &A,
               const ConstrainedNodes                       *nodes,
               const LinearSolverParameters                 &parameters,
               unsigned int                                  degree,
               const Epetra_MultiVector                     *modes);

    /// dst = P^-1 src.
    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

    /// Components eliminated on all ranks (0: the AMG on A).
    unsigned int
    n_eliminated() const;

  private:
    class Elimination;
    std::unique_ptr<Elimination>              elimination;
    dealii::TrilinosWrappers::PreconditionAMG amg;
    /// vmult()'s work vectors with the elimination: Q r, and the
    /// right-hand side of the AMG on S.
    mutable dealii::TrilinosWrappers::MPI::Vector rotated_rhs, rest_rhs;
  };
} // namespace DuctileContact
