// Issue #4, the ductile notched specimen (coarse): the scene
// prm/ductile_notch.prm (steel with gradient plasticity and a crack phase
// field, a plate 1 x 2 mm slit to its centre, pulled) with the overrides of
// tests/ductile_notch_coarse.prm, on the coarse mesh
// tests/meshes/ductile_notch_coarse.msh (`prm/meshes/make_sent.py 0.1 0.2
// ductile_notch_coarse.msh 1.0 2`: h = 0.1 mm, 162 Q2 cells) with the
// lengths of the scene doubled to fit it (l_f = h = 0.1 mm, l_p = 0.2 mm,
// g_c doubled so that g_c/l_f stays), pulled 20.4 um in steps of at most
// 1.2 um; a step that fails (15 Newton iterations, 4 halvings of the line
// search) is cut back early.
// Checks:
//  - it yields before it cracks: at the force peak the largest alpha is
//    above 1 % and the plastic work W_p is above a third of the external
//    work (elastic-brittle fracture would have W_p = 0);
//  - the force has an interior maximum and softens to below 20 % of it by
//    the end: the crack has crossed the ligament;
//  - then the crack energy g_c int gamma is 0.8-1.6 x g_c x ligament x
//    thickness (a crack along the ligament; on this mesh, with h = l_f,
//    the broken band is a few cells tall and its energy above the sharp
//    value: 1.2 on this mesh with dt/4, 1.41 in the scene, h = l_f = 0.05
//    mm);
//  - the energy balance W_ext - Psi^e - W_p - crack energy - viscous
//    dissipation of s (statistics energy_residual, model.md section 6)
//    closes to 5 % of W_ext at every step (at the end W_p is 62 % of W_ext,
//    the crack energy 32 %, the viscous dissipation of s 4 %);
//  - s never decreases at any DoF (Coupling/Irreversibility = history and
//    bound, the default; before g was continued by 0 beyond s = 1, the
//    history field alone let the broken band relax by 1.7e-4 here);
//  - Newton converges quadratically: the observed order has a median above
//    1.7 over the steps where it is defined, also over the steps of the
//    crack's run (four or more iterations).
// One MPI rank only (~2 min; MUMPS is slower on 2 ranks for this size).
// The terms of the coupling are local to quadrature points; that the
// plastic and the fracture assembly (ghosted alpha and s, C0IP faces,
// quadrature-point history) give identical results on 1 and 2 ranks is
// shown by plastic_box, necking_bar, fracture_bar and sent_notch.
// Converged results and run time: benchmarks/plasticity/ductile_notch.
#include "tests.h"

#include <algorithm>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  std::stringstream prm;
  prm << Testing::shipped_scene("ductile_notch.prm");
  prm << Testing::file_text(SOURCE_DIR "/ductile_notch_coarse.prm");
  prm << R"(
subsection Mesh
  subsection Gmsh
    set File name = )" SOURCE_DIR R"(/meshes/ductile_notch_coarse.msh
  end
end
subsection Load stepping
  set End time = 0.68
end
)";
  const Testing::Table t = Testing::run_scene(prm.str(), "ductile_notch_run");

  const double        thickness = 1e-4, ligament = 5e-4, g_c = 2800;
  const auto         &F     = t.at("F2_y");
  const std::size_t   n     = F.size();
  const std::size_t   k_max = std::max_element(F.begin(), F.end()) - F.begin();
  const double        peak  = F[k_max];
  const double        W_ext = t.at("external_work")[n - 1];
  double              worst_balance = 0, min_s_change = 0;
  std::vector<double> rates, crack_rates;
  for (std::size_t k = 1; k < n; ++k)
    {
      worst_balance     = std::max(worst_balance,
                               std::abs(t.at("energy_residual")[k]) /
                                 std::max(t.at("external_work")[k], 1e-300));
      min_s_change      = std::min(min_s_change, t.at("min_s_change")[k]);
      const double rate = t.at("newton_rate")[k];
      if (rate > 0.)
        {
          rates.push_back(rate);
          if (t.at("newton_iterations")[k] >= 4)
            crack_rates.push_back(rate);
        }
    }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0. : v[v.size() / 2];
  };
  const double crack_ratio =
    t.at("fracture_energy")[n - 1] / (g_c * ligament * thickness);
  const double plastic_share =
    t.at("plastic_work")[k_max] / t.at("external_work")[k_max];

  out << "end reached (20.4 um): "
      << Testing::yes_no(std::abs(t.at("time")[n - 1] - 0.68) < 1e-12) << "\n"
      << "yields before it cracks (at the peak alpha > 1 %, W_p > W_ext/3): "
      << Testing::yes_no(t.at("max_alpha")[k_max] > 0.01 &&
                         plastic_share > 1. / 3.)
      << "\n"
      << "interior force maximum, force at the end below 20 % of it: "
      << Testing::yes_no(k_max > 0 && k_max + 1 < n && F[n - 1] < 0.2 * peak)
      << "\n"
      << "crack energy 0.8-1.6 x g_c x ligament x thickness: "
      << Testing::yes_no(crack_ratio > 0.8 && crack_ratio < 1.6) << "\n"
      << "energy balance closes to 5 % of W_ext at every step: "
      << Testing::yes_no(worst_balance < 0.05) << "\n"
      << "s never decreases at any DoF (to the Newton tolerance 1e-8): "
      << Testing::yes_no(min_s_change > -1e-8) << "\n"
      << "Newton rate defined in most steps, median > 1.7: "
      << Testing::yes_no(rates.size() > n / 2 && median(rates) > 1.7) << "\n"
      << "and over the crack's steps (>= 4 iterations), median > 1.7: "
      << Testing::yes_no(crack_rates.size() >= 3 && median(crack_rates) > 1.7)
      << "\n";
  std::cout << "peak " << peak / thickness * 1e-6
            << " kN/mm at u = " << t.at("u2_y")[k_max] * 1e6 << " um, alpha "
            << t.at("max_alpha")[k_max] << ", W_p/W_ext " << plastic_share
            << "; end force / peak " << F[n - 1] / peak << ", crack energy "
            << crack_ratio << " g_c A, worst balance " << worst_balance
            << " W_ext (W_ext " << W_ext << " J), min s change " << min_s_change
            << ", median rate " << median(rates) << " of " << rates.size()
            << ", in the crack's steps " << median(crack_rates) << " of "
            << crack_rates.size() << std::endl;
}
