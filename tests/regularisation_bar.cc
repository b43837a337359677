// Fracture/Regularisation = second order (AT2) on the homogeneous bar of
// fracture_bar (unit cube, 2 x 2 x 2 Q2 cells, symmetry planes, pulled on
// x = 1, quadratic degradation, no plasticity, eta_f = 0), against the
// fourth-order model on the same bar:
//  - a homogeneous state has no gradients, so the two functionals differ
//    only in the local term: s^2/(2 l_f) for AT2 against s^2/(4 l_f). The
//    1-D closed form of AT2 peaks at sigma_c = (9/16) sqrt(E g_c / (3 l_f))
//    at s = 1/4 (doc/model.md section 4), sqrt(2) above the fourth-order
//    sigma_c at the same g_c and l_f: the AT2 peak is its sigma_c to 0.2 %
//    and s there 1/4 to 0.02, and the AT2 peak over the fourth-order peak
//    is sqrt(2) to 0.2 % (the same small finite-strain shift in both);
//  - the crack energy at the end is g_c int gamma of each functional for
//    the homogeneous s it reaches: g_c s^2/(2 l_f) and g_c s^2/(4 l_f)
//    (unit volume), to 1e-6 of it.
// The compared output holds the peaks at 5 significant digits. One rank.
#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

namespace
{
  const double mu = 1., kappa = 2.5;
  const double E = 9. * kappa * mu / (3. * kappa + mu);
  const double l = 1.;
  // g_c such that the AT2 peak strain is 1e-3: eps_c^2 = g_c / (3 l E).
  const double g_c = 3. * l * E * 1e-6;

  std::string
  bar_prm(const std::string &regularisation)
  {
    return Testing::unit_cube_prm(R"(  set Fracture      = true
  subsection Fracture
    set Critical energy release rate = )" +
                                  Utilities::to_string(g_c, 16) + R"(
    set Length scale                 = 1
    set Regularisation               = )" +
                                  regularisation + R"(
  end
)") + Testing::uniaxial_pull_prm("0.0025*t") +
           R"(
subsection Load stepping
  set End time  = 1
  set Time step = 0.0125
end
subsection Newton
  set Relative tolerance = 1e-10
end
subsection Output
  set Interval = 0
end
)";
  }

  /// |crack energy / (g_c s^2 m) - 1| at the last step, s the largest
  /// phase field and m the functional's mass coefficient (per g_c).
  double
  energy_error(const Testing::Table &t, const double m)
  {
    const double s = t.at("max_s").back();
    return std::abs(t.at("fracture_energy").back() / (g_c * s * s * m) - 1.);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(5);
  const double sigma_c = 9. / 16. * std::sqrt(E * g_c / (3. * l));

  const auto second = Testing::run_scene(bar_prm("second order"), "bar_at2");
  const auto fourth = Testing::run_scene(bar_prm("fourth order"), "bar_at4");
  const auto [peak_2, s_2] = Testing::peak(second, "F1_x", "max_s");
  const double peak_4      = Testing::peak(fourth, "F1_x", "max_s").first;
  out << "second order: peak " << peak_2 << " = sigma_c " << sigma_c
      << " (0.2 %), s there " << s_2 << " = 1/4 (0.02): "
      << Testing::yes_no(std::abs(peak_2 / sigma_c - 1.) < 2e-3 &&
                         std::abs(s_2 - 0.25) < 0.02)
      << std::endl
      << "fourth order: peak " << peak_4 << ", the second order's over it "
      << peak_2 / peak_4 << " = sqrt(2) (0.2 %): "
      << Testing::yes_no(std::abs(peak_2 / peak_4 / std::sqrt(2.) - 1.) < 2e-3)
      << std::endl
      << "crack energy = g_c s^2/(2 l_f) and g_c s^2/(4 l_f) (1e-6): "
      << Testing::yes_no(energy_error(second, 0.5 / l) < 1e-6 &&
                         energy_error(fourth, 0.25 / l) < 1e-6)
      << std::endl;
  std::cout << "energy errors " << energy_error(second, 0.5 / l) << ", "
            << energy_error(fourth, 0.25 / l) << std::endl;
}
