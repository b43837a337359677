// Contact on refined meshes (hanging nodes on contact surfaces)
// and adaptive refinement in a contact scene.
//  - The contact patch test of contact_patch (non-matching swirled cubes,
//    symmetry planes through the contact surface, 1 MPa on top) with part
//    of the lower (master) cube's top layer refined once by Local
//    refinement boxes, so that the master surface has hanging nodes: with
//    the augmented Lagrangian and with semi-smooth Newton, the pressure
//    p / lambda_lat^2 at every slave node, the force p A_0 and the single
//    block's top displacement, as on the conforming meshes. The same with
//    part of the upper (slave) cube's bottom layer refined as well: with the
//    augmented Lagrangian each hanging slave node carries its own weighted
//    gap and multiplier, and its force goes to its parents through the
//    constraints; with semi-smooth Newton the hanging nodes hand their
//    aggregates to their parents (ContactProblem::fold_hanging_nodes()).
//  - The linearisation with hanging slave nodes (semi-smooth Newton): the
//    coarse block on the plate of contact_semi_smooth (mu_c = 0.2) with one
//    cell of the block's bottom refined; the condensed tangent against
//    central finite differences of the residual, with and without the
//    refinement, and the Newton iterations of the two runs. Measured:
//    what the checks can tell apart: the finite differences' floor is ~1e-5
//    (three mortar quadratures that agree to 1e-6: 4.5e-6 to 8.8e-6 without the
//    refinement, 6.2e-6 to 1.0e-5 with it), while a tangent without the
//    hanging nodes' terms through their positions errs by 1e-2 to 1e-1;
//    so the error must stay below 1e-4 (until then: 1e-3 and twice the
//    error without the refinement, which the floor's scatter crossed).
//    The Newton iterations follow the path of the stick/slip and active
//    sets: 15, 18 and 14 without the refinement and 15, 16 and 18 with it
//    for the three quadratures (19 with the broken tangent), so the
//    refined run may take 1.5 times as many: a check against divergence
//    and cutbacks, not of the linearisation.
//  - Adaptive refinement with contact: the patch with a plastic lower cube
//    (yield at 0.85 MPa, 1.125 MPa at the end) and Coulomb friction mu_c =
//    0.05,
//    refined where alpha > 1e-8, so the lower cube is refined once in the
//    step where it starts to yield and the step is solved again on the new
//    mesh; from then on the cubes expand differently and the interface
//    slips against friction. Until the refinement the state is homogeneous
//    and exact on either mesh, so the run must equal one on the refined
//    mesh from the start, step by step: that checks the contact state the
//    refinement carries (the positions of the last accepted step that the
//    slip increments start from).
// Run on 2 MPI ranks (1 rank gives the same output; the suite runs only
// the 2-rank case, the costlier check).
#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  const std::string semi_smooth = "  set Enforcement = semi-smooth Newton\n";
  const std::string augmented   = "  set Enforcement = augmented Lagrangian\n"
                                  "  set Penetration tolerance = 1e-8\n";

  std::string
  semi_smooth_pair()
  {
    return "\nsubsection Contact pair 1\n" + semi_smooth + "end\n";
  }

  std::string
  refinement_boxes(const std::string &boxes)
  {
    return "\nsubsection Mesh\n  set Local refinement boxes = " + boxes +
           "\nend\n";
  }

  /// The patch test with hanging nodes: prints its checks.
  void
  patch(std::ofstream     &out,
        const std::string &what,
        const std::string &boxes,
        const std::string &enforcement,
        const double       p_expected,
        const double       top_uz,
        const std::string &name)
  {
    const auto s =
      Testing::run_scene(Testing::contact_patch_prm(4, 3, enforcement) +
                           refinement_boxes(boxes),
                         name);
    const double p_max = s.at("contact1_max_pressure").back();
    const double p_min = s.at("contact1_min_pressure").back();
    const double force = s.at("contact1_force_z").back();
    const double uz    = s.at("u2_z").back();
    out << what << ":" << std::endl
        << "  pressure uniform, (max - min) / max < 1e-8: "
        << Testing::yes_no((p_max - p_min) / p_max < 1e-8) << std::endl
        << "  pressure = p / lambda_lat^2 of the single block (1e-8): "
        << Testing::yes_no(std::abs(p_max - p_expected) < 1e-8 * p_expected)
        << std::endl
        << "  contact force = p A_0 (1e-8): "
        << Testing::yes_no(std::abs(-force - 1e6) < 1e-2) << std::endl
        << "  top displacement = single block's (1e-8): "
        << Testing::yes_no(std::abs(uz - top_uz) < 1e-8 * std::abs(top_uz))
        << std::endl;
    std::cout << what << ": p " << p_min << " .. " << p_max << " (exact "
              << p_expected << "), force " << force << ", top u_z " << uz
              << " (single block " << top_uz << "), active nodes "
              << s.at("contact1_active_nodes").back() << ", Newton "
              << s.at("newton_iterations").back() << std::endl;
  }

  /// The coarse paper scene of contact_semi_smooth (block on plate, mu_c =
  /// 0.2, 3 steps), the tangent checked, with @p boxes refined. Each step
  /// starts from the last state (constant predictor): with the shipped
  /// linear one the unrefined run takes one iteration per step after the
  /// first, and the refined one two: the first residual of a step is
  /// 9.5e-3 N refined and 1.5e-3 N unrefined, on either side of the
  /// absolute tolerance, the second far below (5e-6, 1e-6 N); that is the
  /// extrapolation's accuracy on the two meshes, not the linearisation
  /// this test is about.
  std::string
  block_on_plate_prm(const std::string &boxes)
  {
    std::string prm = Testing::shipped_scene("two_bodies.prm");
    for (const auto &[from, to] :
         {std::pair<std::string, std::string>{"19, 13, 2", "10, 7, 1"},
          {"5, 5, 5", "3, 3, 3"},
          {"End time  = 113", "End time  = 3"},
          {"Predictor = linear", "Predictor = constant"}})
      prm.replace(prm.find(from), from.size(), to);
    return prm + semi_smooth_pair() + R"(
subsection Newton
  set Check tangent = true
end
subsection Output
  set Interval = 0
end
)" + refinement_boxes(boxes);
  }

  /// Largest tangent error and total Newton iterations of a run.
  std::pair<double, double>
  tangent_quality(const Testing::Table &s)
  {
    double tangent_error = 0., newton = 0.;
    for (std::size_t n = 1; n < s.at("time").size(); ++n)
      {
        tangent_error = std::max(tangent_error, s.at("tangent_error")[n]);
        newton += s.at("newton_iterations")[n];
      }
    return {tangent_error, newton};
  }

  /// The plastic lower cube with friction, loaded in five steps.
  std::string
  plastic_patch_prm()
  {
    return Testing::contact_patch_prm(
             4, 3, semi_smooth + "  set Friction coefficient = 0.05\n") +
           R"(
subsection Body 1
  set Plasticity = true
  subsection Plasticity
    set Initial yield stress    = 0.85e6
    set Saturation yield stress = 1.5e6
    set Saturation exponent     = 25
    set Viscosity               = 1e6
  end
end
subsection Newton
  set Relative tolerance = 1e-10
end
subsection Load stepping
  set End time  = 1.125
  set Time step = 0.25
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

  const auto block =
    Testing::run_scene(Testing::contact_patch_single_block_prm(),
                       "single_block");
  const double top_uz     = block.at("u5_z").back();
  const double lateral    = 1. + 2. * block.at("u5_x").back();
  const double p_expected = 1e6 / (lateral * lateral);

  // Cells of the lower cube's top layer near x = y = 0; of the upper
  // cube's bottom layer.
  const std::string master_box = "0, 0, 0.6 : 0.6, 0.6, 1 : 1";
  const std::string slave_box  = "0, 0, 1 : 0.55, 0.55, 1.3 : 1";
  patch(out,
        "refined master, augmented Lagrangian",
        master_box,
        augmented,
        p_expected,
        top_uz,
        "master_al");
  patch(out,
        "refined master, semi-smooth Newton",
        master_box,
        semi_smooth,
        p_expected,
        top_uz,
        "master_ssn");
  patch(out,
        "refined slave and master, augmented Lagrangian",
        master_box + "; " + slave_box,
        augmented,
        p_expected,
        top_uz,
        "slave_al");
  patch(out,
        "refined slave and master, semi-smooth Newton",
        master_box + "; " + slave_box,
        semi_smooth,
        p_expected,
        top_uz,
        "slave_ssn");

  {
    // One cell of the block's bottom layer refined.
    const auto plain = tangent_quality(
      Testing::run_scene(block_on_plate_prm(""), "block_on_plate"));
    const auto s =
      Testing::run_scene(block_on_plate_prm(
                           "0.015, 0.08, 0.02 : 0.035, 0.1, 0.03 : 1"),
                         "block_on_plate_refined");
    const auto        refined = tangent_quality(s);
    const std::size_t last    = s.at("time").size() - 1;
    std::cout << "block on plate: tangent error " << plain.first << " and "
              << refined.first << " with hanging slave nodes; Newton "
              << plain.second << " and " << refined.second << "; sticking "
              << s.at("contact1_sticking_nodes")[last] << ", slipping "
              << s.at("contact1_slipping_nodes")[last] << std::endl;
    out << "block on plate with hanging slave nodes, semi-smooth Newton, mu_c "
           "= 0.2:"
        << std::endl
        << "  condensed tangent = finite differences of the residual "
           "(1e-4 at the last update of each step, as without the "
           "refinement): "
        << Testing::yes_no(refined.first < 1e-4 && plain.first < 1e-4)
        << std::endl
        << "  Newton iterations of the 3 steps at most 1.5 times those "
           "without the refinement: "
        << Testing::yes_no(refined.second <= 1.5 * plain.second) << std::endl;
  }

  // Adaptive refinement against the refined mesh from the start.
  const auto adaptive = [](const std::string &threshold) {
    return R"(
subsection Mesh
  subsection Adaptive refinement
    set Enabled             = true
    set Hardening threshold = )" +
           threshold + R"(
    set Maximum level       = 1
  end
end
)";
  };
  const auto fixed =
    Testing::run_scene(plastic_patch_prm() +
                         refinement_boxes("0, 0, 0 : 1, 1, 1 : 1") +
                         adaptive("1e30"),
                       "plastic_fixed");
  const auto adapted =
    Testing::run_scene(plastic_patch_prm() + adaptive("1e-8"),
                       "plastic_adapted");
  unsigned int refined_step = 0;
  for (unsigned int n = 0; n < adapted.at("refinements").size(); ++n)
    if (adapted.at("refinements")[n] > 0 && refined_step == 0)
      refined_step = adapted.at("step")[n];
  const std::vector<std::string> columns = {"u2_z",
                                            "contact1_force_z",
                                            "contact1_friction_x",
                                            "contact1_dissipation",
                                            "contact1_max_pressure",
                                            "contact1_min_pressure",
                                            "contact1_max_slip",
                                            "max_alpha",
                                            "plastic_work",
                                            "external_work"};
  double                         worst   = 0;
  for (const std::string &c : columns)
    {
      const double d = Testing::column_difference(fixed, adapted, c);
      std::cout << "adaptive: " << c << " differs by " << d << std::endl;
      worst = std::max(worst, d);
    }
  double largest_slip = 0;
  for (const double v : fixed.at("contact1_max_slip"))
    largest_slip = std::max(largest_slip, v);
  out << "adaptive refinement with frictional contact:" << std::endl
      << "  refined in the first plastic step (step 4): "
      << Testing::yes_no(refined_step == 4) << ", cells "
      << adapted.at("cells").front() << " -> " << adapted.at("cells").back()
      << " (the refined mesh from the start: " << fixed.at("cells").back()
      << ")" << std::endl
      << "  the interface slips afterwards (max slip > 1e-6 m): "
      << Testing::yes_no(largest_slip > 1e-6) << std::endl
      << "  every step equals the run on the refined mesh (1e-7 of each "
         "column's scale): "
      << Testing::yes_no(worst < 1e-7) << std::endl;
  // The number of steps depends on cut-backs, which round-off can decide.
  std::cout << "adaptive: largest difference " << worst << ", largest slip "
            << largest_slip << ", " << adapted.at("step").back() << " steps"
            << std::endl;
}
