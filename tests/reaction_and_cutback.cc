// Equilibrium, load-step control and energy bookkeeping of the finite-strain
// solver (neo-Hooke, mu = 1, kappa = 3):
//  A. a column [0,1]x[0,1]x[0,2] clamped at its base (id 4) with a dead-load
//     traction T = (0.05, 0.02, 0.1) on its top (id 5): the force through the
//     top equals T A and the base reaction equals -T A (1e-8 relative);
//  B. the column clamped at the base, its top moved by (0.3, 0, -0.5): one
//     load step with at most 4 Newton iterations must fail and be cut back;
//     the final forces must equal those of a 10-step run (hyperelasticity is
//     path independent), Newton must converge at a rate > 1.6 in each step,
//     and the energy-balance residual W_ext - Psi must shrink like dt^2
//     (ratio > 3 when the step is halved);
//  C. the step controller after a cut-back when no step is easy (Easy step
//     Newton iterations = 1): with Growth after accepted steps = 2 the
//     increment grows, each time after two accepted steps at it; with 0 it
//     never grows again;
//  D. prescribed values that the linear predictor reaches up to round-off
//     count as reached: with the top moved linearly in t, only the first
//     step (no predictor yet) starts with its Dirichlet data pending, so
//     that no later first update is taken without the line search's test;
//     with the constant predictor every step starts with them pending.
#include "tests.h"

#include <cmath>

using namespace dealii;

namespace
{
  std::string
  column(const std::string &top_bc, const std::string &stepping)
  {
    return R"(
subsection Mesh
  set Scene = box
  subsection Box
    set Upper corner = 1, 1, 2
    set Subdivisions = 2, 2, 4
  end
end
subsection Body 0
  set Shear modulus = 1
  set Bulk modulus  = 3
end
subsection Boundary conditions
  set Boundary ids = 4, 5
end
subsection Boundary 4
  set Constrained components = x, y, z
end
subsection Linear solver
  set Type = direct
end
subsection Output
  set Interval = 0
end
)" + top_bc +
           stepping;
  }

  /// Runs the scene and returns how many Newton iterations 0 began with
  /// Dirichlet data pending and how many there were (Verbosity = 2 lines of
  /// the screen, on rank 0; zero elsewhere).
  std::pair<unsigned int, unsigned int>
  pending_starts(const std::string &prm, const std::string &directory)
  {
    std::ostringstream screen;
    Testing::run_scene(prm + "\nsubsection Output\n  set Verbosity = 2\nend\n",
                       directory,
                       screen);
    std::istringstream lines(screen.str());
    unsigned int       pending = 0, starts = 0;
    for (std::string line; std::getline(lines, line);)
      if (line.find("Newton  0:") != std::string::npos)
        {
          ++starts;
          pending +=
            line.find("Dirichlet data pending") != std::string::npos ? 1 : 0;
        }
    return {pending, starts};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  // A. Traction.
  {
    const auto t = Testing::run_scene(
      column(
        "subsection Boundary 5\n  set Traction = 0.05*t; 0.02*t; 0.1*t\nend\n",
        "subsection Load stepping\n  set Time step = 0.5\nend\n"
        "subsection Newton\n  set Relative tolerance = 1e-12\nend\n"),
      "traction");
    const double T[3]  = {0.05, 0.02, 0.1};
    const char  *xyz[] = {"x", "y", "z"};
    double       worst = 0;
    for (unsigned int d = 0; d < 3; ++d)
      {
        worst =
          std::max(worst,
                   std::abs(t.at(std::string("F5_") + xyz[d]).back() - T[d]));
        worst =
          std::max(worst,
                   std::abs(t.at(std::string("F4_") + xyz[d]).back() + T[d]));
        out << "mean top displacement " << xyz[d] << " = "
            << t.at(std::string("u5_") + xyz[d]).back() << std::endl;
      }
    out << "top force = T A and base reaction = -T A (1e-8): "
        << Testing::yes_no(worst < 1e-8 * 0.1) << std::endl;
  }

  // B. Cut-back, path independence, Newton rate, energy balance.
  {
    const std::string top =
      "subsection Boundary 5\n  set Constrained components = x, y, z\n"
      "  set Displacement = 0.3*t; 0; -0.5*t\nend\n";
    const auto stepping = [](const double dt, const unsigned int max_it) {
      return "subsection Load stepping\n  set Time step = " +
             std::to_string(dt) +
             "\n  set Growth factor = 1\nend\nsubsection Newton\n"
             "  set Relative tolerance = 1e-11\n  set Maximum iterations = " +
             std::to_string(max_it) + "\nend\n";
    };
    const auto one =
      Testing::run_scene(column(top, stepping(1., 4)), "one_step");
    const auto ten =
      Testing::run_scene(column(top, stepping(0.1, 15)), "ten_steps");
    const auto twenty =
      Testing::run_scene(column(top, stepping(0.05, 15)), "twenty_steps");

    double cutbacks = 0;
    for (const double c : one.at("cutbacks"))
      cutbacks += c;
    out << "single step was cut back: " << Testing::yes_no(cutbacks > 0)
        << std::endl;

    double worst = 0;
    for (const std::string c : {"F5_x", "F5_y", "F5_z"})
      worst =
        std::max(worst,
                 Testing::relative_error(one.at(c).back(),
                                         ten.at(c).back(),
                                         std::abs(ten.at("F5_z").back())));
    out << "top force after the load path = " << ten.at("F5_x").back() << ", "
        << ten.at("F5_z").back() << std::endl;
    out << "cut-back run ends in the same state (1e-8): "
        << Testing::yes_no(worst < 1e-8) << std::endl;

    // The rate is undefined (nan) when Newton reaches round-off before three
    // residuals above it exist (most steps of the 20-step run); it must be
    // defined in most steps of the 10-step run and > 1.6 wherever defined.
    bool quadratic = true;
    for (const auto *table : {&ten, &twenty})
      for (std::size_t i = 1; i < table->at("newton_rate").size(); ++i)
        if (table->at("newton_rate")[i] > 0.)
          quadratic = quadratic && table->at("newton_rate")[i] > 1.6;
    unsigned int defined = 0;
    for (const double rate : ten.at("newton_rate"))
      defined += std::isfinite(rate) ? 1 : 0;
    out << "Newton rate > 1.6 in every step: "
        << Testing::yes_no(quadratic && 2 * defined > ten.at("step").size())
        << std::endl;
    const double r10 = std::abs(ten.at("energy_residual").back());
    const double r20 = std::abs(twenty.at("energy_residual").back());
    out << "stored energy = " << ten.at("stored_energy").back() << std::endl;
    out << "energy residual shrinks like dt^2 (ratio > 3): "
        << Testing::yes_no(r10 / r20 > 3.) << std::endl;
    std::cout << "energy residuals " << r10 << " " << r20 << std::endl;
  }

  // C. Growth after a run of accepted (not easy) steps.
  {
    const std::string top =
      "subsection Boundary 5\n  set Constrained components = x, y, z\n"
      "  set Displacement = 0.3*sqrt(t); 0; -0.5*sqrt(t)\nend\n";
    const auto stepping = [](const unsigned int run) {
      return "subsection Load stepping\n  set Time step = 1\n"
             "  set Growth factor = 2\n  set Easy step Newton iterations = 1\n"
             "  set Growth after accepted steps = " +
             std::to_string(run) +
             "\nend\nsubsection Newton\n  set Relative tolerance = 1e-11\n"
             "  set Maximum iterations = 3\nend\n";
    };
    const auto grows = Testing::run_scene(column(top, stepping(2)), "run2");
    const auto stays = Testing::run_scene(column(top, stepping(0)), "run0");

    // Accepted increments (row 0 is the initial state).
    const auto increments = [](const Testing::Table &t) {
      return std::vector<double>(t.at("dt").begin() + 1, t.at("dt").end());
    };
    const std::vector<double> dt2      = increments(grows);
    const std::vector<double> dt0      = increments(stays);
    double                    cutbacks = 0, easy = 0;
    for (const auto *t : {&grows, &stays})
      for (std::size_t i = 1; i < t->at("step").size(); ++i)
        {
          cutbacks += t->at("cutbacks")[i];
          easy += t->at("newton_iterations")[i] <= 1 ? 1 : 0;
        }
    out << "both runs were cut back and had no easy step: "
        << Testing::yes_no(cutbacks > 0 && easy == 0) << std::endl;
    unsigned int growths   = 0;
    bool         after_two = true;
    for (std::size_t i = 1; i < dt2.size(); ++i)
      if (dt2[i] > dt2[i - 1])
        {
          ++growths;
          after_two = after_two && i >= 2 && dt2[i - 1] == dt2[i - 2];
        }
    out << "Growth after accepted steps = 2: the increment grows, each time "
           "after two steps at it: "
        << Testing::yes_no(growths > 0 && after_two) << std::endl;
    bool never = true;
    for (std::size_t i = 1; i < dt0.size(); ++i)
      never = never && dt0[i] <= dt0[i - 1];
    out << "Growth after accepted steps = 0: it never grows: "
        << Testing::yes_no(never) << std::endl;
    out << "both end in the same state (1e-8): "
        << Testing::yes_no(
             Testing::relative_error(grows.at("F5_z").back(),
                                     stays.at("F5_z").back(),
                                     std::abs(stays.at("F5_z").back())) < 1e-8)
        << std::endl;
  }

  // D. Pending prescribed values: genuine ones only.
  {
    const std::string top =
      "subsection Boundary 5\n  set Constrained components = x, y, z\n"
      "  set Displacement = 0.03*t; 0.01*t; -0.05*t\nend\n";
    const auto stepping = [](const std::string &predictor) {
      return "subsection Load stepping\n  set Time step = 0.1\n"
             "  set End time = 0.7\n  set Predictor = " +
             predictor +
             "\nend\nsubsection Newton\n  set Relative tolerance = "
             "1e-11\nend\n";
    };
    const auto linear =
      pending_starts(column(top, stepping("linear")), "pending_linear");
    const auto constant =
      pending_starts(column(top, stepping("constant")), "pending_constant");
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "steps starting with data pending: linear predictor "
                << linear.first << " of " << linear.second
                << ", constant predictor " << constant.first << " of "
                << constant.second << std::endl;
    out << "linear predictor: data pending at the start of step 1 only: "
        << Testing::yes_no(linear.first == 1 && linear.second == 7)
        << std::endl;
    out << "constant predictor: at the start of every step: "
        << Testing::yes_no(constant.first == 7 && constant.second == 7)
        << std::endl;
  }
}
