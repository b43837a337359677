// The per-step contact search and its check (doc/contact.md
// section 8). The candidates of a load step fix the matrix couplings; a
// master face that comes within reach of a slave face during the step
// without being a candidate would be left out of D and M. Every assembly
// checks for such a pair; one makes the state inadmissible, the step is
// cut back and redone, and the pair's search radius doubles.
// The Hertz line contact of contact_hertz (h = a/4): at the start the
// cylinder touches the slab along a line, and the gap under the slave faces
// grows to ~1 mm at the edge of the slave surface, all within reach (half a
// slave face, 1.25 mm):
//  - with the default radius (reach plus a margin) no step misses a pair;
//  - with a given radius of 0.1 mm the candidates miss the faces further
//    out: the step fails, is cut back and redone with the radius doubled
//    until they are found, and the run ends in the same state: frictionless
//    elastic contact does not depend on the steps, so the contact force and
//    the reaction agree with the first run's (1e-6).
// On 2 MPI ranks.
#include "tests.h"

#include <cmath>
#include <sstream>

using namespace dealii;


namespace
{
  unsigned int
  count(const std::string &text, const std::string &what)
  {
    unsigned int n = 0;
    for (auto at = text.find(what); at != std::string::npos;
         at      = text.find(what, at + 1))
      ++n;
    return n;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  const std::string missed             = "came within reach of the slave face";

  std::ostringstream screen_default, screen_small;
  const auto         a =
    Testing::run_scene(Testing::hertz_line_prm(4), "default", screen_default);
  const auto b =
    Testing::run_scene(Testing::hertz_line_prm(4,
                                               "  set Search radius = 1e-4\n"),
                       "small",
                       screen_small);
  const unsigned int misses_default = count(screen_default.str(), missed);
  const unsigned int misses_small   = count(screen_small.str(), missed);
  const std::size_t  la = a.at("time").size() - 1, lb = b.at("time").size() - 1;
  double             difference = 0.;
  for (const std::string c : {"contact1_force_x", "contact1_force_y", "F2_y"})
    difference = std::max(difference,
                          std::abs(a.at(c)[la] - b.at(c)[lb]) /
                            Testing::contact_norm(a, "force", la));
  std::cout << "missed pairs: default radius " << misses_default << ", 0.1 mm "
            << misses_small << "; steps " << la << ", " << lb
            << "; largest force difference " << difference << std::endl;

  out << "default search radius: no step misses a face pair: "
      << Testing::yes_no(misses_default == 0) << std::endl
      << "search radius 0.1 mm: steps miss face pairs and are redone: "
      << Testing::yes_no(misses_small > 0 && lb > la) << std::endl
      << "  both runs reach t = 1: "
      << Testing::yes_no(std::abs(a.at("time")[la] - 1.) < 1e-12 &&
                         std::abs(b.at("time")[lb] - 1.) < 1e-12)
      << std::endl
      << "  the same contact forces and reaction at t = 1 (1e-6): "
      << Testing::yes_no(difference < 1e-6) << std::endl;
  return 0;
}
