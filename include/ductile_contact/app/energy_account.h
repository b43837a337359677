#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/assembly/assembly_data.h>
#include <ductile_contact/output/statistics.h>

namespace DuctileContact
{
  /**
   * The energy account of a run (doc/model.md section 6), summed over accepted
   * steps: the external work by the trapezoidal rule,
   *
   *   W_ext += 1/2 (f_n + f_n+1) . (u_n+1 - u_n)
   *
   * (f the internal force, whose entries on prescribed DoFs are the
   * reactions), the plastic work W_p, the viscous phase-field dissipation
   * D_f and the history driving work (AssemblyInfo), and the energy-balance
   * residual
   *
   *   W_ext - Psi^e - W_p + R_p - g_c int gamma - D_f - D_c
   *   = W_ext - Psi^e - Psi^p - D_p - g_c int gamma - D_f - D_c
   *
   * with D_c the frictional dissipation (47) of the contact pairs, R_p the
   * plastic energy the crack has released (0 unless the plastic energy is
   * degraded, Crack driver = elastic and plastic energy) and D_p = W_p -
   * Psi^p - R_p the plastic dissipation. All in [J]. The crack energy
   * enters as its change since the start (an initial crack's own energy is
   * not work done on the solid).
   *
   * In a dynamic run f holds the inertial force too (its Dirichlet rows are
   * the reactions of the moving bodies), and the residual also subtracts
   * the inertial work W_in = sum of int rho (u_n+1 - u_n) . (a_m,n +
   * a_m,n+1)/2 dV, which is the change of kinetic energy K - K_0 plus the
   * scheme's numerical dissipation D_num = W_in - (K - K_0) (0 for the
   * trapezoidal rule; doc/model.md section 6.5).
   */
  class EnergyAccount
  {
  public:
    /// The state at t = 0 (its crack energy is the zero of the account).
    void
    start(const AssemblyInfo &initial)
    {
      initial_fracture_energy = initial.fracture_energy;
      initial_kinetic_energy  = initial.kinetic_energy;
    }

    /// Adds an accepted step: internal force @p force at its end, the
    /// increment @p increment of the solution and the commit's @p committed.
    void
    add_step(const dealii::TrilinosWrappers::MPI::BlockVector &force,
             const dealii::TrilinosWrappers::MPI::BlockVector &increment,
             const AssemblyInfo                               &committed);

    /// The columns stored_energy, external_work, [plastic_work,
    /// hardening_energy], [fracture_energy, fracture_viscous_work,
    /// history_driving_work] and energy_residual at the state @p committed;
    /// with plasticity also plastic_dissipation, plastic_energy_released,
    /// the step's smallest local plastic dissipation min_plastic_dissipation
    /// [J/m^3] and the smallest alpha at a quadrature point, min_alpha;
    /// if @p dynamic kinetic_energy, numerical_dissipation and
    /// momentum_x, _y, _z.
    void
    add_columns(Statistics         &statistics,
                const AssemblyInfo &committed,
                const bool          plastic,
                const bool          cracking,
                const bool          dynamic,
                const double        contact_dissipation) const;

    /// The force of the last accepted step (trapezoidal external work).
    dealii::TrilinosWrappers::MPI::BlockVector &
    last_force()
    {
      return previous_force;
    }

    /// The sums so far (checkpoints; last_force() travels on the mesh).
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &external_work &plastic_work &fracture_viscous_work
        &history_driving_work &plastic_energy_released &initial_fracture_energy
          &inertial_work &initial_kinetic_energy;
    }

  private:
    dealii::TrilinosWrappers::MPI::BlockVector previous_force;
    double                                     external_work           = 0.;
    double                                     plastic_work            = 0.;
    double                                     fracture_viscous_work   = 0.;
    double                                     history_driving_work    = 0.;
    double                                     plastic_energy_released = 0.;
    double                                     initial_fracture_energy = 0.;
    double                                     inertial_work           = 0.;
    double                                     initial_kinetic_energy  = 0.;
  };
} // namespace DuctileContact
