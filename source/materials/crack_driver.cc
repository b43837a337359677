#include <ductile_contact/materials/crack_driver.h>

#include <cmath>

namespace DuctileContact
{
  DrivingEnergy
  crack_driving_energy(const MaterialResponse     &m,
                       const double                alpha,
                       const CrackDriverType       driver,
                       const PlasticWorkDriver    &work_driver,
                       const PlasticityParameters &plastic)
  {
    DrivingEnergy d;
    if (driver == CrackDriverType::elastic)
      {
        d.value       = m.psi_plus;
        d.variational = m.psi_plus;
        d.d_dF        = m.dpsi_plus_dF;
        d.d_dalpha    = m.dpsi_plus_dalpha;
        d.d_ds        = m.dpsi_plus_ds;
        return d;
      }
    if (driver == CrackDriverType::elastic_plastic_energy)
      {
        // -dPsi/ds / (-g_k'(s)) of Psi^e + Psi^p_loc
        // (plastic_energy_density()).
        const auto [phi, slope] =
          degradable_plastic_energy(plastic_work_density(alpha, plastic),
                                    plastic);
        d.value       = m.psi_plus + phi;
        d.variational = d.value;
        d.d_dF        = m.dpsi_plus_dF;
        d.d_dalpha =
          m.dpsi_plus_dalpha + slope * hardening_stress(alpha, plastic);
        d.d_ds = m.dpsi_plus_ds;
        return d;
      }
    d.variational      = m.psi_plus;
    const double above = m.psi_plus + plastic_work_density(alpha, plastic) -
                         work_driver.critical_work_density;
    if (above <= 0.)
      return d;
    const double zeta = work_driver.factor;
    d.value           = zeta * above;
    d.d_dF            = zeta * m.dpsi_plus_dF;
    d.d_dalpha = zeta * (m.dpsi_plus_dalpha + hardening_stress(alpha, plastic));
    d.d_ds     = zeta * m.dpsi_plus_ds;
    return d;
  }
} // namespace DuctileContact
