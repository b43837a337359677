// The coarse tearing check of block_on_plate_tearing_bernstein.cc in plane
// strain, with the default Lagrange phase field: prm/block_on_strip_2d.prm
// (19 x 2 Q2 cells in the strip) with the variational crack driver
// 'elastic and plastic energy' (doc/model.md section 4.3), the
// irreversibility by the bound alone, g_c = 30 kJ/m^2, w_c = 0, the hold
// stiffness factor 10 and Maximum phase-field increment = 0.1 of
// prm/block_on_plate_tearing.prm, 0.3 mm steps to 24 mm: the strip tears
// through its thickness at the clamp at ~17.7 mm. Checks:
//  - |W_ext - Psi^e - Psi^p - D_p - g_c int gamma - D_f - D_c| <= 1 % of
//    W_ext at every step from the fourth on (0.84 % at most, at the fourth:
//    the offset of the first touch; 0.79 % in the tear),
//    and below 0.08 J/m in the first three, where the block starts to
//    touch (0.071 J/m of W_ext = 0.40 J/m after the first step, an offset
//    that then stays); no history driving work;
//  - the increments of D_f, D_c and of the plastic energy the crack takes,
//    R_p, are >= 0 at every step, s stays in [0, 1] at the nodes and never
//    decreases (between the nodes the Lagrange field exceeds 1: its largest
//    value at a quadrature point is printed, against <= 1 with the
//    Bernstein basis of the 3-D test);
//  - the strip tears: the set s >= 0.95 reaches within 2 mm (a tenth of
//    the thickness) of its bottom and top at the clamp, max s = 1, and the
//    reaction falls below 10 % of its peak;
//  - the quantities of interest per unit thickness, 5 significant digits.
// One rank.
#include "../tearing_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                            out = Testing::open_output();
  const Testing::TearingScene              scene =
    Testing::strip_tearing_scene(R"(
subsection Body 0
  subsection Plasticity
    set Hold stiffness factor = 10
  end
end
)",
                                 2.,
                                 "block_on_strip_tearing");
  Testing::check_tearing(out, scene);
}
