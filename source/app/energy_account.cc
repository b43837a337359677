#include <ductile_contact/app/energy_account.h>

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
  }



  void
  EnergyAccount::add_columns(Statistics         &statistics,
                             const AssemblyInfo &committed,
                             const bool          plastic,
                             const bool          cracking,
                             const double        contact_dissipation) const
  {
    statistics.add("stored_energy", committed.stored_energy);
    statistics.add("external_work", external_work);
    if (plastic)
      {
        statistics.add("plastic_work", plastic_work);
        statistics.add("hardening_energy", committed.hardening_energy);
      }
    if (cracking)
      {
        statistics.add("fracture_energy", committed.fracture_energy);
        statistics.add("fracture_viscous_work", fracture_viscous_work);
        statistics.add("history_driving_work", history_driving_work);
      }
    statistics.add("energy_residual",
                   external_work - committed.stored_energy - plastic_work -
                     committed.fracture_energy - fracture_viscous_work -
                     contact_dissipation);
  }
} // namespace DuctileContact
