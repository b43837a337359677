#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/discretisation/boundary_condition.h>
#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_parameters.h>
#include <ductile_contact/solver/solver_parameters.h>

#include <deque>
#include <vector>

namespace DuctileContact
{
  /**
   * The Bossak-alpha scheme of a dynamic run (Load stepping/Time
   * integration = Bossak; Wood, Bossak & Zienkiewicz 1980; doc/model.md
   * section 6.5). The momentum balance takes the inertia at
   *
   *   a_m,n+1 = (1 - a_B) a_n+1 + a_B a_n,
   *
   * with Newmark's update
   *
   *   u_n+1 = u_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_n+1),
   *   v_n+1 = v_n + dt ((1 - gamma) a_n + gamma a_n+1),
   *
   * a_B = (rho_inf - 1)/(rho_inf + 1), gamma = 1/2 - a_B, beta = (1 -
   * a_B)^2/4: second order, unconditionally stable, rho_inf the spectral
   * radius at omega dt -> infinity (1: the trapezoidal rule). So a_m is
   * linear in u_n+1, a_m = c (u_n+1 - u*), which is what the assembly
   * needs (InertiaTerms).
   *
   * The nodes of @p massless_boundaries carry no mass: the cells there take
   * their mass matrix from redistributed_mass_rule() (InertiaTerms::
   * massless).
   *
   * Holds the state v_n, a_n, a_m,n of the displacement block (the other
   * blocks stay zero), for checkpoints and mesh transfer by vectors().
   *
   * local_error() is the estimate of Zienkiewicz & Xie (1991) of a step's
   * local displacement error, e = (beta - 1/6) dt^2 (a_n+1 - a_n), that
   * the step control of Load stepping/Local error tolerance reads.
   */
  class TimeIntegrator
  {
  public:
    /// @p massless_boundaries: the boundary ids whose nodes carry no mass
    /// (the contact surfaces with Contact surface mass = redistributed).
    /// @p boundary_conditions: their prescribed DoFs are left out of
    /// local_error().
    TimeIntegrator(
      const LoadSteppingParameters                  &parameters,
      const std::deque<BodyParameters>              &bodies,
      const std::deque<BoundaryCondition>           &boundary_conditions,
      const Discretisation                          &discretisation,
      const std::vector<dealii::types::boundary_id> &massless_boundaries);

    /// Sizes the vectors (zero) and finds the massless DoFs; after every
    /// DoF distribution.
    void
    setup();

    /// v_0 from the bodies' Initial velocity, a_0 = a_m,0 = 0.
    void
    start();

    /// The terms of the commit at t = 0: v_0 (kinetic energy, momentum),
    /// no inertial work.
    const InertiaTerms &
    initial_terms();

    /// The inertia of the step of size @p dt from the accepted @p u_n.
    const InertiaTerms &
    step_terms(const dealii::TrilinosWrappers::MPI::BlockVector &u_n,
               const double                                      dt);

    /// The accepted step from @p u_n to @p u (size @p dt): a_n+1, v_n+1
    /// and a_m,n+1, kept until accept(); the terms of the commit pass.
    const InertiaTerms &
    commit_terms(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                 const dealii::TrilinosWrappers::MPI::BlockVector &u_n,
                 const double                                      dt);

    /// The relative local error of the converged step from @p u_n to @p u
    /// (size @p dt): the largest |e| over the DoFs with mass that no
    /// boundary condition prescribes, over the largest |u - u_n| there (0
    /// when nothing moves). The same on every rank.
    double
    local_error(const dealii::TrilinosWrappers::MPI::BlockVector &u,
                const dealii::TrilinosWrappers::MPI::BlockVector &u_n,
                const double                                      dt) const;

    /// Makes the state of commit_terms() the accepted one.
    void
    accept();

    /// Terms whose inertial force is that of the accepted state at @p u_n,
    /// M a_m,n (c = 1, u* = u_n - a_m,n): the last force after a transfer.
    const InertiaTerms &
    accepted_terms(const dealii::TrilinosWrappers::MPI::BlockVector &u_n);

    /// v_n, a_n, a_m,n (owned entries): what checkpoints and the mesh
    /// transfer carry.
    std::vector<dealii::TrilinosWrappers::MPI::BlockVector *>
    vectors()
    {
      return {&velocity, &acceleration, &inertial_acceleration};
    }

    /// v_n of the accepted state (owned entries).
    const dealii::TrilinosWrappers::MPI::BlockVector &
    current_velocity() const
    {
      return velocity;
    }

    /// Copies of vectors() with ghost entries.
    std::vector<dealii::TrilinosWrappers::MPI::BlockVector>
    ghosted_vectors() const;

    /// a_B, beta, gamma.
    double alpha_b, beta, gamma;

  private:
    /// A fresh #terms with the massless DoFs.
    InertiaTerms &
    reset_terms();

    const std::deque<BodyParameters>             &bodies;
    const std::deque<BoundaryCondition>          &boundary_conditions;
    const Discretisation                         &discretisation;
    const std::vector<dealii::types::boundary_id> massless_boundaries;
    /// The u DoFs on those boundaries (sorted, locally relevant).
    std::vector<dealii::types::global_dof_index> massless;
    /// The owned u DoFs whose error local_error() measures: with mass, not
    /// prescribed.
    dealii::IndexSet measured;

    dealii::TrilinosWrappers::MPI::BlockVector velocity, acceleration,
      inertial_acceleration;
    /// The step's a_n+1, v_n+1, a_m,n+1 (commit_terms() to accept()).
    dealii::TrilinosWrappers::MPI::BlockVector new_velocity, new_acceleration,
      new_inertial_acceleration;
    /// Ghosted vectors the assembly reads.
    dealii::TrilinosWrappers::MPI::BlockVector target, velocity_ghosted,
      mean_acceleration;
    InertiaTerms terms;
  };
} // namespace DuctileContact
