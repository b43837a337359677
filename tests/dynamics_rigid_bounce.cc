// An elastic bar bounces off a rigid foundation (doc/model.md section 6.5):
// the upper bar of prm/bar_impact.prm (1 m, 0.1 x 0.1 m, 10 Q2 cells of
// tests/meshes/two_bars.msh, rho = 1000 kg/m^3, sides on rollers, so that
// the P wave speed is c = 1000 m/s of 1-D theory) falls at v_0 = 2 m/s onto
// the lower bar's top face, clamped in x, y and z: a rigid, flat
// foundation 1 mm below it. Frictionless mortar contact, the trapezoidal
// rule, massless contact surfaces. 1-D theory: contact from t = 0.5 ms for
// 2L/c = 2 ms under the force rho c v_0 A = 20 kN, then the bar leaves at
// +v_0, with all its energy kinetic again.
// Checks, at dt = 20 and 10 us:
//  - the contact closes once and opens once, after 2L/c within 3 %, under a
//    force within 2 % of rho c v_0 A (its mean over the contact but 0.25 ms
//    at either end);
//  - the bar leaves at +v_0 within 2 % (the mean velocity of its free end
//    from the release to the end), with at least 98 % of K_0 as kinetic
//    energy;
//  - the foundation does not move: the lower bar's free end stays at 0 to
//    1e-12 m (nothing but the contact could move it);
//  - the energy error at the end, -(energy_residual) = K + Psi - K_0,
//    shrinks by more than 2.5 when dt halves (second order in dt).
// Then with the step control of Load stepping/Local error tolerance =
// 1e-3 from a nominal step of 40 us:
//  - every accepted step's estimate (statistics column local_error) is
//    within the tolerance;
//  - the smallest steps are taken where the accelerations jump: in each
//    millisecond the smallest step lies within 50 us of its event, the
//    impact (0.5 ms), the wave's reflection at the free end (1.5 ms: that
//    end's velocity turns from -v_0 to +v_0) and the release (2.5 ms), and
//    each is below a quarter of the largest step;
//  - the bar still leaves at +v_0 (2 %), and the energy error is below
//    that of the fixed 10 us steps (the step counts: stdout).
// One MPI rank (the contact terms on 1, 2 and 3 ranks: dynamics_bar_impact
// and checkpoint/dynamic_resume).
#include "contact_events.h"

using namespace dealii;

namespace
{
  constexpr double v0 = 2., force = 1000. * 1000. * v0 * 0.01, duration = 2e-3;

  std::string
  bounce_prm(const double dt, const double tolerance = 0.)
  {
    return Testing::shipped_scene("bar_impact.prm") + R"(
subsection Mesh
  subsection Gmsh
    set File name = )" SOURCE_DIR R"(/meshes/two_bars.msh
  end
end
subsection Boundary conditions
  set Boundary ids = 1, 2, 3, 5, 6
end
subsection Boundary 3
  # the foundation: the lower bar's top face, the master surface, clamped
  set Constrained components = x, y, z
end
subsection Load stepping
  set End time  = 3e-3
  set Time step = )" +
           std::to_string(dt) +
           "\n  set Local error tolerance = " + std::to_string(tolerance) + R"(
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

  double error[2] = {0., 0.};
  for (const unsigned int k : {0u, 1u})
    {
      const double dt = k == 0 ? 2e-5 : 1e-5;
      const auto   stats =
        Testing::run_scene(bounce_prm(dt), "bounce_" + std::to_string(k));
      const auto e          = Testing::contact_events(stats, 0.25e-3);
      double     foundation = 0.;
      for (const double u : stats.at("u1_z"))
        foundation = std::max(foundation, std::abs(u));
      const double velocity =
        Testing::mean_rate_after(stats, "u2_z", e.release);
      const double kinetic =
        stats.at("kinetic_energy").back() / stats.at("kinetic_energy")[0];
      error[k] = -stats.at("energy_residual").back();
      std::cout << "dt " << dt << ": contact from " << e.closed << " to "
                << e.opened << ", " << e.closings << " closing(s), "
                << e.openings << " opening(s), energy error " << error[k]
                << " of K_0 " << stats.at("kinetic_energy")[0]
                << ", foundation moved " << foundation << std::endl;
      out << "dt " << dt << ": contact duration / (2L/c) "
          << (e.opened - e.closed) / duration << ", mean force / (rho c v0 A) "
          << e.mean_force / force << ", velocity after / v_0 " << velocity / v0
          << ", K at the end / K_0 " << kinetic << std::endl;
      out << "  closes once, opens once, after 2L/c within 3 %, force within "
             "2 %, leaves at +v_0 (2 %), K >= 0.98 K_0, foundation at rest: "
          << Testing::yes_no(e.closings == 1 && e.openings == 1 &&
                             std::abs((e.opened - e.closed) / duration - 1.) <
                               0.03 &&
                             std::abs(e.mean_force / force - 1.) < 0.02 &&
                             std::abs(velocity - v0) < 0.02 * v0 &&
                             kinetic >= 0.98 && foundation < 1e-12)
          << std::endl;
    }
  out << "energy error ratio " << error[0] / error[1]
      << ", above 2.5 (second order): "
      << Testing::yes_no(error[0] > 0. && error[0] / error[1] > 2.5)
      << std::endl;

  // The same bounce with the local error control.
  constexpr double tolerance = 1e-3;
  const auto       stats =
    Testing::run_scene(bounce_prm(4e-5, tolerance), "adaptive");
  const auto       &t = stats.at("time"), &dt = stats.at("dt");
  const std::size_t last          = t.size() - 1;
  double            largest_error = 0., largest_dt = 0.;
  // The smallest step of each millisecond: impact, reflection, release.
  std::size_t smallest[3] = {0, 0, 0};
  for (std::size_t s = 1; s <= last; ++s)
    {
      largest_error = std::max(largest_error, stats.at("local_error")[s]);
      // The last step may be shortened to reach the end time.
      if (s == last)
        continue;
      largest_dt        = std::max(largest_dt, dt[s]);
      const unsigned ms = std::min(2u, static_cast<unsigned>(t[s] / 1e-3));
      if (smallest[ms] == 0 || dt[s] < dt[smallest[ms]])
        smallest[ms] = s;
    }
  bool at_events = true;
  for (unsigned int ms = 0; ms < 3; ++ms)
    at_events = at_events && smallest[ms] > 0 &&
                std::abs(t[smallest[ms]] - (ms + 0.5) * 1e-3) < 5e-5 &&
                dt[smallest[ms]] < 0.25 * largest_dt;
  const double velocity =
    Testing::mean_rate_after(stats,
                             "u2_z",
                             Testing::contact_events(stats, 0.25e-3).release);
  const double adaptive_error = -stats.at("energy_residual")[last];
  double       cutbacks       = 0.;
  for (const double c : stats.at("cutbacks"))
    cutbacks += c;
  std::cout << "adaptive: " << last << " steps, " << cutbacks
            << " cut-backs; largest estimate " << largest_error
            << "; smallest steps";
  for (const std::size_t s : smallest)
    std::cout << " " << dt[s] << " at " << t[s];
  std::cout << ", largest " << largest_dt << "; velocity after / v_0 "
            << velocity / v0 << "; energy error " << adaptive_error
            << std::endl;
  out << "adaptive (tolerance 1e-3): estimates within the tolerance, the "
         "smallest steps at the impact, the reflection and the release "
         "(below a quarter of the largest), leaves at +v_0 (2 %), energy "
         "error below that of dt = 10 us: "
      << Testing::yes_no(largest_error <= tolerance && at_events &&
                         std::abs(velocity - v0) < 0.02 * v0 &&
                         std::abs(adaptive_error) < std::abs(error[1]))
      << std::endl;
}
