#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_parameters.h>

#include <deque>
#include <map>

namespace DuctileContact
{
  /// What one assembly pass found (all values summed over MPI ranks).
  struct AssemblyInfo
  {
    /// An element is inverted (J <= 0 at a quadrature point): the state
    /// is not admissible and nothing else here is meaningful.
    bool   inverted = false;
    double min_J    = 1.;
    /// int Psi dV over the reference configuration [J].
    double stored_energy = 0.;
    /// Size of the terms summed into f_int: sqrt of the sum over cells and
    /// DoFs of (sum over quadrature points of (|P : Grad N_i| + (mu + kappa)
    /// |Grad N_i|) JxW)^2 [N]. F = I + Grad u resolves Grad u only to eps,
    /// so P is uncertain by eps (mu + kappa): ||R|| cannot drop much below
    /// eps times this, whatever the solver does.
    double force_magnitude = 0.;
  };

  /// Where assemble() writes; null members are skipped.
  struct AssemblyTargets
  {
    /// Newton tangent K, condensed with the Newton constraints.
    dealii::TrilinosWrappers::BlockSparseMatrix *tangent = nullptr;
    /// -R condensed with the (inhomogeneous) Newton constraints: the
    /// right-hand side of K delta = -R.
    dealii::TrilinosWrappers::MPI::BlockVector *newton_rhs = nullptr;
    /// R = f_int - f_ext on free DoFs (constrained entries zero): its norm
    /// decides convergence.
    dealii::TrilinosWrappers::MPI::BlockVector *residual = nullptr;
    /// f_int condensed with the hanging-node constraints only (Dirichlet
    /// rows kept): reactions and external work come from it.
    dealii::TrilinosWrappers::MPI::BlockVector *internal_force = nullptr;
  };

  /**
   * Residual and exact tangent of the total-Lagrangian equilibrium
   *
   *   R(u) = int_B P(F) : Grad du dV - int_dB T . du dA = 0,  F = I + Grad u,
   *
   * with P and A = dP/dF from the body's material (model.md (16)/(19)) and
   * dead-load nominal tractions T. A pure assembly: it does not own vectors,
   * know the load history or decide anything.
   */
  class SystemAssembler
  {
  public:
    SystemAssembler(const Discretisation                   &discretisation,
                    const std::map<dealii::types::material_id,
                                   const BodyParameters *> &bodies,
                    const std::deque<BoundaryCondition> &boundary_conditions);

    /// @p u must have ghost entries. Matrices/vectors in @p targets are
    /// zeroed and compressed here.
    AssemblyInfo
    assemble(const dealii::TrilinosWrappers::MPI::BlockVector &u,
             const double                                      t,
             const dealii::AffineConstraints<double>          &constraints,
             const AssemblyTargets                            &targets) const;

  private:
    const Discretisation &discretisation;
    const std::map<dealii::types::material_id, const BodyParameters *> bodies;
    const std::deque<BoundaryCondition> &boundary_conditions;
  };
} // namespace DuctileContact
