#pragma once

#include <deal.II/base/types.h>

#include <vector>

namespace DuctileContact
{
  /**
   * A node of the displacement block whose rows, turned into the node's
   * orthonormal frame Q (rows q_k), hold constraints in their first
   * n_constrained rows: q_k^T R_node = 0 ties the node's own displacement
   * to its neighbours' and carries no bulk stiffness of it (the
   * complementarity rows of an active contact node: its normal row, and its
   * tangential rows where it sticks). The other rows are ordinary
   * equilibrium rows. The linear solver may eliminate the constrained
   * components (DisplacementPreconditioner); the solution is the same.
   */
  struct ConstrainedNode
  {
    /// The node's displacement DoFs, one per component (numbers of the
    /// displacement block).
    std::vector<dealii::types::global_dof_index> dofs;
    /// Q row by row: q_k = frame[k * n + 0 ... k * n + n - 1], n =
    /// dofs.size().
    std::vector<double> frame;
    /// Rows of Q K_node that are constraints: the first this many.
    unsigned int n_constrained = 0;
  };

  /// Every constrained node of the system, the same list on every rank.
  using ConstrainedNodes = std::vector<ConstrainedNode>;
} // namespace DuctileContact
