// The paper's scene in plane strain (prm/block_on_strip_2d.prm: a soft
// block pressed onto a clamped strip that yields at the clamp, the
// fourth-order crack phase field and Coulomb friction, line3 mortar
// contact), to 9 mm in steps of 0.3 mm. Checks at every step:
//  - the contact force plus the friction force equals the reaction on the
//    block's top (1e-6 of the reaction);
//  - the energy balance W_ext - Psi^e - W_p - crack energy - viscous and
//    frictional dissipation closes to 1 % of W_ext from the third step, and
//    to 0.02 J/m in the first two (the block's first touch leaves 0.015
//    J/m, as in 3-D);
//  - the viscous crack dissipation and the frictional dissipation never
//    decrease; s stays in [0, 1] at the nodes and never decreases (1e-8);
//  - the strip yields (W_p > 0), the crack field grows (max s > 0.01) and
//    the block slides (frictional dissipation > 0).
// The quantities of interest at the end at 5 significant digits: reaction,
// W_ext, W_p, crack energy, max s, frictional dissipation. On 1 and 2 MPI
// ranks with identical output.
#include "../tests.h"

#include <cmath>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const std::string prm = Testing::shipped_scene("block_on_strip_2d.prm") +
                          R"(
subsection Load stepping
  set End time  = 60
  set Time step = 2
end
subsection Output
  set Interval = 0
end
)";
  const Testing::Table t = Testing::run_scene(prm, "block_on_strip");
  const auto column      = [&](const std::string &name, const std::size_t k) {
    return t.at(name)[k];
  };
  const std::size_t n           = t.at("time").size();
  double            worst_force = 0, worst_balance = 0, worst_onset = 0,
         worst_increment = 0, max_s = 0, min_s_change = 0;
  for (std::size_t k = 1; k < n; ++k)
    {
      const Tensor<1, 2> contact(
        {column("contact1_force_x", k) + column("contact1_friction_x", k),
         column("contact1_force_y", k) + column("contact1_friction_y", k)});
      const Tensor<1, 2> reaction({column("F2_x", k), column("F2_y", k)});
      worst_force =
        std::max(worst_force, (contact - reaction).norm() / reaction.norm());
      const double residual = std::abs(column("energy_residual", k));
      if (k <= 2)
        worst_onset = std::max(worst_onset, residual);
      else
        worst_balance =
          std::max(worst_balance, residual / column("external_work", k));
      for (const char *c : {"fracture_viscous_work", "contact1_dissipation"})
        worst_increment =
          std::min(worst_increment, column(c, k) - column(c, k - 1));
      max_s        = std::max(max_s, column("max_s", k));
      min_s_change = std::min(min_s_change, column("min_s_change", k));
    }
  const std::size_t last = n - 1;
  out << "contact + friction force = reaction on the block's top (1e-6): "
      << Testing::yes_no(worst_force < 1e-6) << "\n"
      << "energy balance within 1 % of W_ext from the third step, 0.02 J/m "
         "in the first two: "
      << Testing::yes_no(worst_balance < 0.01 && worst_onset < 0.02) << "\n"
      << "D_f and D_c never decrease (1e-12 J/m): "
      << Testing::yes_no(worst_increment > -1e-12) << "\n"
      << "s in [0, 1] at the nodes and never decreasing (1e-8): "
      << Testing::yes_no(max_s <= 1. + 1e-12 && min_s_change > -1e-8) << "\n"
      << "the strip yields, s grows, the block slides: "
      << Testing::yes_no(column("plastic_work", last) > 0. && max_s > 0.01 &&
                         column("contact1_dissipation", last) > 0.)
      << "\n"
      << std::setprecision(5) << "at 9 mm: F2_y " << column("F2_y", last)
      << " N/m, W_ext " << column("external_work", last) << " J/m, W_p "
      << column("plastic_work", last) << " J/m, crack energy "
      << column("fracture_energy", last) << " J/m, max s " << max_s
      << ", friction " << column("contact1_dissipation", last) << " J/m\n";
  std::cout << "worst force " << worst_force << ", worst balance "
            << worst_balance << ", onset " << worst_onset << std::endl;
}
