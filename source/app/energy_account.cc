#include <ductile_contact/app/energy_account.h>

#include <limits>

namespace DuctileContact
{
  void
  EnergyAccount::add_step(
    const dealii::TrilinosWrappers::MPI::BlockVector &force,
    const dealii::TrilinosWrappers::MPI::BlockVector &increment,
    const AssemblyInfo                               &committed)
  {
    if (previous_force.size() == 0)
      previous_force.reinit(force); // zero: the unloaded start
    external_work += 0.5 * (force * increment + previous_force * increment);
    previous_force = force;
    plastic_work += committed.plastic_work_increment;
    fracture_viscous_work += committed.fracture_viscous_work_increment;
    history_driving_work += committed.history_work_increment;
    plastic_energy_released += committed.plastic_energy_release_increment;
    inertial_work += committed.inertial_work_increment;
  }



  void
  EnergyAccount::add_columns(Statistics         &statistics,
                             const AssemblyInfo &committed,
                             const bool          plastic,
                             const bool          cracking,
                             const bool          dynamic,
                             const double        contact_dissipation) const
  {
    statistics.add("stored_energy", committed.stored_energy);
    statistics.add("external_work", external_work);
    if (plastic)
      {
        statistics.add("plastic_work", plastic_work);
        statistics.add("hardening_energy", committed.hardening_energy);
        // D_p = W_p - (Psi^p - Psi^p_0) - (the part of Psi^p the crack
        // took): Psi^p_0 = 0 at the unloaded start.
        statistics.add("plastic_dissipation",
                       plastic_work - committed.hardening_energy -
                         plastic_energy_released);
        statistics.add("plastic_energy_released", plastic_energy_released);
        const double min_local = committed.min_plastic_dissipation;
        statistics.add("min_plastic_dissipation",
                       min_local < std::numeric_limits<double>::max()
                         ? min_local
                         : 0.);
        statistics.add("min_alpha",
                       committed.min_alpha < std::numeric_limits<double>::max()
                         ? committed.min_alpha
                         : 0.);
      }
    if (cracking)
      {
        statistics.add("fracture_energy", committed.fracture_energy);
        statistics.add("fracture_viscous_work", fracture_viscous_work);
        statistics.add("history_driving_work", history_driving_work);
      }
    if (dynamic)
      {
        statistics.add("kinetic_energy", committed.kinetic_energy);
        statistics.add("numerical_dissipation",
                       inertial_work -
                         (committed.kinetic_energy - initial_kinetic_energy));
        static const char *const names[] = {"momentum_x",
                                            "momentum_y",
                                            "momentum_z"};
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add(names[d], committed.momentum[d]);
      }
    statistics.add("energy_residual",
                   external_work - inertial_work - committed.stored_energy -
                     plastic_work + plastic_energy_released -
                     (committed.fracture_energy - initial_fracture_energy) -
                     fracture_viscous_work - contact_dissipation);
  }
} // namespace DuctileContact
