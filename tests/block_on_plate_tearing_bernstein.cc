// The coarse tearing scene of block_on_plate_tearing.cc (the same checks)
// with the phase field in the Bernstein basis (Finite elements/Phase-field
// basis = Bernstein, as prm/block_on_plate_tearing.prm sets it): the box s_n <= s <= 1 on the Bernstein coefficients
// holds at every point, so s <= 1 at every quadrature point as well (the
// Lagrange field of block_on_plate_tearing reaches 1.0189 there); the
// balance holds to 0.73 % of W_ext through the tear. The peak reaction
// agrees with the Lagrange field's to 6e-5 (the tear starts after it); the
// tear's path differs by the field's representation between the nodes.
// One rank.
#include "tearing_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out = Testing::open_output();
  Testing::check_coarse_tearing(out,
                                R"(
subsection Finite elements
  set Phase-field basis = Bernstein
end
)",
                                "tearing_run_bernstein",
                                true);
}
