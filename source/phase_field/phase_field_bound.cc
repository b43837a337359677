#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <ductile_contact/phase_field/phase_field_bound.h>

#include <algorithm>
#include <cmath>
#include <exception>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The lower bound of the box at a DoF whose accepted value is @p s_n:
    /// s_n, but at most the upper bound 1 (an accepted s_n above 1, from a
    /// run without the bound, must not empty the box).
    double
    lower(const double s_n)
    {
      return std::min(s_n, 1.);
    }
  } // namespace

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
    upper           = IndexSet(owned.size());
    for (const auto i : owned)
      if (!constraints.is_constrained(offset + i))
        {
          if (R[i] + diagonal[i] * (lower(s_n[i]) - s[i]) > 0.)
            active.add_index(i);
          else if (R[i] + diagonal[i] * (1. - s[i]) < 0.)
            upper.add_index(i);
        }
    active.compress();
    upper.compress();
    return active_size();
  }



  unsigned int
  PhaseFieldBound::identify_active_set(
    const TrilinosWrappers::BlockSparseMatrix &K,
    const TrilinosWrappers::MPI::BlockVector  &newton_rhs,
    const TrilinosWrappers::MPI::BlockVector  &u,
    const TrilinosWrappers::MPI::BlockVector  &old,
    const AffineConstraints<double>           &constraints,
    const std::string                         &direct_solver,
    const unsigned int                         max_sweeps)
  {
    const IndexSet &owned =
      discretisation.owned_partitioning[Block::phase_field];
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    const auto    &K_ss = K.block(Block::phase_field, Block::phase_field);
    const auto    &s    = u.block(Block::phase_field);
    const auto    &s_n  = old.block(Block::phase_field);
    const auto    &b    = newton_rhs.block(Block::phase_field);

    const IndexSet                 first = active, first_upper = upper;
    TrilinosWrappers::SparseMatrix K_A;
    TrilinosWrappers::MPI::Vector  rhs(owned, comm), delta(owned, comm),
      r_lin(owned, comm);
    for (unsigned int sweep = 1;; ++sweep)
      {
        K_A.copy_from(K_ss);
        rhs = b;
        hold_active_rows(K_A, rhs, s, s_n);
        SolverControl                  control(1, 0.);
        TrilinosWrappers::SolverDirect direct(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(false, direct_solver));
        try
          {
            direct.solve(K_A, delta, rhs);
          }
        catch (const std::exception &)
          {
            // E.g. MUMPS out of workspace on a large 3-D s block: keep the
            // set of update_active_set(), the coupled iteration refines it.
            active = first;
            upper  = first_upper;
            return 0;
          }
        // R_s + K_ss delta: zero on the free rows, the bound's reaction on
        // the rows of A.
        K_ss.vmult(r_lin, delta);
        r_lin -= b;

        IndexSet next(owned.size()), next_upper(owned.size());
        for (const auto i : owned)
          if (!constraints.is_constrained(offset + i))
            {
              if (r_lin[i] + diagonal[i] * (lower(s_n[i]) - s[i] - delta[i]) > 0.)
                next.add_index(i);
              else if (r_lin[i] + diagonal[i] * (1. - s[i] - delta[i]) < 0.)
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
  PhaseFieldBound::active_size() const
  {
    return Utilities::MPI::sum(active.n_elements() + upper.n_elements(),
                               discretisation.dof_handler.get_communicator());
  }



  void
  PhaseFieldBound::constrain(
    TrilinosWrappers::BlockSparseMatrix      &K,
    TrilinosWrappers::MPI::BlockVector       &rhs,
    const TrilinosWrappers::MPI::BlockVector &u,
    const TrilinosWrappers::MPI::BlockVector &old) const
  {
    for (const IndexSet *set : {&active, &upper})
      for (const auto i : *set)
        for (unsigned int c = 0; c < Block::n_blocks; ++c)
          if (c != Block::phase_field)
            K.block(Block::phase_field, c).clear_row(i, 0.);
    hold_active_rows(K.block(Block::phase_field, Block::phase_field),
                     rhs.block(Block::phase_field),
                     u.block(Block::phase_field),
                     old.block(Block::phase_field));
  }



  void
  PhaseFieldBound::hold_active_rows(
    TrilinosWrappers::SparseMatrix      &K_ss,
    TrilinosWrappers::MPI::Vector       &b,
    const TrilinosWrappers::MPI::Vector &s,
    const TrilinosWrappers::MPI::Vector &s_n) const
  {
    for (const auto i : active)
      {
        K_ss.clear_row(i, diagonal[i]);
        b[i] = diagonal[i] * (lower(s_n[i]) - s[i]);
      }
    for (const auto i : upper)
      {
        K_ss.clear_row(i, diagonal[i]);
        b[i] = diagonal[i] * (1. - s[i]);
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
        R[i] = std::max<double>(std::min<double>(R[i],
                                                 diagonal[i] * (s[i] - lower(s_n[i]))),
                                diagonal[i] * (s[i] - 1.));
    R.compress(VectorOperation::insert);
  }



  void
  PhaseFieldBound::remove_active_rows(
    TrilinosWrappers::MPI::BlockVector &v) const
  {
    auto &block = v.block(Block::phase_field);
    for (const IndexSet *set : {&active, &upper})
      for (const auto i : *set)
        block[i] = 0.;
    block.compress(VectorOperation::insert);
  }
} // namespace DuctileContact
