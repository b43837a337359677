// Validation rung 8 (coarse): single-edge-notched tension as a
// thin 3-D slab (tests/meshes/sent_notch.msh: `prm/meshes/make_sent.py 0.1
// 0.2`, one element layer, slit from the left edge to the centre), Miehe's
// material (lambda = 121.15, mu = 80.77 kN/mm^2, g_c = 2.7 N/mm) with a coarse
// l_f = h = 0.1 mm, Q2, top pulled, u_z = 0 on the slab faces.
//  - eta_f = 0, monolithic, pulled to u = 0.0065 mm: the force peaks (F_max
//    printed) and softens as the crack runs through the ligament; once the
//    force has dropped to 20 % of F_max, the crack energy g_c int gamma
//    equals g_c x ligament (0.5 mm) x thickness within 10 % (a straight
//    crack: a crack that left the ligament would be longer);
//    s never decreases at any DoF (the default Coupling/Irreversibility);
//  - the staggered strategy gives the same curve up to the peak.
// Peak-force convergence in h and du: benchmarks/phase_field/sent.
// One MPI rank (it ran on 2 ranks too until the suite outgrew its
// 10-minute budget): the crack's run through the ligament with the bound on
// 2 ranks is checked by fracture_bar, crack_strip, adaptive_refinement and
// checkpoint/adaptive_resume (this specimen, adapted, on 1 to 3 ranks).
#include "tests.h"

using namespace dealii;

namespace
{
  const double thickness = 1e-4; // m (one element, h = 0.1 mm)
  const double g_c       = 2700; // N/m
  const double ligament  = 5e-4; // m

  std::string
  sent_prm(const std::string &strategy,
           const double       eta_f,
           const double       end_time,
           const double       dt)
  {
    return R"(
subsection Mesh
  set Scene = gmsh
  subsection Gmsh
    set File name = )" SOURCE_DIR R"(/meshes/sent_notch.msh
  end
end
subsection Bodies
  set Material ids = 1
end
subsection Body 1
  set Shear modulus = 80.77e9
  set Bulk modulus  = 175.0e9
  set Fracture      = true
  subsection Fracture
    set Critical energy release rate = 2700
    set Length scale                 = 1e-4
    set Viscosity                    = )" +
           Utilities::to_string(eta_f) + R"(
  end
end
subsection Boundary conditions
  set Boundary ids = 1, 2, 3
end
subsection Boundary 1
  set Constrained components = x, y, z
end
subsection Boundary 2
  set Constrained components = x, y, z
  set Displacement           = 0; 1e-5*t; 0
end
subsection Boundary 3
  set Constrained components = z
end
subsection Coupling
  set Strategy = )" +
           strategy + R"(
  set Maximum staggered iterations = 500
end
subsection Load stepping
  set End time          = )" +
           Utilities::to_string(end_time) + R"(
  set Time step         = )" +
           Utilities::to_string(dt) + R"(
  set Minimum time step = )" +
           Utilities::to_string(dt / 8) + R"(
end
subsection Newton
  set Relative tolerance = 1e-9
end
subsection Linear solver
  set Type = direct
end
subsection Output
  set Interval = 0
end
)";
  }

  /// Force per unit thickness [kN/mm] on the top face at step n.
  double
  force(const Testing::Table &t, const unsigned int n)
  {
    return t.at("F2_y")[n] / thickness * 1e-6;
  }

  /// Index of the largest force.
  unsigned int
  peak(const Testing::Table &t)
  {
    unsigned int k = 0;
    for (unsigned int n = 0; n < t.at("time").size(); ++n)
      if (force(t, n) > force(t, k))
        k = n;
    return k;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(4);

  // Monolithic, rate independent (eta_f = 0), through the ligament.
  const auto mono = Testing::run_scene(sent_prm("monolithic", 0., 0.65, 0.05),
                                       "sent_monolithic");
  const unsigned int k    = peak(mono);
  const std::size_t  last = mono.at("time").size() - 1;
  // First step after the crack has run through: force below 20 % of the
  // peak.
  unsigned int through = k;
  while (through < last && force(mono, through) > 0.2 * force(mono, k))
    ++through;
  const double crack_ratio =
    mono.at("fracture_energy")[through] / (g_c * ligament * thickness);
  double min_s_change = 0;
  for (unsigned int n = 1; n <= last; ++n)
    min_s_change = std::min(min_s_change, mono.at("min_s_change")[n]);
  out << "monolithic, eta_f = 0: F_max = " << force(mono, k)
      << " kN/mm at u = " << mono.at("u2_y")[k] * 1e3 << " mm" << std::endl
      << "  the force softens to below 20 % of F_max by u = 0.0065 mm: "
      << Testing::yes_no(through < last ||
                         force(mono, last) < 0.2 * force(mono, k))
      << std::endl
      << "  when the force has dropped to 20 %, g_c int gamma = g_c x "
         "ligament x thickness (a straight crack through the ligament, "
         "10 %): "
      << Testing::yes_no(force(mono, through) < 0.2 * force(mono, k) &&
                         std::abs(crack_ratio - 1.) < 0.1)
      << std::endl
      << "  s never decreases at any DoF while the crack runs (Newton "
         "tolerance 1e-9): "
      << Testing::yes_no(min_s_change > -1e-9) << std::endl;
  std::cout << "peak " << force(mono, k) << " at t = " << mono.at("time")[k]
            << "; crack through at t = " << mono.at("time")[through]
            << ", crack energy ratio " << crack_ratio << "; final force "
            << force(mono, last) << ", min s change " << min_s_change
            << std::endl;

  // Staggered, same steps, up to the peak.
  const auto stag =
    Testing::run_scene(sent_prm("staggered", 0., mono.at("time")[k], 0.05),
                       "sent_staggered");
  double       worst        = 0;
  unsigned int alternations = 0, it_stag = 0, it_mono = 0;
  for (unsigned int n = 0; n <= k && n < stag.at("time").size(); ++n)
    {
      worst =
        std::max(worst,
                 std::abs(force(stag, n) - force(mono, n)) / force(mono, k));
      alternations += stag.at("staggered_iterations")[n];
      it_stag += stag.at("newton_iterations")[n];
      it_mono += mono.at("newton_iterations")[n];
    }
  out << "staggered = monolithic up to the peak (same steps, force to 1e-6): "
      << Testing::yes_no(stag.at("time").size() == k + 1 && worst < 1e-6)
      << std::endl;
  std::cout << "staggered vs monolithic: " << worst
            << "; Newton iterations up to the peak: monolithic " << it_mono
            << ", staggered " << it_stag << " in " << alternations
            << " alternations" << std::endl;
}
