// A free elastic body that flies and spins (doc/model.md section 6.5): the
// unit cube of 2 x 2 x 2 Q2 cells, mu = 1, kappa = 2.5, rho = 1, no
// boundary conditions, with the initial velocity v = (0.1, 0, 0) + omega x
// (X - X_c), omega = 0.8 about z: the rotation stretches the cube (about 15 %
// at its corners) and it vibrates while it spins, up to t = 2 (half a
// turn).
//  - momentum: no force acts, so P = rho V (0.1, 0, 0) at every step to
//    1e-9 (Newton's tolerance, not the step, decides it);
//  - the trapezoidal rule (rho_inf = 1) keeps W_ext = 0 and D_num = 0 (to
//    round-off), and its energy error K + Psi - K_0 (the residual; its
//    largest magnitude over the steps) is of second order in dt: halving
//    dt from 0.05 to 0.025 divides it by 4 +- 0.6;
//  - rho_inf = 0.8 dissipates: D_num > 0, and K + Psi + D_num = K_0 to the
//    same error;
//  - the quantities of interest at 5 significant digits.
#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

namespace
{
  std::string
  spinning_cube_prm(const double dt, const double spectral_radius)
  {
    return Testing::unit_cube_prm(R"(  set Density = 1
  set Initial velocity = 0.1 - 0.8*(y - 0.5); 0.8*(x - 0.5); 0
)") + R"(
subsection Load stepping
  set End time  = 2
  set Time step = )" +
           std::to_string(dt) + R"(
  set Time integration = Bossak
  set High-frequency spectral radius = )" +
           std::to_string(spectral_radius) + R"(
end
subsection Newton
  set Relative tolerance = 1e-12
end
subsection Output
  set Interval = 0
end
)";
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(5);

  double error[3] = {0., 0., 0.};
  for (const unsigned int k : {0u, 1u, 2u})
    {
      const double      dt       = 0.1 / (1u << k);
      const auto        stats    = Testing::run_scene(spinning_cube_prm(dt, 1.),
                                            "free_body_" + std::to_string(k));
      const std::size_t last     = stats.at("time").size() - 1;
      double            drift_px = 0., other_p = 0.;
      for (std::size_t n = 0; n <= last; ++n)
        {
          error[k] =
            std::max(error[k], std::abs(stats.at("energy_residual")[n]));
          drift_px =
            std::max(drift_px, std::abs(stats.at("momentum_x")[n] - 0.1));
          other_p = std::max({other_p,
                              std::abs(stats.at("momentum_y")[n]),
                              std::abs(stats.at("momentum_z")[n])});
        }
      std::cout << "dt " << dt << ": energy error " << error[k]
                << ", momentum drift " << drift_px << ", " << other_p
                << ", numerical dissipation "
                << stats.at("numerical_dissipation")[last] << std::endl;
      if (k == 2)
        out << "K_0 " << stats.at("kinetic_energy")[0] << ", at t = 2: K "
            << stats.at("kinetic_energy")[last] << ", Psi "
            << stats.at("stored_energy")[last] << std::endl;
      out << "dt " << dt << ": momentum (0.1, 0, 0) to 1e-9 at every step, "
          << "W_ext = 0, D_num below 1e-12: "
          << Testing::yes_no(
               drift_px < 1e-9 && other_p < 1e-9 &&
               std::abs(stats.at("external_work")[last]) < 1e-12 &&
               std::abs(stats.at("numerical_dissipation")[last]) < 1e-12)
          << std::endl;
    }
  std::cout << "energy error ratios " << error[0] / error[1] << ", "
            << error[1] / error[2] << std::endl;
  const double ratio = error[1] / error[2];
  out << "energy error ratio " << ratio << ": second order (4 +- 0.6): "
      << Testing::yes_no(std::abs(ratio - 4.) < 0.6) << std::endl;

  const auto damped =
    Testing::run_scene(spinning_cube_prm(0.025, 0.8), "free_body_damped");
  const std::size_t last    = damped.at("time").size() - 1;
  const double      d       = damped.at("numerical_dissipation")[last];
  const double      balance = damped.at("kinetic_energy")[last] +
                         damped.at("stored_energy")[last] + d -
                         damped.at("kinetic_energy")[0];
  std::cout << "rho_inf = 0.8: D_num " << d << ", K + Psi + D_num - K_0 "
            << balance << std::endl;
  out << "rho_inf = 0.8: D_num / K_0 " << d / damped.at("kinetic_energy")[0]
      << std::endl;
  out << "rho_inf = 0.8: D_num > 0 and K + Psi + D_num - K_0 within twice "
         "the trapezoidal error: "
      << Testing::yes_no(d > 0. && std::abs(balance) < 2. * error[2])
      << std::endl;
}
