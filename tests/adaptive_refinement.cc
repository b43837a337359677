// Adaptive refinement during the run (Mesh/Adaptive refinement),
// the predictor-corrector scheme and the state it carries.
//  - Homogeneous states are represented exactly on every mesh, so a run
//    that refines must give the run without refinement to round-off: the
//    cracking bar (fracture_bar: s grows uniformly; refined once s > 0.05)
//    (also with the phase field in the Bernstein basis, whose prolongation
//    is exact subdivision) and the plastic box (plastic_box: alpha grows
//    uniformly; refined once alpha > 1e-3). Both are refined where the loaded
//    face is, so the external work checks that the last step's force is
//    assembled again on the new mesh (an interpolated nodal force would count
//    the new nodes of the face twice), the plastic work and hardening energy
//    that the quadrature-point history arrives on the children, and the step
//    counts that the corrector redoes a step without a trace of the first
//    attempt. To 1e-7
//    of each column's scale (energies: of the external work): the
//    statistics carry 9 digits, and the runs solve to 1e-10 and 1e-11.
//  - Notched tension (tests/sent_adaptive.prm, as tests/sent_notch with
//    l_f = 0.1 mm): from
//    a mesh of h = 0.2 mm = 2 l_f, refined where s > 0.05 to h = l_f, the
//    peak force is that of the mesh made with h = l_f along the whole crack
//    path (0.3544 kN/mm, tests/sent_notch.output) and s never decreases,
//    also not across a refinement.
// Run on 2 MPI ranks (1 rank gives the same output; the suite runs only
// the 2-rank case, the costlier check).
#include "tests.h"

using namespace dealii;

namespace
{
  std::string
  adaptive(const std::string &threshold_entry,
           const double       threshold,
           const unsigned int maximum_level)
  {
    return R"(
subsection Mesh
  subsection Adaptive refinement
    set Enabled = true
    set )" +
           threshold_entry + " = " + Utilities::to_string(threshold) + R"(
    set Maximum level = )" +
           std::to_string(maximum_level) + R"(
  end
end
)";
  }

  /// The uniaxial pull of the unit cube (fracture_bar's and plastic_box's
  /// scenes) with @p body_entries in Body 0.
  std::string
  cube_prm(const std::string &body_entries,
           const std::string &pull,
           const double       dt,
           const double       tolerance)
  {
    return Testing::unit_cube_prm(body_entries) +
           Testing::uniaxial_pull_prm(pull) + R"(
subsection Load stepping
  set End time  = 1
  set Time step = )" +
           Utilities::to_string(dt) + R"(
end
subsection Newton
  set Relative tolerance = )" +
           Utilities::to_string(tolerance) + R"(
end
subsection Output
  set Interval = 0
end
)";
  }

  const std::string cracking_body = R"(  set Fracture = true
  subsection Fracture
    set Critical energy release rate = 1.588e-5
    set Length scale                 = 1
  end
)";

  const std::string plastic_body = R"(  set Plasticity = true
  subsection Plasticity
    set Initial yield stress    = 0.005
    set Saturation yield stress = 0.006
    set Saturation exponent     = 25
    set Viscosity               = 1e-6
  end
)";

  /// Largest difference of the columns @p names of two runs, each
  /// relative to the largest magnitude in its column of @p a (the energies
  /// relative to the external work: the energy-balance residual is a small
  /// difference of large terms); infinity when the steps differ.
  double
  difference(const Testing::Table           &a,
             const Testing::Table           &b,
             const std::vector<std::string> &names)
  {
    if (a.at("time") != b.at("time"))
      return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (const std::string &name : names)
      {
        const bool energy = name.find("energy") != std::string::npos ||
                            name.find("work") != std::string::npos;
        double scale = 0;
        for (const double v : a.at(energy ? "external_work" : name))
          scale = std::max(scale, std::abs(v));
        for (unsigned int n = 0; n < a.at(name).size(); ++n)
          worst =
            std::max(worst, std::abs(a.at(name)[n] - b.at(name)[n]) / scale);
      }
    return worst;
  }

  double
  sum(const std::vector<double> &column)
  {
    double s = 0;
    for (const double v : column)
      s += v;
    return s;
  }

  /// Compares a run with refinement to one without and prints the result.
  void
  compare_homogeneous(std::ofstream                  &out,
                      const std::string              &what,
                      const std::string              &prm,
                      const std::string              &refinement,
                      const std::vector<std::string> &columns,
                      const std::string              &name)
  {
    const auto fixed = Testing::run_scene(prm, name + "_fixed");
    const auto adapted =
      Testing::run_scene(prm + refinement, name + "_adapted");
    const double worst = difference(fixed, adapted, columns);
    for (const std::string &c : columns)
      std::cout << what << ": " << c << " differs by "
                << difference(fixed, adapted, {c}) << std::endl;
    out << what << ": refined once (8 -> " << adapted.at("cells").back()
        << " cells, " << sum(adapted.at("refinements"))
        << " refinement), the same steps and "
        << "the same";
    for (const std::string &c : columns)
      out << " " << c;
    out << " as without refinement (1e-7): " << Testing::yes_no(worst < 1e-7)
        << std::endl;
    std::cout << what << ": largest difference " << worst << std::endl;
  }

  /// tests/sent_adaptive.prm on its mesh.
  std::string
  sent_prm()
  {
    return Testing::file_text(SOURCE_DIR "/sent_adaptive.prm") + R"(
subsection Mesh
  subsection Gmsh
    set File name = )" SOURCE_DIR R"(/meshes/sent_h2lf.msh
  end
end
subsection Output
  set Interval = 0
end
)";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  out << std::setprecision(4);

  compare_homogeneous(
    out,
    "cracking bar",
    cube_prm(cracking_body, "0.0025*t", 0.025, 1e-10),
    adaptive("Phase-field threshold", 0.05, 1),
    {"F1_x", "max_s", "external_work", "fracture_energy", "energy_residual"},
    "bar");
  compare_homogeneous(
    out,
    "cracking bar, Bernstein phase field",
    cube_prm(cracking_body, "0.0025*t", 0.025, 1e-10) + R"(
subsection Finite elements
  set Phase-field basis = Bernstein
end
)",
    adaptive("Phase-field threshold", 0.05, 1),
    {"F1_x", "max_s", "external_work", "fracture_energy", "energy_residual"},
    "bar_bernstein");
  compare_homogeneous(out,
                      "plastic box",
                      cube_prm(plastic_body, "0.02*t", 0.1, 1e-11),
                      adaptive("Hardening threshold", 1e-3, 1),
                      {"F1_x",
                       "max_alpha",
                       "external_work",
                       "plastic_work",
                       "hardening_energy",
                       "energy_residual"},
                      "box");

  // Notched tension from h = 2 l_f.
  const double thickness    = 2e-4; // m, the coarse mesh's one layer
  const auto   sent         = Testing::run_scene(sent_prm(), "sent_adaptive");
  unsigned int k            = 0;
  double       min_s_change = 0;
  for (unsigned int n = 0; n < sent.at("time").size(); ++n)
    {
      if (sent.at("F2_y")[n] > sent.at("F2_y")[k])
        k = n;
      min_s_change = std::min(min_s_change, sent.at("min_s_change")[n]);
    }
  const double peak = sent.at("F2_y")[k] / thickness * 1e-6;
  out << "notched tension from h = 2 l_f: F_max = " << peak
      << " kN/mm at u = " << sent.at("u2_y")[k] * 1e3 << " mm, refined "
      << sum(sent.at("refinements")) << " times to " << sent.at("cells").back()
      << " cells" << std::endl
      << "  F_max of the mesh with h = l_f along the path (0.3544 kN/mm, "
         "1 %): "
      << Testing::yes_no(std::abs(peak - 0.3544) < 0.01 * 0.3544) << std::endl
      << "  s never decreases at any DoF (1e-9): "
      << Testing::yes_no(min_s_change > -1e-9) << std::endl;
  std::cout << "sent: peak " << peak << " at step " << k << ", min s change "
            << min_s_change << ", dofs " << sent.at("dofs").back() << std::endl;
}
