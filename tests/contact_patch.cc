// Validation rung 10: the contact patch test. Two unit cubes
// stacked along z (tests/meshes/contact_patch.msh, made by
// `make_contact_patch.py 3 4 10`): 3x3 and 4x4 cells across, node positions
// swirled in opposite senses so that the contact surfaces do not match.
// Symmetry planes x = 0 and y = 0, u_z = 0 at the bottom, a dead-load
// pressure p = 1e6 Pa on the top, frictionless mortar contact between the
// cubes. Exact: both cubes in the same homogeneous state as one 1 x 1 x 2
// block (run here as well), the contact pressure p / lambda_lat^2 at every
// slave node (Cauchy), the contact force p A_0.
// Checked for the finer mesh as slave (the documented choice) and for the
// coarser one as slave; on 1, 2 and 3 MPI ranks with identical output.
#include "tests.h"

using namespace dealii;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const auto block =
    Testing::run_scene(Testing::contact_patch_single_block_prm(),
                       "single_block");
  const double top_uz     = block.at("u5_z").back();
  const double lateral    = 1. + 2. * block.at("u5_x").back();
  const double p_expected = 1e6 / (lateral * lateral);
  std::cout << "single block: top u_z " << top_uz << ", lateral stretch "
            << lateral << ", Cauchy pressure " << p_expected << std::endl;

  for (const auto &[slave, master, name] :
       {std::tuple{4u, 3u, "finer (upper) cube as slave"},
        std::tuple{3u, 4u, "coarser (lower) cube as slave"}})
    {
      const auto s =
        Testing::run_scene(Testing::contact_patch_prm(slave, master),
                           "patch_" + std::to_string(slave));
      const double p_max = s.at("contact1_max_pressure").back();
      const double p_min = s.at("contact1_min_pressure").back();
      const double force = s.at("contact1_force_z").back();
      const double uz    = s.at("u2_z").back();
      const double pen   = s.at("contact1_max_penetration").back();
      // The slave normal points out of the slave body: down for the upper
      // cube, up for the lower one.
      const double sign = (slave == 4) ? -1. : 1.;
      out << name << ":" << std::endl
          << "  pressure uniform, (max - min) / max < 1e-8: "
          << Testing::yes_no((p_max - p_min) / p_max < 1e-8) << std::endl
          << "  pressure = p / lambda_lat^2 of the single block (1e-8): "
          << Testing::yes_no(std::abs(p_max - p_expected) < 1e-8 * p_expected)
          << std::endl
          << "  contact force = p A_0 (1e-8): "
          << Testing::yes_no(std::abs(sign * force - 1e6) < 1e-2) << std::endl
          << "  top displacement = single block's (1e-8): "
          << Testing::yes_no(std::abs(uz - top_uz) < 1e-8 * std::abs(top_uz))
          << std::endl
          << "  penetration below the tolerance (1e-6 h): "
          << Testing::yes_no(pen < 1e-6 * 0.25) << std::endl
          << "  active slave nodes: " << s.at("contact1_active_nodes").back()
          << std::endl;
      std::cout << name << ": p " << p_min << " .. " << p_max << " (exact "
                << p_expected << "), force " << force << ", top u_z " << uz
                << " (single block " << top_uz << "), penetration " << pen
                << ", Newton " << s.at("newton_iterations").back()
                << ", augmentations " << s.at("contact_augmentations").back()
                << std::endl;
    }
}
