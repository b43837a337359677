// pfm-cracks' notched shear with its model in plane strain: the shipped
// scene prm/sent_shear_pfm_2d.prm (small-strain linear elasticity with the
// spectral split, the second-order phase field with l_f = 0.0441942 mm, Q1,
// its level-4 mesh) through the peak to u = 0.012 mm:
//  - the peak reaction and where it is, the stored and crack energies at
//    u = 0.01 mm and the reaction at u = 0.011 mm, at 5 significant digits;
//  - the crack runs down from the notch tip towards the bottom right
//    (the spectral split's path; with the whole energy degraded it would
//    branch up as well): at the end the cracked zone (s >= 0.95) lies below
//    the slit (y < 0.5 mm), reaches below y = 0.42 mm and right of
//    x = 0.52 mm (0.35 and 0.587 here: margins of about two cells);
//  - the energy balance closes at every step to 1e-3 of W_ext;
//  - s never decreases at any DoF (Irreversibility = bound; to the Newton
//    tolerance 1e-8, as in two_d/sent_pfm).
// Run on 1 MPI rank.
#include "../tests.h"

#include <algorithm>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(5);

  const std::string prm =
    Testing::shipped_scene("sent_shear_pfm_2d.prm") +
    "subsection Mesh\n  subsection Gmsh\n    set File name = " SOURCE_DIR
    "/../prm/meshes/sent_shear_uniform_h0.03125_2d.msh\n  end\nend\n"
    "subsection Load stepping\n  set End time = 120\nend\n";
  const Testing::Table t = Testing::run_scene(prm, "sent_shear_pfm_run");

  // Plane strain: per unit thickness, N/m and J/m -> N/mm and N.
  const auto       &F    = t.at("F2_x");
  const std::size_t k    = std::max_element(F.begin(), F.end()) - F.begin();
  const double      peak = F[k] * 1e-3, u_peak = t.at("u2_x")[k] * 1e3;
  std::size_t       n100 = 0, n110 = 0;
  double            worst = 0, min_s_change = 0;
  for (std::size_t n = 1; n < F.size(); ++n)
    {
      if (std::abs(t.at("time")[n] - 100.) < 1e-9)
        n100 = n;
      if (std::abs(t.at("time")[n] - 110.) < 1e-9)
        n110 = n;
      worst        = std::max(worst,
                       std::abs(t.at("energy_residual")[n]) /
                         t.at("external_work")[n]);
      min_s_change = std::min(min_s_change, t.at("min_s_change")[n]);
    }
  const std::size_t last  = F.size() - 1;
  const double      y_min = t.at("cracked_min_y")[last] * 1e3,
               y_max      = t.at("cracked_max_y")[last] * 1e3,
               x_max      = t.at("cracked_max_x")[last] * 1e3;
  const bool down         = y_max < 0.5 && y_min < 0.42 && x_max > 0.52;

  out << "peak reaction " << peak << " N/mm at u = " << u_peak << " mm"
      << std::endl
      << "at u = 0.01 mm: stored energy " << t.at("stored_energy")[n100]
      << " N, crack energy " << t.at("fracture_energy")[n100] << " N"
      << std::endl
      << "reaction at u = 0.011 mm " << F[n110] * 1e-3 << " N/mm" << std::endl
      << "at u = " << t.at("u2_x")[last] * 1e3
      << " mm the crack runs down and to the right: " << Testing::yes_no(down)
      << std::endl
      << "energy balance to 1e-3 of W_ext at every step: "
      << Testing::yes_no(worst < 1e-3) << std::endl
      << "s never decreases (1e-8): " << Testing::yes_no(min_s_change > -1e-8)
      << std::endl;
  std::cout << "worst balance " << worst << ", smallest s change "
            << min_s_change << "; cracked zone y " << y_min << " ... " << y_max
            << ", x up to " << x_max << " mm" << std::endl;
}
