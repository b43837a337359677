// The contact patch test in plane strain (line3 contact faces): two unit
// squares stacked along y (tests/meshes/contact_patch_2d.msh, made by
// `make_contact_patch_2d.py`: 3 and 4 cells across at unequal spacings, so
// that the contact lines do not match), u_x = 0 on x = 0, u_y = 0 at the
// bottom, a dead-load pressure p = 1e6 Pa on the top, frictionless mortar
// contact between the squares. Exact: both squares in the same homogeneous
// state as one 1 x 2 block (run here as well), the contact pressure
// p / lambda_lat at every slave node (Cauchy), the contact force p L_0 per
// unit thickness. Checked with semi-smooth Newton for the finer mesh as
// slave (the documented choice) and for the coarser one as slave, and
// with the augmented Lagrangian for the finer one. On 1 and 2 MPI ranks
// with identical output.
#include "../tests.h"

using namespace dealii;

namespace
{
  /// Two load steps to 1 MPa, Newton to 1e-11 (both runs).
  const std::string steps = R"(subsection Load stepping
  set End time  = 1
  set Time step = 0.5
end
subsection Newton
  set Relative tolerance = 1e-11
end
)";

  const std::string material = R"(
  set Shear modulus = 1e9
  set Bulk modulus  = 2e9
end
)";

  /// The single 1 x 2 block: the state both squares must reach.
  std::string
  single_block_prm()
  {
    return R"(
set Dimension = 2
subsection Mesh
  set Scene = box
  subsection Box
    set Lower corner = 0, 0
    set Upper corner = 1, 2
    set Subdivisions = 2, 4
  end
end
subsection Body 0)" +
           material + R"(
subsection Boundary conditions
  set Boundary ids = 0, 2, 3
end
subsection Boundary 0
  set Constrained components = x
end
subsection Boundary 2
  set Constrained components = y
end
subsection Boundary 3
  set Traction = 0; -1e6*t
end
)" + steps;
  }

  std::string
  patch_prm(const unsigned int slave,
            const unsigned int master,
            const std::string &pair_entries)
  {
    return "set Dimension = 2\n" +
           Testing::two_body_contact_prm("contact_patch_2d.msh",
                                         "1e9",
                                         "2e9",
                                         slave,
                                         master,
                                         pair_entries) +
           R"(
subsection Boundary conditions
  set Boundary ids = 1, 2, 5, 8
end
subsection Boundary 1
  set Constrained components = y
end
subsection Boundary 2
  set Traction = 0; -1e6*t
end
subsection Boundary 5
  set Constrained components = x
end
subsection Boundary 8
  set Constrained components = x
end
)" + steps;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const auto   block   = Testing::run_scene(single_block_prm(), "single_block");
  const double top_uy  = block.at("u3_y").back();
  const double lateral = 1. + 2. * block.at("u3_x").back();
  const double p_expected = 1e6 / lateral;
  std::cout << "single block: top u_y " << top_uy << ", lateral stretch "
            << lateral << ", Cauchy pressure " << p_expected << std::endl;

  const std::string augmented = "  set Enforcement = augmented Lagrangian\n"
                                "  set Penetration tolerance = 1e-8\n";
  for (const auto &[slave, master, entries, name] :
       {std::tuple{4u, 3u, std::string(), "finer (upper) square as slave"},
        std::tuple{3u, 4u, std::string(), "coarser (lower) square as slave"},
        std::tuple{
          4u, 3u, augmented, "finer square as slave, augmented Lagrangian"}})
    {
      const auto   s     = Testing::run_scene(patch_prm(slave, master, entries),
                                        "patch_" + std::to_string(slave) +
                                          (entries.empty() ? "" : "_al"));
      const double p_max = s.at("contact1_max_pressure").back();
      const double p_min = s.at("contact1_min_pressure").back();
      const double force = s.at("contact1_force_y").back();
      const double uy    = s.at("u2_y").back();
      const double pen   = s.at("contact1_max_penetration").back();
      // The slave normal points out of the slave body: down for the upper
      // square, up for the lower one.
      const double sign = (slave == 4) ? -1. : 1.;
      out << name << ":" << std::endl
          << "  pressure uniform, (max - min) / max < 1e-8: "
          << Testing::yes_no((p_max - p_min) / p_max < 1e-8) << std::endl
          << "  pressure = p / lambda_lat of the single block (1e-8): "
          << Testing::yes_no(std::abs(p_max - p_expected) < 1e-8 * p_expected)
          << std::endl
          << "  contact force = p L_0 (1e-8): "
          << Testing::yes_no(std::abs(sign * force - 1e6) < 1e-2) << std::endl
          << "  top displacement = single block's (1e-8): "
          << Testing::yes_no(std::abs(uy - top_uy) < 1e-8 * std::abs(top_uy))
          << std::endl
          << "  penetration below 1e-6 h: " << Testing::yes_no(pen < 1e-6 * 0.2)
          << std::endl
          << "  active slave nodes: " << s.at("contact1_active_nodes").back()
          << std::endl;
      std::cout << name << ": p " << p_min << " .. " << p_max << " (exact "
                << p_expected << "), force " << force << ", top u_y " << uy
                << " (single block " << top_uy << "), penetration " << pen
                << ", Newton " << s.at("newton_iterations").back() << std::endl;
    }
}
