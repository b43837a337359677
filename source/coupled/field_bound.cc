#include <deal.II/base/mpi.h>

#include <ductile_contact/coupled/field_bound.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace DuctileContact
{
  using namespace dealii;


  namespace
  {
    /// The first DoF of @p block in the global numbering.
    types::global_dof_index
    block_offset(const Discretisation &discretisation, const unsigned int block)
    {
      types::global_dof_index offset = 0;
      for (unsigned int b = 0; b < block; ++b)
        offset += discretisation.dofs_per_block[b];
      return offset;
    }
  } // namespace



  FieldBound::FieldBound(const Discretisation &discretisation,
                         const unsigned int    block,
                         const double          upper)
      : discretisation(discretisation)
      , block_index(block)
      , upper_bound(upper)
      , has_upper(std::isfinite(upper))
      , offset(block_offset(discretisation, block))
  {
    Assert(block == Block::hardening || block == Block::phase_field,
           ExcInternalError());
  }



  std::string
  FieldBound::field_name() const
  {
    return block_index == Block::phase_field ? "s" : "alpha";
  }



  void
  FieldBound::record_diagonal(const TrilinosWrappers::BlockSparseMatrix &K)
  {
    const IndexSet &owned = discretisation.owned_partitioning[block_index];
    diagonal.reinit(owned, discretisation.dof_handler.get_communicator());
    const auto &K_xx = K.block(block_index, block_index);
    for (const auto i : owned)
      diagonal[i] = std::abs(K_xx.diag_element(i));
    diagonal.compress(VectorOperation::insert);
  }



  types::global_dof_index
  FieldBound::update_active_set(
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old,
    const TrilinosWrappers::MPI::BlockVector &residual,
    const AffineConstraints<double>          &constraints)
  {
    const IndexSet &owned = discretisation.owned_partitioning[block_index];
    const auto     &x     = u.block(block_index);
    const auto     &x_n   = old.block(block_index);
    const auto     &R     = residual.block(block_index);
    active                = IndexSet(owned.size());
    upper                 = IndexSet(owned.size());
    for (const auto i : owned)
      if (!constraints.is_constrained(offset + i))
        {
          if (R[i] + diagonal[i] * (lower(x_n[i]) - x[i]) > 0.)
            active.add_index(i);
          else if (has_upper && R[i] + diagonal[i] * (upper_bound - x[i]) < 0.)
            upper.add_index(i);
        }
    active.compress();
    upper.compress();
    return active_size();
  }



  unsigned int
  FieldBound::identify_active_set(
    const TrilinosWrappers::BlockSparseMatrix &K,
    const TrilinosWrappers::MPI::BlockVector  &newton_rhs,
    const TrilinosWrappers::MPI::BlockVector  &u,
    const TrilinosWrappers::MPI::BlockVector  &old,
    const AffineConstraints<double>           &constraints,
    DirectSolve                               &direct_solver,
    const unsigned int                         max_sweeps)
  {
    const IndexSet &owned = discretisation.owned_partitioning[block_index];
    const MPI_Comm  comm  = discretisation.dof_handler.get_communicator();
    const auto     &K_xx  = K.block(block_index, block_index);
    const auto     &x     = u.block(block_index);
    const auto     &x_n   = old.block(block_index);
    const auto     &b     = newton_rhs.block(block_index);

    const IndexSet                 first = active, first_upper = upper;
    TrilinosWrappers::SparseMatrix K_A;
    TrilinosWrappers::MPI::Vector  rhs(owned, comm), delta(owned, comm),
      r_lin(owned, comm);
    for (unsigned int sweep = 1;; ++sweep)
      {
        K_A.copy_from(K_xx);
        rhs = b;
        hold_active_rows(K_A, rhs, x, x_n);
        try
          {
            // The pattern of K_A is that of the block's: the solver's
            // analysis carries over from sweep to sweep and iteration to
            // iteration.
            direct_solver.factorize(K_A);
            direct_solver.apply(delta, rhs);
          }
        catch (const std::exception &)
          {
            // E.g. MUMPS out of workspace on a large 3-D block: keep the
            // set of update_active_set(), the coupled iteration refines it.
            active = first;
            upper  = first_upper;
            return 0;
          }
        // R_x + K_xx delta: zero on the free rows, the bound's reaction on
        // the rows of A.
        K_xx.vmult(r_lin, delta);
        r_lin -= b;

        IndexSet next(owned.size()), next_upper(owned.size());
        for (const auto i : owned)
          if (!constraints.is_constrained(offset + i))
            {
              if (r_lin[i] + diagonal[i] * (lower(x_n[i]) - x[i] - delta[i]) >
                  0.)
                next.add_index(i);
              else if (has_upper && r_lin[i] + diagonal[i] * (upper_bound -
                                                              x[i] - delta[i]) <
                                      0.)
                next_upper.add_index(i);
            }
        next.compress();
        next_upper.compress();
        const bool repeated =
          Utilities::MPI::min(next == active && next_upper == upper ? 1u : 0u,
                              comm) == 1u;
        active = next;
        upper  = next_upper;
        if (repeated || sweep == max_sweeps)
          return sweep;
      }
  }



  types::global_dof_index
  FieldBound::active_size() const
  {
    return Utilities::MPI::sum(active.n_elements() + upper.n_elements(),
                               discretisation.dof_handler.get_communicator());
  }



  void
  FieldBound::constrain(TrilinosWrappers::BlockSparseMatrix      &K,
                        TrilinosWrappers::MPI::BlockVector       &rhs,
                        const TrilinosWrappers::MPI::BlockVector &u,
                        const TrilinosWrappers::MPI::BlockVector &old) const
  {
    for (const IndexSet *set : {&active, &upper})
      for (const auto i : *set)
        for (unsigned int c = 0; c < Block::n_blocks; ++c)
          if (c != block_index)
            K.block(block_index, c).clear_row(i, 0.);
    hold_active_rows(K.block(block_index, block_index),
                     rhs.block(block_index),
                     u.block(block_index),
                     old.block(block_index));
  }



  void
  FieldBound::hold_active_rows(TrilinosWrappers::SparseMatrix      &K_xx,
                               TrilinosWrappers::MPI::Vector       &b,
                               const TrilinosWrappers::MPI::Vector &x,
                               const TrilinosWrappers::MPI::Vector &x_n) const
  {
    for (const IndexSet *set : {&active, &upper})
      for (const auto i : *set)
        K_xx.clear_row(i, diagonal[i]);
    hold_active_rhs(b, x, x_n);
  }



  void
  FieldBound::hold_active_rhs(TrilinosWrappers::MPI::Vector       &b,
                              const TrilinosWrappers::MPI::Vector &x,
                              const TrilinosWrappers::MPI::Vector &x_n) const
  {
    for (const auto i : active)
      b[i] = diagonal[i] * (lower(x_n[i]) - x[i]);
    for (const auto i : upper)
      b[i] = diagonal[i] * (upper_bound - x[i]);
    b.compress(VectorOperation::insert);
  }



  bool
  FieldBound::keep_active_set(
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old,
    const TrilinosWrappers::MPI::BlockVector &residual,
    const AffineConstraints<double>          &constraints,
    TrilinosWrappers::MPI::BlockVector       &rhs)
  {
    const IndexSet kept = active, kept_upper = upper;
    update_active_set(u, old, residual, constraints);
    const bool same =
      Utilities::MPI::min((active == kept && upper == kept_upper) ? 1 : 0,
                          discretisation.dof_handler.get_communicator()) == 1;
    if (!same)
      return false;
    hold_active_rhs(rhs.block(block_index),
                    u.block(block_index),
                    old.block(block_index));
    return true;
  }



  void
  FieldBound::to_complementarity(
    TrilinosWrappers::MPI::BlockVector       &residual,
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old,
    const AffineConstraints<double>          &constraints) const
  {
    const IndexSet &owned = discretisation.owned_partitioning[block_index];
    const auto     &x     = u.block(block_index);
    const auto     &x_n   = old.block(block_index);
    auto           &R     = residual.block(block_index);
    for (const auto i : owned)
      if (!constraints.is_constrained(offset + i))
        {
          R[i] = std::min<double>(R[i], diagonal[i] * (x[i] - lower(x_n[i])));
          if (has_upper)
            R[i] = std::max<double>(R[i], diagonal[i] * (x[i] - upper_bound));
        }
    R.compress(VectorOperation::insert);
  }



  void
  FieldBound::remove_active_rows(TrilinosWrappers::MPI::BlockVector &v) const
  {
    auto &block = v.block(block_index);
    for (const IndexSet *set : {&active, &upper})
      for (const auto i : *set)
        block[i] = 0.;
    block.compress(VectorOperation::insert);
  }
} // namespace DuctileContact
