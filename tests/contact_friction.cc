// Validation rung 12: Coulomb friction on the non-matching
// two-cube patch (tests/meshes/contact_patch.msh). The lower cube's bottom
// is clamped; the upper cube's top is pressed down by 1 MPa (t <= 1) and
// then moved along x by 1e-2 m x (t - 1), held in y; its sides are free.
//  - mu_c = 0.3: the interface first sticks, then slips from the edges
//    until every node in contact slips; in steady sliding (t = 2, once the
//    slip directions have aligned) |F_T| = mu_c |F_N| (the friction and
//    normal forces the slave exerts on the master) to 1e-6,
//    the top's reaction balances F_T + F_N along x, the ratio |F_T|/|F_N|
//    grows while some nodes stick and the block starts to slide as a
//    whole (no node sticks) when it reaches mu_c, never above; in the last
//    steps the work done goes into the dissipation (47): the energy balance
//    W_ext - Psi^e - D_c stays constant to 0.1 % of that work;
//  - mu_c = 0: no friction force: all the top's reaction along x comes
//    from the normal pressure on the (slightly dented) interface;
//  - mu_c = 10, moved to 2.5e-3 m: every node in contact sticks, nothing
//    is dissipated.
// On 2 MPI ranks (rank invariance is shown by contact_patch and
// contact_hertz).
#include "tests.h"

#include <cmath>

using namespace dealii;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  {
    const auto s =
      Testing::run_scene(Testing::patch_sliding_prm(0.3, "2"), "mu03");
    const std::size_t last  = s.at("time").size() - 1;
    const double      ratio = Testing::contact_norm(s, "friction", last) /
                         Testing::contact_norm(s, "force", last);
    const double balance =
      std::abs(s.at("F2_x")[last] - s.at("contact1_force_x")[last] -
               s.at("contact1_friction_x")[last]) /
      std::abs(s.at("F2_x")[last]);
    // Energy balance over the last steps (steady sliding): the work done
    // on the top goes into dissipation (and a little stored energy).
    const std::size_t first = last - 4;
    const double      dW =
      s.at("external_work")[last] - s.at("external_work")[first];
    const double dD =
      s.at("contact1_dissipation")[last] - s.at("contact1_dissipation")[first];
    const double dR =
      s.at("energy_residual")[last] - s.at("energy_residual")[first];
    // Onset of gross sliding: the first step in which no node sticks.
    std::size_t onset     = last + 1;
    double      max_ratio = 0;
    for (std::size_t n = 1; n <= last; ++n)
      {
        max_ratio = std::max(max_ratio,
                             Testing::contact_norm(s, "friction", n) /
                               Testing::contact_norm(s, "force", n));
        if (onset > last && s.at("contact1_sticking_nodes")[n] == 0 &&
            s.at("contact1_slipping_nodes")[n] > 0)
          onset = n;
      }
    const double onset_ratio = onset <= last
                                 ? Testing::contact_norm(s, "friction", onset) /
                                     Testing::contact_norm(s, "force", onset)
                                 : 0.;
    std::cout << "onset of sliding at t = "
              << (onset <= last ? s.at("time")[onset] : -1.) << ", ratio "
              << onset_ratio << ", largest ratio " << max_ratio << std::endl;
    std::cout << "mu 0.3: |F_T|/|F_N| " << ratio << ", balance " << balance
              << ", dW " << dW << ", dD " << dD << ", d residual " << dR
              << ", slipping " << s.at("contact1_slipping_nodes")[last]
              << " of " << s.at("contact1_active_nodes")[last] << std::endl;
    out << "mu_c = 0.3, full sliding: every node in contact slips: "
        << Testing::yes_no(s.at("contact1_slipping_nodes")[last] ==
                             s.at("contact1_active_nodes")[last] &&
                           s.at("contact1_active_nodes")[last] > 0)
        << std::endl
        << "  |F_T| = mu_c |F_N| (1e-6): "
        << Testing::yes_no(std::abs(ratio - 0.3) < 0.3e-6) << std::endl
        << "  reaction of the top = F_N,x + F_T,x (1e-6): "
        << Testing::yes_no(balance < 1e-6) << std::endl
        << "  steady sliding: dissipation > 95 % of the work done, energy "
           "balance W_ext - Psi^e - D_c closes to 0.1 % of it: "
        << Testing::yes_no(dD > 0.95 * dW && std::abs(dR) < 1e-3 * dW)
        << std::endl
        << "  the block starts to slide (no node sticks any more) when |F_T| "
           "reaches mu_c |F_N| (1e-3), never above it (1e-6): "
        << Testing::yes_no(onset < last &&
                           std::abs(onset_ratio - 0.3) < 0.3e-3 &&
                           max_ratio < 0.3 * (1. + 1e-6))
        << std::endl
        << "  the interface stuck at first (no slip before the shear): "
        << Testing::yes_no(s.at("contact1_slipping_nodes")[8] == 0 &&
                           s.at("contact1_sticking_nodes")[8] > 0)
        << std::endl;
  }
  {
    const auto s =
      Testing::run_scene(Testing::patch_sliding_prm(0., "1.5"), "mu0");
    const std::size_t last = s.at("time").size() - 1;
    std::cout << "mu 0: F2_x " << s.at("F2_x")[last] << ", F_N "
              << Testing::contact_norm(s, "force", last) << std::endl;
    out << "mu_c = 0: no friction force; the top's reaction along x is the "
           "x-part of the normal force (1e-6 |F_N|): "
        << Testing::yes_no(
             Testing::contact_norm(s, "friction", last) == 0. &&
             std::abs(s.at("F2_x")[last] - s.at("contact1_force_x")[last]) <
               1e-6 * Testing::contact_norm(s, "force", last))
        << std::endl;
  }
  {
    const auto s =
      Testing::run_scene(Testing::patch_sliding_prm(10., "1.25"), "mu10");
    const std::size_t last = s.at("time").size() - 1;
    out << "mu_c = 10: every node sticks, nothing dissipated: "
        << Testing::yes_no(s.at("contact1_sticking_nodes")[last] ==
                             s.at("contact1_active_nodes")[last] &&
                           std::abs(s.at("contact1_dissipation")[last]) < 1e-9)
        << std::endl;
    std::cout << "mu 10: sticking " << s.at("contact1_sticking_nodes")[last]
              << " of " << s.at("contact1_active_nodes")[last]
              << ", dissipation " << s.at("contact1_dissipation")[last]
              << std::endl;
  }
}
