// Contact by the semi-smooth Newton method (Contact pair/
// Enforcement = semi-smooth Newton: dual multipliers condensed from the
// slave rows, active set and stick/slip resolved in the one Newton loop).
//  - The patch test of contact_patch (non-matching swirled cubes, symmetry
//    planes through the contact surface, 1 MPa on top), both sides as
//    slave: the pressure p / lambda_lat^2 at every slave node and the
//    single block's displacement, as with the augmented Lagrangian, but
//    with the weighted gap zero on the active set (no penetration
//    tolerance) and no multiplier loop.
//  - The paper's block on the plate (coarse copy of prm/two_bodies.prm,
//    mu_c = 0.2, 3 steps): the condensed tangent against central finite
//    differences of the whole condensed residual (frictionless, sticking
//    and slipping nodes at once); 1 Newton iteration in each step after
//    the first, and the reaction on the block's top at the end, 5
//    significant digits. The first step starts touching at zero pressure,
//    where the stick/slip state of every node is decided by the round-off
//    of gaps and tractions near 1e-21: its path moves with the summation
//    order of the mortar integrals and the CPU (5, 6 or 7 iterations; the
//    residual after the first update 129.9, 130.0 or 130.3 with the same
//    code built with and without -march=native, and with D lumped before
//    or after the integration), so its count goes to the screen only; the
//    later steps' does not move.
//    (The patch test's flush edges put kinks into the residual, so its
//    tangent is not checked there.)
//  - Coulomb sliding of contact_friction (mu_c = 0.3): the interface
//    sticks exactly at first, then every node slips with |F_T| = mu_c
//    |F_N|, and the top's reaction balances F_N + F_T.
// One MPI rank (it ran on 2 ranks too until the suite outgrew its
// 10-minute budget): contact_refined runs the same patch test, the block
// on the plate with the tangent checked and frictional sliding by
// semi-smooth Newton on 2 ranks, and checkpoint/resume the block on the
// plate on 1, 2 and 3 ranks.
#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  const std::string semi_smooth = "  set Enforcement = semi-smooth Newton\n";

  std::string
  block_on_plate_prm()
  {
    std::string prm = Testing::shipped_scene("two_bodies.prm");
    for (const auto &[from, to] :
         {std::pair<std::string, std::string>{"19, 13, 2", "10, 7, 1"},
          {"5, 5, 5", "3, 3, 3"},
          {"End time  = 113", "End time  = 3"}})
      prm.replace(prm.find(from), from.size(), to);
    return prm + R"(
subsection Contact pair 1
  set Enforcement = semi-smooth Newton
end
subsection Newton
  set Check tangent = true
end
)";
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const auto block =
    Testing::run_scene(Testing::contact_patch_single_block_prm(),
                       "single_block");
  const double lateral    = 1. + 2. * block.at("u5_x").back();
  const double p_expected = 1e6 / (lateral * lateral);
  for (const auto &[slave, master, name] :
       {std::tuple{4u, 3u, "finer (upper) cube as slave"},
        std::tuple{3u, 4u, "coarser (lower) cube as slave"}})
    {
      const auto        s = Testing::run_scene(Testing::contact_patch_prm(slave,
                                                                   master,
                                                                   semi_smooth),
                                        "patch_" + std::to_string(slave));
      const std::size_t last   = s.at("time").size() - 1;
      const double      p_max  = s.at("contact1_max_pressure")[last];
      const double      p_min  = s.at("contact1_min_pressure")[last];
      const double      force  = s.at("contact1_force_z")[last];
      const double      pen    = s.at("contact1_max_penetration")[last];
      const double      sign   = (slave == 4) ? -1. : 1.;
      double            newton = 0.;
      for (std::size_t n = 1; n <= last; ++n)
        newton = std::max(newton, s.at("newton_iterations")[n]);
      out << name << ":" << std::endl
          << "  pressure uniform, (max - min) / max < 1e-8: "
          << Testing::yes_no((p_max - p_min) / p_max < 1e-8) << std::endl
          << "  pressure = p / lambda_lat^2 of the single block (1e-6): "
          << Testing::yes_no(std::abs(p_max - p_expected) < 1e-6 * p_expected)
          << std::endl
          << "  contact force = p A_0 (1e-8): "
          << Testing::yes_no(std::abs(sign * force - 1e6) < 1e-2) << std::endl
          << "  weighted gap zero on the active set (penetration < 1e-12 h): "
          << Testing::yes_no(pen < 1e-12 * 0.25) << std::endl
          << "  at most 4 Newton iterations per step, no multiplier "
             "updates: "
          << Testing::yes_no(newton <= 4 &&
                             s.at("contact_augmentations")[last] <= 1)
          << std::endl
          << "  active slave nodes: " << s.at("contact1_active_nodes")[last]
          << std::endl;
      std::cout << name << ": p " << p_min << " .. " << p_max << " (exact "
                << p_expected << "), force " << force << ", penetration " << pen
                << ", Newton per step " << newton << std::endl;
    }

  {
    const auto s = Testing::run_scene(block_on_plate_prm(), "block_on_plate");
    const std::size_t last          = s.at("time").size() - 1;
    double            tangent_error = 0., newton = 0.;
    for (std::size_t n = 1; n <= last; ++n)
      {
        tangent_error = std::max(tangent_error, s.at("tangent_error")[n]);
        if (n > 1)
          newton = std::max(newton, s.at("newton_iterations")[n]);
      }
    const double first = s.at("newton_iterations")[1];
    std::cout << "block on plate: tangent error " << tangent_error
              << ", Newton in the first step " << first << ", later " << newton
              << ", sticking " << s.at("contact1_sticking_nodes")[last]
              << ", slipping " << s.at("contact1_slipping_nodes")[last]
              << std::endl;
    out << "block on plate, mu_c = 0.2:" << std::endl
        << "  sticking and slipping nodes: "
        << Testing::yes_no(s.at("contact1_sticking_nodes")[last] > 0 &&
                           s.at("contact1_slipping_nodes")[last] > 0)
        << std::endl
        << "  condensed tangent = finite differences of the residual "
           "(1e-3 at the last update of each step): "
        << Testing::yes_no(tangent_error < 1e-3) << std::endl
        << "  1 Newton iteration in each step after the first: "
        << Testing::yes_no(newton <= 1) << std::endl
        << std::setprecision(5)
        << "  reaction on the block's top at the end: x " << s.at("F2_x").back()
        << " N, z " << s.at("F2_z").back() << " N (y is 0 to round-off)"
        << std::setprecision(6) << std::endl;
  }

  {
    const auto s =
      Testing::run_scene(Testing::patch_sliding_prm(0.3, "2", semi_smooth),
                         "mu03");
    const std::size_t last  = s.at("time").size() - 1;
    const double      ratio = Testing::contact_norm(s, "friction", last) /
                         Testing::contact_norm(s, "force", last);
    const double balance =
      std::abs(s.at("F2_x")[last] - s.at("contact1_force_x")[last] -
               s.at("contact1_friction_x")[last]) /
      std::abs(s.at("F2_x")[last]);
    double newton = 0.;
    for (std::size_t n = 1; n <= last; ++n)
      newton += s.at("newton_iterations")[n];
    std::cout << "mu 0.3: |F_T|/|F_N| " << ratio << ", balance " << balance
              << ", slipping " << s.at("contact1_slipping_nodes")[last]
              << " of " << s.at("contact1_active_nodes")[last]
              << ", Newton iterations " << newton << " in " << last << " steps"
              << std::endl;
    out << "mu_c = 0.3, full sliding: every node in contact slips: "
        << Testing::yes_no(s.at("contact1_slipping_nodes")[last] ==
                             s.at("contact1_active_nodes")[last] &&
                           s.at("contact1_active_nodes")[last] > 0)
        << std::endl
        << "  |F_T| = mu_c |F_N| (1e-6): "
        << Testing::yes_no(std::abs(ratio - 0.3) < 0.3e-6) << std::endl
        << "  reaction of the top = F_N,x + F_T,x (1e-6): "
        << Testing::yes_no(balance < 1e-6) << std::endl
        << "  the interface stuck at first (no slip before the shear, no "
           "slip distance): "
        << Testing::yes_no(s.at("contact1_slipping_nodes")[8] == 0 &&
                           s.at("contact1_sticking_nodes")[8] > 0 &&
                           s.at("contact1_max_slip")[8] < 1e-12)
        << std::endl;
  }
}
