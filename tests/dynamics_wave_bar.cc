// A longitudinal wave in a bar (doc/model.md section 6.5): a neo-Hooke bar
// of length L = 1 m, 40 x 1 x 1 Q2 cells, rho = 1000 kg/m^3, its sides on
// rollers (uniaxial strain, so the wave speed is that of a P wave, c =
// sqrt((kappa + 4 mu/3)/rho) = 1000 m/s), fixed at x = L and driven at x = 0
// with the velocity v_0 = 1 m/s, reached over a quadratic ramp of tau =
// 50 us. Linear theory: the end x = 0 carries rho c v_0 A behind the front
// and the wave reaches x = L at L/c + tau/2, where the fixed end doubles the
// stress, 2 rho c v_0 A (strain v_0/c = 1e-3, so neo-Hooke is linear to
// about 1e-3).
//  - rho_inf = 1 (the trapezoidal rule), dt = 10 us:
//    - the arrival time (where the far reaction first reaches rho c v_0 A)
//      against L/c + tau/2, the reflected force against 2 rho c v_0 A and
//      the driven end's mean force against rho c v_0 A, within 2 %;
//    - the energy account closes: numerical dissipation 0 to round-off,
//      residual below 1e-5 of W_ext at every step;
//    - momentum: P_x(T) equals the impulse of the two reactions by the
//      trapezoidal rule, to 1e-8 relative;
//  - rho_inf = 0.5: the numerical dissipation is positive and below 1 % of
//    W_ext, and it damps the step-to-step oscillation of the driven end's
//    reaction (the trapezoidal rule keeps the one the ramp's kink starts);
//  - the quantities of interest at 5 significant digits.
// Run on 2 MPI ranks (1 rank gives the same output; the suite runs only
// the 2-rank case, the costlier check).
#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

namespace
{
  constexpr double rho = 1000., c = 1000., v0 = 1., area = 0.05 * 0.05,
                   tau = 5e-5, length = 1.;

  std::string
  bar_prm(const double spectral_radius)
  {
    std::string prm = R"(
subsection Mesh
  set Scene = box
  subsection Box
    set Upper corner = 1, 0.05, 0.05
    set Subdivisions = 40, 1, 1
  end
end
subsection Body 0
  set Shear modulus = 0.3e9
  set Bulk modulus  = 0.6e9
  set Density       = 1000
end
subsection Boundary conditions
  set Boundary ids = 0, 1, 2, 3, 4, 5
end
subsection Boundary 0
  set Constrained components = x
  set Displacement = if(t < 5e-5, t^2/(2*5e-5), t - 2.5e-5); 0; 0
end
subsection Boundary 1
  set Constrained components = x
end
)";
    for (const char *b : {"2", "3"})
      prm += "subsection Boundary " + std::string(b) +
             "\n  set Constrained components = y\nend\n";
    for (const char *b : {"4", "5"})
      prm += "subsection Boundary " + std::string(b) +
             "\n  set Constrained components = z\nend\n";
    return prm + R"(
subsection Load stepping
  set End time  = 1.5e-3
  set Time step = 1e-5
  set Minimum time step = 1e-9
  set Time integration = Bossak
  set High-frequency spectral radius = )" +
           std::to_string(spectral_radius) + R"(
end
subsection Newton
  set Relative tolerance = 1e-10
end
subsection Output
  set Interval = 0
end
)";
  }

  /// Mean of |F_n - F_n-1| over the steps with t in [t0, t1].
  double
  oscillation(const Testing::Table &stats,
              const std::string    &column,
              const double          t0,
              const double          t1)
  {
    double       sum = 0.;
    unsigned int n   = 0;
    for (std::size_t k = 1; k < stats.at("time").size(); ++k)
      if (stats.at("time")[k] >= t0 && stats.at("time")[k] <= t1)
        {
          sum += std::abs(stats.at(column)[k] - stats.at(column)[k - 1]);
          ++n;
        }
    return sum / n;
  }

  /// Mean of the column over the steps with t in [t0, t1].
  double
  mean(const Testing::Table &stats,
       const std::string    &column,
       const double          t0,
       const double          t1)
  {
    double       sum = 0.;
    unsigned int n   = 0;
    for (std::size_t k = 0; k < stats.at("time").size(); ++k)
      if (stats.at("time")[k] >= t0 && stats.at("time")[k] <= t1)
        {
          sum += stats.at(column)[k];
          ++n;
        }
    return sum / n;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(5);

  const double force = rho * c * v0 * area;
  const auto   stats = Testing::run_scene(bar_prm(1.), "wave_bar_trapezoidal");
  const auto  &t     = stats.at("time");
  const auto  &far   = stats.at("F1_x");
  const auto  &near  = stats.at("F0_x");
  const std::size_t last = t.size() - 1;

  // The far end's reaction is negative (it holds the bar back).
  double arrival = 0.;
  for (std::size_t k = 1; k <= last && arrival == 0.; ++k)
    if (-far[k] >= force)
      arrival = t[k - 1] + (t[k] - t[k - 1]) * (force + far[k - 1]) /
                             (far[k - 1] - far[k]);
  const double expected_arrival = length / c + 0.5 * tau;
  const double reflected        = -mean(stats, "F1_x", 1.2e-3, 1.5e-3);
  const double driven           = mean(stats, "F0_x", 2e-4, 8e-4);
  out << "arrival time / (L/c + tau/2) " << arrival / expected_arrival
      << std::endl
      << "reflected force / (2 rho c v0 A) " << reflected / (2. * force)
      << std::endl
      << "driven end force / (rho c v0 A) " << driven / force << std::endl;
  out << "all three within 2 %: "
      << Testing::yes_no(std::abs(arrival / expected_arrival - 1.) < 0.02 &&
                         std::abs(reflected / (2. * force) - 1.) < 0.02 &&
                         std::abs(driven / force - 1.) < 0.02)
      << std::endl;

  double worst = 0., impulse = 0.;
  for (std::size_t k = 1; k <= last; ++k)
    {
      worst = std::max(worst,
                       std::abs(stats.at("energy_residual")[k]) /
                         stats.at("external_work")[k]);
      impulse +=
        0.5 * (t[k] - t[k - 1]) * (near[k] + far[k] + near[k - 1] + far[k - 1]);
    }
  const double w_ext = stats.at("external_work")[last];
  out << "W_ext " << w_ext << ", kinetic energy "
      << stats.at("kinetic_energy")[last] << ", stored energy "
      << stats.at("stored_energy")[last] << ", momentum "
      << stats.at("momentum_x")[last] << std::endl;
  std::cout << "trapezoidal: worst residual " << worst
            << " of W_ext, numerical dissipation "
            << stats.at("numerical_dissipation")[last] << ", impulse "
            << impulse << std::endl;
  out << "numerical dissipation 0 (below 1e-12 W_ext) and residual below "
         "1e-5 W_ext at every step: "
      << Testing::yes_no(std::abs(stats.at("numerical_dissipation")[last]) <
                           1e-12 * w_ext &&
                         worst < 1e-5)
      << std::endl;
  out << "momentum equals the reactions' impulse to 1e-8: "
      << Testing::yes_no(std::abs(stats.at("momentum_x")[last] - impulse) <
                         1e-8 * std::abs(impulse))
      << std::endl;

  const auto   damped     = Testing::run_scene(bar_prm(0.5), "wave_bar_damped");
  const double dissipated = damped.at("numerical_dissipation")[last];
  const double damped_w   = damped.at("external_work")[last];
  const double jitter     = oscillation(stats, "F0_x", 5e-4, 8e-4);
  const double damped_jitter = oscillation(damped, "F0_x", 5e-4, 8e-4);
  std::cout << "rho_inf = 0.5: numerical dissipation " << dissipated
            << ", driven end's step-to-step change " << damped_jitter
            << " N against " << jitter << " N" << std::endl;
  out << "rho_inf = 0.5: numerical dissipation / W_ext "
      << dissipated / damped_w << ", arrival force "
      << -mean(damped, "F1_x", 1.2e-3, 1.5e-3) / (2. * force) << std::endl;
  out << "rho_inf = 0.5 dissipates (0 < D_num < 1 % W_ext) and damps the "
         "driven end's oscillation 10-fold: "
      << Testing::yes_no(dissipated > 0. && dissipated < 0.01 * damped_w &&
                         damped_jitter < 0.1 * jitter)
      << std::endl;
}
