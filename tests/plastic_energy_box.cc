// Homogeneous box (2x2x2 Q2 cells, unit cube) in uniaxial tension with
// visco-plastic J2, the phase field and the variational crack driver
// 'elastic and plastic energy' (doc/model.md section 4.3): the plastic
// energy above w_c is degraded, the flow resistance falls with s, and the
// box softens and breaks (s -> 0.7) at 10 % strain. Irreversibility by the
// bound alone, so that the driver is -dPsi/ds.
//  - the energy account closes with the model's own terms,
//      W_ext = Psi^e + Psi^p + D_p + g_c int gamma + D_f,
//    within 1 % of W_ext at every step at dt = 0.005, and the residual
//    falls at first order when dt is halved from 0.01 (ratio > 1.7); no
//    history driving work;
//  - the plastic dissipation D_p = W_p - Psi^p - R_p is a time
//    discretisation error here (eta_p is tiny): the backward Euler step
//    takes the flow resistance at the step's end, which falls with alpha
//    in the rounded bracket, so the work falls short of the stored energy
//    by O(dalpha^2) per step: D_p halves with dt (ratio 2 +- 0.2) and
//    stays within 0.1 % of W_p;
//  - the crack is paid by plastic energy: plastic_energy_released > 0 and
//    the largest part of the crack energy;
//  - the quantities of interest at dt = 0.025 (peak and end force, W_ext,
//    W_p, Psi^p, R_p, D_p, crack energy, max s), 5 significant digits.
// Run on 2 MPI ranks (1 rank gives the same output; the suite runs only
// the 2-rank case, the costlier check).
#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

namespace
{
  std::string
  box_prm(const double dt)
  {
    return Testing::unit_cube_prm(R"(  set Plasticity    = true
  subsection Plasticity
    set Initial yield stress    = 0.005
    set Saturation yield stress = 0.006
    set Saturation exponent     = 25
    set Viscosity               = 1e-6
  end
  set Fracture = true
  subsection Fracture
    set Critical energy release rate = 4e-4
    set Length scale                 = 0.5
    set Viscosity                    = 1e-6
    set Volumetric switch width      = 1e-3
    set Crack driver                 = elastic and plastic energy
    set Critical work density        = 5e-5
  end
)") + Testing::uniaxial_pull_prm("0.1*t") +
           R"(
subsection Coupling
  set Irreversibility = bound
end
subsection Load stepping
  set End time  = 1
  set Time step = )" +
           std::to_string(dt) + R"(
end
subsection Newton
  set Relative tolerance = 1e-11
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

  double residual[2] = {0., 0.}, dissipation[2] = {0., 0.}, work = 0.;
  for (const unsigned int k : {0u, 1u})
    {
      const double dt = (k == 0) ? 0.01 : 0.005;
      const auto   stats =
        Testing::run_scene(box_prm(dt),
                           "plastic_energy_box_" + std::to_string(k));
      const std::size_t last = stats.at("time").size() - 1;
      const auto at  = [&](const std::string &c) { return stats.at(c)[last]; };
      residual[k]    = at("energy_residual");
      dissipation[k] = at("plastic_dissipation");
      work           = at("plastic_work");
      double peak = 0., min_local = 0., worst_residual = 0.;
      for (std::size_t n = 1; n <= last; ++n)
        {
          peak = std::max(peak, stats.at("F1_x")[n]);
          min_local =
            std::min(min_local, stats.at("min_plastic_dissipation")[n]);
          worst_residual = std::max(worst_residual,
                                    std::abs(stats.at("energy_residual")[n]) /
                                      stats.at("external_work")[n]);
        }
      std::cout << "dt " << dt << ": residual " << residual[k] << " of W_ext "
                << at("external_work") << " (worst step " << worst_residual
                << "), history work " << at("history_driving_work")
                << ", smallest local D_p " << min_local << std::endl;
      if (k == 1)
        {
          out << "peak force " << peak << ", end force " << at("F1_x")
              << std::endl
              << "W_ext " << at("external_work") << ", W_p "
              << at("plastic_work") << ", Psi^p " << at("hardening_energy")
              << ", R_p " << at("plastic_energy_released") << ", D_p "
              << at("plastic_dissipation") << std::endl
              << "crack energy " << at("fracture_energy") << ", max s "
              << at("max_s") << std::endl;
          out << "the crack is paid mostly by plastic energy (R_p > crack "
                 "energy / 2): "
              << Testing::yes_no(at("plastic_energy_released") >
                                 0.5 * at("fracture_energy"))
              << std::endl;
          out << "no history driving work: "
              << Testing::yes_no(at("history_driving_work") == 0.) << std::endl;
          out << "residual below 1 % of W_ext at every step: "
              << Testing::yes_no(worst_residual < 0.01) << std::endl;
        }
    }
  const double ratio = residual[0] / residual[1];
  std::cout << "energy residual ratio " << ratio << std::endl;
  out << "halving dt shrinks the residual at first order (ratio > 1.7): "
      << Testing::yes_no(ratio > 1.7) << std::endl;
  const double d_ratio = dissipation[0] / dissipation[1];
  std::cout << "plastic dissipation " << dissipation[0] << ", "
            << dissipation[1] << ", ratio " << d_ratio << std::endl;
  out << "D_p halves with dt (ratio 2 +- 0.2), within 0.1 % of W_p: "
      << Testing::yes_no(std::abs(d_ratio - 2.) < 0.2 &&
                         std::abs(dissipation[1]) < 1e-3 * work)
      << std::endl;
}
