// The iterative linear solver on the plane-strain paper scene
// (prm/block_on_strip_2d.prm refined once: plasticity, the fourth-order
// phase field, Coulomb friction with stick and slip nodes, line3 mortar
// contact by semi-smooth Newton), 3 steps to 3 mm (the strip has not yet
// yielded: W_p is round-off there and is compared, not printed). The scene
// runs with `Type = direct`, and with `Type = gmres-amg` keeping the contact
// rows in the displacement AMG and eliminating them (`Constrained rows =
// eliminate`: the Schur complement of the active nodes' constrained
// components in their nodal frames), the latter also with the rigid-body
// modes of each body as the AMG's near-null space (`Rigid-body modes = per
// body`). The preconditioner changes how the solves get there, not the
// answer: each iterative run must give the direct run's reaction (to 1e-6 of
// itself), W_ext, W_p, crack energy and frictional dissipation (to 1e-6 of
// W_ext) at every step. The direct run's values at the end are printed at 5
// significant digits. On 1 and 2 MPI ranks with identical output (on 2 ranks
// the constrained nodes' columns cross the partition).
#include "../tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  Testing::Table
  run(const std::string &entries, const std::string &directory)
  {
    const std::string prm = Testing::shipped_scene("block_on_strip_2d.prm") +
                            R"(
subsection Mesh
  set Global refinements = 1
end
subsection Load stepping
  set End time  = 3
  set Time step = 1
end
subsection Output
  set Interval = 0
end
subsection Linear solver
)" + entries + R"(
end
)";
    return Testing::run_scene(prm, directory);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const Testing::Table direct = run("  set Type = direct\n", "direct");
  for (const std::string rows : {"keep", "eliminate", "eliminate, per body"})
    {
      const bool           per_body = rows.find("per body") != rows.npos;
      const Testing::Table t =
        run("  set Type = gmres-amg\n"
            "  set Constrained rows = " +
              rows.substr(0, rows.find(',')) + "\n" +
              (per_body ? "  set Rigid-body modes = per body\n" : ""),
            "gmres_" + std::to_string(per_body) + rows.substr(0, 4));
      // The force against itself, the energies against W_ext.
      const double worst =
        Testing::stepwise_difference(t,
                                     direct,
                                     "F2_y",
                                     {"external_work",
                                      "plastic_work",
                                      "fracture_energy",
                                      "contact1_dissipation"});
      out << "gmres-amg, constrained rows " << rows
          << ": every step as the direct solver's to 1e-6: "
          << Testing::yes_no(worst < 1e-6) << "\n";
      std::cout << rows << ": worst relative difference " << worst << std::endl;
    }
  const std::size_t last = direct.at("time").size() - 1;
  out << std::setprecision(5) << "at 3 mm: F2_y " << direct.at("F2_y")[last]
      << " N/m, W_ext " << direct.at("external_work")[last]
      << " J/m, crack energy " << direct.at("fracture_energy")[last]
      << " J/m, friction " << direct.at("contact1_dissipation")[last]
      << " J/m, active nodes " << direct.at("contact1_active_nodes")[last]
      << "\n";
}
