#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ductile_contact/core/option.h>

#include <string>

namespace DuctileContact
{
  /**
   * Subsection `Coupling`: how the fields [u | alpha | s] are solved at a
   * load step when a body cracks.
   *
   *  - monolithic: Newton on all fields at once with the exact coupled
   *    tangent;
   *  - staggered: alternate minimisation, Newton on (u, alpha) with s fixed,
   *    then on s with (u, alpha) fixed, repeated until a sub-solve finds its
   *    fields already converged (so all blocks meet the Newton tolerances
   *    at the same state, as in the monolithic scheme); optionally with
   *    Anderson acceleration of the phase field between alternations
   *    (AndersonAcceleration);
   *  - monolithic-staggered: monolithic, and a step where Newton fails is
   *    redone staggered before it is cut back.
   *
   * Irreversibility of s (doc/model.md section 2): `history` (the crack driver
   * uses the history maximum of psi^+), `bound` (s_i >= s_n,i at every
   * phase-field DoF, FieldBound, with the driver from the current
   * psi^+) or `history and bound` (default: both).
   */
  /// Coupling/Strategy.
  enum class CouplingStrategy
  {
    monolithic,
    staggered,
    monolithic_staggered
  };

  inline const NameTable<CouplingStrategy> &
  coupling_strategy_names()
  {
    static const NameTable<CouplingStrategy> t{
      {CouplingStrategy::monolithic, "monolithic"},
      {CouplingStrategy::staggered, "staggered"},
      {CouplingStrategy::monolithic_staggered, "monolithic-staggered"}};
    return t;
  }

  /// Coupling/Irreversibility.
  enum class Irreversibility
  {
    history,
    bound,
    history_and_bound
  };

  inline const NameTable<Irreversibility> &
  irreversibility_names()
  {
    static const NameTable<Irreversibility> t{
      {Irreversibility::history, "history"},
      {Irreversibility::bound, "bound"},
      {Irreversibility::history_and_bound, "history and bound"}};
    return t;
  }

  struct CouplingParameters
  {
    CouplingStrategy strategy                 = CouplingStrategy::monolithic;
    unsigned int     max_staggered_iterations = 200;
    /// Anderson depth m for the staggered phase field (0: plain).
    unsigned int    acceleration_depth = 0;
    Irreversibility irreversibility    = Irreversibility::history_and_bound;
    /// Whether alpha_n <= alpha is enforced at the alpha DoFs: not an
    /// entry of this subsection but the plastic bodies' Plasticity/Loading
    /// condition = bound (set by RunParameters::check()).
    bool hardening_bound = false;

    /// Whether the crack driver keeps the history maximum of psi^+.
    bool
    crack_history() const
    {
      return irreversibility != Irreversibility::bound;
    }
    /// Whether s_n <= s <= 1 is enforced at the phase-field DoFs.
    bool
    phase_field_bound() const
    {
      return irreversibility != Irreversibility::history;
    }

    void
    declare(dealii::ParameterHandler &prm);
    void
    check() const;
  };
} // namespace DuctileContact
