#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/discretisation.h>

#include <array>
#include <deque>

namespace DuctileContact
{
  /**
   * Constraints of a Newton update at load time @p t: hanging nodes, and on
   * every Dirichlet DoF the update that moves the current displacement to
   * the prescribed value, delta = ubar(t) - u. When @p u is nullptr the
   * Dirichlet lines are homogeneous (same structure; used for the sparsity
   * pattern). The DoFs of every block marked in @p frozen keep their
   * values (homogeneous lines): the staggered scheme solves one group of
   * fields with the others fixed.
   * Returns "" or, when a prescribed value is not finite (an expression
   * that is NaN or Inf at @p t), which boundary condition gives it; its
   * DoFs are then held (homogeneous lines).
   */
  std::string
  make_newton_constraints(
    const Discretisation                             &discretisation,
    const std::deque<BoundaryCondition>              &boundary_conditions,
    const double                                      t,
    const dealii::TrilinosWrappers::MPI::BlockVector *u,
    dealii::AffineConstraints<double>                &constraints,
    const std::array<bool, Block::n_blocks> &frozen = {{false, false, false}});
} // namespace DuctileContact
