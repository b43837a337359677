// Validation rung 6: the crack-energy strip. A bar [-L, L] periodic across
// (an infinite plate) with s = 1 imposed on the plane x = 0, no load: the
// C0IP-consistent int gamma per unit crack area must equal the 1-D optimum
// Gamma(L) = 0.48563, 0.82033, 0.95382, 0.99804 for L = 1, 2, 3, 5 l_f
// (model.md section 4). Q2 with h = l_f/4 and l_f/8 (errors below 0.3 % and
// 0.08 %, shrinking like h^2) and Q3 with h = l_f/4 (below 2e-5, the
// precision of the reference values).
#include <ductile_contact/phase_field/operator_problems.h>

#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const double       reference[4]   = {0.48563, 0.82033, 0.95382, 0.99804};
  const double       half_length[4] = {1, 2, 3, 5};
  const unsigned int degree[3]      = {2, 2, 3};
  const unsigned int cells[3]       = {4, 8, 4};
  const double       tolerance[3]   = {3e-3, 8e-4, 2e-5};
  for (unsigned int run = 0; run < 3; ++run)
    {
      out << "Q" << degree[run] << ", h = l_f/" << cells[run] << ":"
          << std::endl;
      bool ok = true;
      for (unsigned int k = 0; k < 4; ++k)
        {
          const StripResult r = solve_crack_strip(
            degree[run], half_length[k], cells[run], "direct", MPI_COMM_WORLD);
          const double error = std::abs(r.gamma - reference[k]) / reference[k];
          ok                 = ok && error < tolerance[run];
          out << "  L = " << half_length[k]
              << " l_f: Gamma = " << std::setprecision(5) << r.gamma
              << std::setprecision(6) << std::endl;
        }
      out << "  within " << tolerance[run]
          << " of Gamma(L): " << Testing::yes_no(ok) << std::endl;
    }
}
