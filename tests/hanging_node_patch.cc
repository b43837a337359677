// Patch test with hanging nodes: the unit cube (2x2x2 cells) with the block
// [0.5,1]x[0,0.5]x[0,0.5] refined twice by 'Local refinement boxes', so
// hanging nodes sit inside the body and on the faces x+, y-, z-. Symmetry
// planes x-, y-, z- and a dead-load traction T = 0.3 mu on x+ (the face with
// hanging nodes): the exact solution is homogeneous uniaxial stress with
// P_xx = T, which Q2 with hanging-node constraints must reproduce. Checked
// against the closed form (stretches from tau_yy = 0 and P_xx = T by
// bisection): the force through x+ and the reaction on x- (+-T A), both
// stretches and the stored energy Psi V, to 1e-8 relative.
// Identical on 1 and 2 MPI ranks.
#include <ductile_contact/materials/neo_hooke.h>

#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const double mu = 1., kappa = 4., T = 0.3;
  const auto   t = Testing::run_scene(R"(
subsection Mesh
  set Scene = box
  set Local refinement boxes = 0.5, 0, 0 : 1, 0.5, 0.5 : 2
  subsection Box
    set Subdivisions = 2, 2, 2
  end
end
subsection Body 0
  set Shear modulus = 1
  set Bulk modulus  = 4
end
subsection Boundary conditions
  set Boundary ids = 0, 1, 2, 3, 4
end
subsection Boundary 0
  set Constrained components = x
end
subsection Boundary 1
  set Traction = 0.3*t; 0; 0
end
subsection Boundary 2
  set Constrained components = y
end
subsection Boundary 3
end
subsection Boundary 4
  set Constrained components = z
end
subsection Newton
  set Relative tolerance = 1e-12
end
subsection Load stepping
  set Time step = 0.5
end
subsection Linear solver
  set Type = cg-amg
  set Relative tolerance = 1e-12
end
subsection Output
  set Interval = 0
end
)",
                                    "hanging");

  // Closed form: lateral stretch from tau_yy = 0, axial from P_xx = T.
  double lo = 1., hi = 2., lt = 1.;
  for (unsigned int i = 0; i < 200; ++i)
    ((Testing::uniaxial_stress_state(0.5 * (lo + hi), mu, kappa, lt).P[0][0] >
      T)
       ? hi
       : lo) = 0.5 * (lo + hi);
  const double           lambda = 0.5 * (lo + hi);
  const MaterialResponse m =
    Testing::uniaxial_stress_state(lambda, mu, kappa, lt);

  const double errors[] = {
    Testing::relative_error(t.at("F1_x").back(), T, T),
    Testing::relative_error(t.at("F0_x").back(), -T, T),
    Testing::relative_error(1. + t.at("u1_x").back(), lambda, 1.),
    Testing::relative_error(1. + t.at("u3_y").back(), lt, 1.),
    Testing::relative_error(t.at("stored_energy").back(),
                            m.psi_elastic,
                            m.psi_elastic)};
  out << "axial stretch = " << 1. + t.at("u1_x").back()
      << ", lateral stretch = " << 1. + t.at("u3_y").back()
      << ", stored energy / mu = " << t.at("stored_energy").back() << std::endl;
  out << "closed form: " << lambda << ", " << lt << ", " << m.psi_elastic
      << std::endl;
  out << "homogeneous uniaxial state with hanging nodes (1e-8): "
      << Testing::yes_no(
           *std::max_element(std::begin(errors), std::end(errors)) < 1e-8)
      << std::endl;
  std::cout << "errors:";
  for (const double e : errors)
    std::cout << " " << e;
  std::cout << std::endl;
}
