// A coarse copy of prm/block_on_plate_tearing.prm that tears: the paper's
// scene (plate 8 x 5 x 1, block 2 x 2 x 2 Q2 cells, 0.6 mm steps) with the
// variational crack driver 'elastic and plastic energy' (doc/model.md
// section 4.3), g_c lowered to 30 kJ/m^2 and w_c = 0 so that the hinge's
// plastic energy tears the plate at the clamp within 48 mm (the shipped
// scene's sourced w_c tears only at ~170 mm, benchmarks/paper_scene). It
// checks the energy account through the tear, with the model's own terms:
//  - |W_ext - Psi^e - Psi^p - D_p - g_c int gamma - D_f - D_c| <= 1 % of
//    W_ext at every step from the third on (0.76 % at most, through the
//    tear), and below 0.02 J in the first two, where the block starts to
//    touch and W_ext is 0.2 and 0.9 J (0.0146 and 0.0128 J there); no
//    history driving work (irreversibility by the box s_n <= s <= 1
//    alone);
//  - at every step the increments of the viscous crack dissipation D_f,
//    of the frictional dissipation D_c and of the plastic energy the crack
//    takes, R_p, are >= 0 (to 1e-9 J), s stays in [0, 1] at the nodes and
//    never decreases;
//  - the plate tears: the reaction falls below 5 % of its peak, max s = 1;
//  - the quantities of interest, 5 significant digits: peak and end
//    reaction, W_ext, W_p, Psi^p, R_p, D_p, crack energy, friction.
// D_p is reported, not bounded: here it is the backward Euler step's
// O(dalpha^2) on the flow resistance that falls in the rounded bracket
// (model.md section 3), -1.6 % of W_p with these 0.6 mm steps.
// One rank.
#include "tests.h"

#include <algorithm>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const Testing::Table t = Testing::run_scene(
    Testing::coarse_block_on_plate_prm(R"(
subsection Body 0
  subsection Fracture
    set Critical energy release rate = 30e3
    set Critical work density        = 0
  end
end
subsection Load stepping
  set End time = 320
end
)",
                                       "block_on_plate_tearing.prm"),
    "tearing_run");
  const std::size_t n   = t.at("time").size();
  const auto        col = [&](const std::string &name, const std::size_t k) {
    return t.at(name)[k];
  };
  double worst_balance = 0., worst_increment = 0., peak = 0., max_s = 0.,
         min_s_change = 0., history = 0., worst_onset = 0.;
  for (std::size_t k = 1; k < n; ++k)
    {
      if (k <= 2)
        worst_onset =
          std::max(worst_onset, std::abs(col("energy_residual", k)));
      else
        worst_balance = std::max(worst_balance,
                                 std::abs(col("energy_residual", k)) /
                                   col("external_work", k));
      for (const char *c : {"fracture_viscous_work",
                            "contact1_dissipation",
                            "plastic_energy_released"})
        worst_increment =
          std::min(worst_increment, col(c, k) - col(c, k - 1));
      peak         = std::max(peak, std::abs(col("F2_z", k)));
      max_s        = std::max(max_s, col("max_s", k));
      min_s_change = std::min(min_s_change, col("min_s_change", k));
      history =
        std::max(history, std::abs(col("history_driving_work", k)));
    }
  const std::size_t last = n - 1;
  out << "energy balance within 1 % of W_ext at every step from the third, "
         "0.02 J in the first two: "
      << Testing::yes_no(worst_balance < 0.01 && worst_onset < 0.02) << "\n"
      << "no history driving work: " << Testing::yes_no(history == 0.)
      << "\n"
      << "D_f, D_c and R_p never decrease (1e-9 J): "
      << Testing::yes_no(worst_increment > -1e-9) << "\n"
      << "s in [0, 1] at the nodes and never decreasing (1e-8): "
      << Testing::yes_no(max_s <= 1. + 1e-12 && min_s_change > -1e-8)
      << "\n"
      << "the plate tears (end reaction < 5 % of the peak, max s = 1): "
      << Testing::yes_no(std::abs(col("F2_z", last)) < 0.05 * peak &&
                         max_s > 1. - 1e-6)
      << "\n"
      << std::setprecision(5) << "peak reaction " << peak
      << " N, end reaction " << col("F2_z", last) << " N\n"
      << "W_ext " << col("external_work", last) << " J, W_p "
      << col("plastic_work", last) << " J, Psi^p "
      << col("hardening_energy", last) << " J, R_p "
      << col("plastic_energy_released", last) << " J, D_p "
      << col("plastic_dissipation", last) << " J\n"
      << "crack energy " << col("fracture_energy", last) << " J, friction "
      << col("contact1_dissipation", last) << " J\n";
  std::cout << "worst balance " << worst_balance << ", worst increment "
            << worst_increment << ", steps " << last << std::endl;
}
