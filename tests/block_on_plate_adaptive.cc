// The paper's scene refined at the clamp as it yields
// (coarse): the coarse scene of block_on_plate (plate 8 x 5 x 1, block
// 2 x 2 x 2 Q2 cells, 0.6 mm steps to 9.6 mm, plasticity, the fourth-order
// phase field and Coulomb friction) three times:
//  - "coarse": as block_on_plate;
//  - "box": the plate refined once for x > 0.22 m from the start (the
//    hinge at the clamp, like benchmarks/paper_scene's clamp_refined);
//  - "adaptive": Mesh/Adaptive refinement where alpha > 5e-4, one level:
//    the cells are refined while the hinge yields, each time the step is
//    solved again on the new mesh with the carried state (history, s_n,
//    contact state).
// Checks:
//  - until the first refinement the adaptive run is the coarse run (every
//    column to 1e-9 of its scale): no trace of the adaptivity before it
//    acts;
//  - it refines in more than one step and only where the box refines (at
//    the end it has more cells than the coarse run and no more than the box
//    run);
//  - the force on the block's top at the end: the adaptive run recovers
//    most of what the box refinement changes (|F_adaptive - F_box| below a
//    quarter of |F_coarse - F_box|);
//  - across the refinements the energy balance still closes to 1 % of
//    W_ext at every step, s never decreases at any DoF, and the contact
//    plus friction force equals the reaction on the block's top (1e-6).
// One MPI rank (~60 s); adaptive refinement with contact on 2 ranks:
// contact_refined, checkpoints of adapted meshes: checkpoint/adaptive_resume.
// Benchmark on the paper's mesh: benchmarks/paper_scene (clamp_adaptive).
#include "tests.h"

#include <algorithm>
#include <cmath>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  // Every run with adaptive refinement on (the columns cells and dofs),
  // two of them with a threshold that nothing reaches.
  const auto refinement = [](const std::string &threshold,
                             const std::string &boxes) {
    return "subsection Mesh\n  set Local refinement boxes = " + boxes +
           "\n  subsection Adaptive refinement\n    set Enabled = true\n"
           "    set Hardening threshold = " +
           threshold + "\n    set Maximum level = 1\n  end\nend\n";
  };
  const Testing::Table coarse = Testing::run_scene(
    Testing::coarse_block_on_plate_prm(refinement("1e30", "")), "coarse");
  const Testing::Table box =
    Testing::run_scene(Testing::coarse_block_on_plate_prm(
                         refinement("1e30", "0.22,0,0 : 0.3,0.2,0.02 : 1")),
                       "box");
  const Testing::Table adapted = Testing::run_scene(
    Testing::coarse_block_on_plate_prm(refinement("5e-4", "")), "adaptive");

  const std::size_t n = adapted.at("time").size();
  // The first row (step) whose mesh differs from the coarse one.
  std::size_t first_refined = n;
  for (std::size_t k = 0; k < n; ++k)
    if (adapted.at("cells")[k] != coarse.at("cells")[0])
      {
        first_refined = k;
        break;
      }
  double worst_before = 0;
  for (const auto &[name, column] : coarse)
    if (name.find("time") == std::string::npos &&
        name.find("iterations") == std::string::npos && name != "newton_rate")
      worst_before = std::max(
        worst_before,
        Testing::column_difference(coarse, adapted, name, first_refined));
  unsigned int refining_steps = 0;
  double       worst_balance = 0, worst_force = 0, min_s_change = 0;
  for (std::size_t k = 1; k < n; ++k)
    {
      const auto column = [&](const std::string &name) {
        return adapted.at(name)[k];
      };
      if (column("cells") > adapted.at("cells")[k - 1])
        ++refining_steps;
      worst_balance =
        std::max(worst_balance,
                 std::abs(column("energy_residual")) / column("external_work"));
      min_s_change = std::min(min_s_change, column("min_s_change"));
      const Tensor<1, 3> contact(
        {column("contact1_force_x") + column("contact1_friction_x"),
         column("contact1_force_y") + column("contact1_friction_y"),
         column("contact1_force_z") + column("contact1_friction_z")});
      const Tensor<1, 3> reaction(
        {column("F2_x"), column("F2_y"), column("F2_z")});
      worst_force =
        std::max(worst_force, (contact - reaction).norm() / reaction.norm());
    }
  const double cells_coarse = coarse.at("cells").back();
  const double cells_box    = box.at("cells").back();
  const double cells_end    = adapted.at("cells").back();
  const double F_coarse     = coarse.at("F2_z").back(),
               F_box        = box.at("F2_z").back(),
               F_adapted    = adapted.at("F2_z").back();
  const bool same_end = std::abs(adapted.at("time").back() - 64.) < 1e-12 &&
                        std::abs(box.at("time").back() - 64.) < 1e-12 &&
                        std::abs(coarse.at("time").back() - 64.) < 1e-12;

  out << "all three runs reach 9.6 mm: " << Testing::yes_no(same_end) << "\n"
      << "adaptive = coarse until the first refinement (1e-9 of scale): "
      << Testing::yes_no(first_refined > 1 && first_refined < n &&
                         worst_before < 1e-9)
      << "\n"
      << "refined in more than one step, cells between the coarse and the "
         "box run: "
      << Testing::yes_no(refining_steps > 1 && cells_end > cells_coarse &&
                         cells_end <= cells_box)
      << "\n"
      << "end force: |adaptive - box| < |coarse - box| / 4: "
      << Testing::yes_no(std::abs(F_adapted - F_box) <
                         0.25 * std::abs(F_coarse - F_box))
      << "\n"
      << "energy balance closes to 1 % of W_ext at every step: "
      << Testing::yes_no(worst_balance < 0.01) << "\n"
      << "s never decreases at any DoF (to the Newton tolerance 1e-8): "
      << Testing::yes_no(min_s_change > -1e-8) << "\n"
      << "contact + friction force = reaction on the block's top (1e-6): "
      << Testing::yes_no(worst_force < 1e-6) << "\n";
  std::cout << "first refined at row " << first_refined << " of " << n
            << " (t = "
            << (first_refined < n ? adapted.at("time")[first_refined] : -1.)
            << "), before it differs by " << worst_before << "; refined in "
            << refining_steps << " steps; cells coarse " << cells_coarse
            << ", adaptive " << cells_end << ", box " << cells_box
            << "; F2_z coarse " << F_coarse << ", adaptive " << F_adapted
            << ", box " << F_box << " N; max alpha coarse "
            << coarse.at("max_alpha").back() << ", adaptive "
            << adapted.at("max_alpha").back() << ", box "
            << box.at("max_alpha").back() << "; worst balance " << worst_balance
            << ", min s change " << min_s_change << ", worst force "
            << worst_force << std::endl;
}
