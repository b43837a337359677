// Run time against error for the C0IP crack operator alone: the
// manufactured solution (validation rung 5) and the crack-energy strip
// (rung 6), Q2 and Q3, direct (MUMPS) and CG + ML AMG. One line per run:
// problem degree solver h n_dofs error(s) assembly_s solve_s iterations.
#include <deal.II/base/mpi.h>

#include <ductile_contact/phase_field/operator_problems.h>

#include <cmath>
#include <iostream>

using namespace DuctileContact;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (root)
    std::cout << "problem degree solver h n_dofs err_L2 err_H1 err_H2 "
                 "assembly_s solve_s iterations\n";

  for (const unsigned int degree : {2u, 3u})
    for (const std::string solver : {"direct", "cg-amg"})
      for (unsigned int r = 1; r <= (degree == 2 ? 4u : 3u); ++r)
        {
          if (solver == "cg-amg" && r > 3)
            continue; // > 1000 CG iterations at l/h = 16, see README
          C0IPCoefficients c;
          c.mass        = 0.5;
          c.gradient    = 1.;
          c.bilaplacian = 0.5;
          c.penalty     = default_c0ip_penalty(degree);
          const ManufacturedErrors e =
            solve_manufactured_c0ip(degree, r, c, solver, MPI_COMM_WORLD);
          if (root)
            std::cout << "manufactured " << degree << " " << solver << " "
                      << e.h << " " << e.info.n_dofs << " " << e.l2 << " "
                      << e.h1 << " " << e.h2 << " " << e.info.assembly_seconds
                      << " " << e.info.solve_seconds << " "
                      << e.info.linear_iterations << std::endl;
        }

  // Gamma(5 l_f) = 0.99804 (1-D optimum, model.md section 4).
  for (const unsigned int degree : {2u, 3u})
    for (const std::string solver : {"direct", "cg-amg"})
      for (const unsigned int n : {2u, 4u, 8u, 16u})
        {
          const StripResult s =
            solve_crack_strip(degree, 5., n, solver, MPI_COMM_WORLD);
          if (root)
            std::cout << "strip " << degree << " " << solver << " " << 1. / n
                      << " " << s.info.n_dofs << " "
                      << std::abs(s.gamma - 0.99804) / 0.99804 << " - - "
                      << s.info.assembly_seconds << " " << s.info.solve_seconds
                      << " " << s.info.linear_iterations << std::endl;
        }
}
