#include <deal.II/base/mpi.h>

#include <ductile_contact/solver/phase_field_bound.h>

#include <algorithm>
#include <cmath>

namespace DuctileContact
{
  using namespace dealii;

  PhaseFieldBound::PhaseFieldBound(const Discretisation &discretisation)
      : discretisation(discretisation)
      , offset(discretisation.dofs_per_block[Block::displacement] +
               discretisation.dofs_per_block[Block::hardening])
  {
  }



  void
  PhaseFieldBound::record_diagonal(const TrilinosWrappers::BlockSparseMatrix &K)
  {
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::phase_field];
    diagonal.reinit(owned, discretisation.dof_handler.get_communicator());
    const auto &K_ss = K.block(Block::phase_field, Block::phase_field);
    for (const auto i : owned)
      diagonal[i] = std::abs(K_ss.diag_element(i));
    diagonal.compress(VectorOperation::insert);
  }



  types::global_dof_index
  PhaseFieldBound::update_active_set(
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old,
    const TrilinosWrappers::MPI::BlockVector &residual,
    const AffineConstraints<double>          &constraints)
  {
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::phase_field];
    const auto &s   = u.block(Block::phase_field);
    const auto &s_n = old.block(Block::phase_field);
    const auto &R   = residual.block(Block::phase_field);
    active          = IndexSet(owned.size());
    for (const auto i : owned)
      if (!constraints.is_constrained(offset + i) &&
          R[i] + diagonal[i] * (s_n[i] - s[i]) > 0.)
        active.add_index(i);
    active.compress();
    return Utilities::MPI::sum(active.n_elements(),
                               discretisation.dof_handler.get_communicator());
  }



  void
  PhaseFieldBound::constrain(
    TrilinosWrappers::BlockSparseMatrix      &K,
    TrilinosWrappers::MPI::BlockVector       &rhs,
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old) const
  {
    const auto &s   = u.block(Block::phase_field);
    const auto &s_n = old.block(Block::phase_field);
    auto       &b   = rhs.block(Block::phase_field);
    for (const auto i : active)
      {
        for (unsigned int c = 0; c < Block::n_blocks; ++c)
          K.block(Block::phase_field, c)
            .clear_row(i, c == Block::phase_field ? diagonal[i] : 0.);
        b[i] = diagonal[i] * (s_n[i] - s[i]);
      }
    b.compress(VectorOperation::insert);
  }



  void
  PhaseFieldBound::to_complementarity(
    TrilinosWrappers::MPI::BlockVector       &residual,
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old,
    const AffineConstraints<double>          &constraints) const
  {
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::phase_field];
    const auto &s   = u.block(Block::phase_field);
    const auto &s_n = old.block(Block::phase_field);
    auto       &R   = residual.block(Block::phase_field);
    for (const auto i : owned)
      if (!constraints.is_constrained(offset + i))
        R[i] = std::min<double>(R[i], diagonal[i] * (s[i] - s_n[i]));
    R.compress(VectorOperation::insert);
  }



  void
  PhaseFieldBound::remove_active_rows(
    TrilinosWrappers::MPI::BlockVector &v) const
  {
    auto &block = v.block(Block::phase_field);
    for (const auto i : active)
      block[i] = 0.;
    block.compress(VectorOperation::insert);
  }
} // namespace DuctileContact
