// Load stepping/Predictor on a homogeneous bar that cracks (unit cube, 2x2x2
// Q2 cells, symmetry planes, pulled on x = 1, as tests/fracture_bar, with a
// small crack viscosity): s grows from zero through the peak (t = 0.4)
// until the pull stops at t = 0.6; held there, s relaxes viscously towards
// its equilibrium, each increment about 0.29 times the last.
//  - 'linear', 'linear displacements' and 'best linear' give the same
//    curve (the converged states do not depend on the first guess);
//  - 'best linear' chooses among the first guesses of the two others: at
//    every step where they are far from Newton's tolerances (merit above
//    100; the runs' converged states differ within those tolerances, which
//    moves a merit near 1 by up to 1 %), its two merits are those that Newton's
//    first iteration sees in the runs with 'linear' and 'linear displacements'
//    (the same states to the solver tolerance), so the guesses are those two;
//  - Newton then starts from the guess with the smaller merit: its first
//    iteration shows that merit;
//  - each guess is chosen by a clear margin (a merit 10 % below the
//    other's, both far from Newton's tolerances) in some step: the
//    extrapolation of s helps while s grows with the pull; while it relaxes
//    at the hold (increments shrinking faster than by half per step), the
//    last increment overshoots by more than keeping s misses.
// A bound engaged at the start of every step: a homogeneous plastic box
// (tests/plastic_box) with Plasticity/Loading condition = bound, whose
// bound alpha_n <= alpha holds from the first iteration. 'best linear'
// evaluates its first guesses before any tangent of the step, with the
// bound's rows made afresh; it gives the curve of 'linear'.
#include "tests.h"

using namespace dealii;
using namespace DuctileContact;

namespace
{
  const double mu = 1., kappa = 2.5;
  const double E = 9. * kappa * mu / (3. * kappa + mu);
  // g_c such that the peak strain is 1e-3 (tests/fracture_bar).
  const double g_c = 6. * E * 1e-6;

  std::string
  bar_prm(const std::string &predictor)
  {
    return Testing::unit_cube_prm(R"(  set Fracture      = true
  subsection Fracture
    set Critical energy release rate = )" +
                                  Utilities::to_string(g_c, 16) + R"(
    set Length scale                 = 1
    set Viscosity                    = 1.4e-7
  end
)") + Testing::uniaxial_pull_prm("0.0025*min(t, 0.6)") +
           R"(
subsection Coupling
  set Strategy        = monolithic
  set Irreversibility = history and bound
end
subsection Load stepping
  set End time  = 1
  set Time step = 0.025
  set Predictor = )" +
           predictor + R"(
end
subsection Newton
  set Relative tolerance = 1e-10
end
subsection Output
  set Interval  = 0
  set Verbosity = 2
end
)";
  }

  /// What the verbose screen of a run shows per step (rank 0; empty
  /// elsewhere): the merit of Newton's first iteration, and for 'best
  /// linear' the merits of the two guesses and the one chosen.
  struct Starts
  {
    std::vector<double>                newton_0;
    std::vector<std::array<double, 2>> guesses;
    std::vector<unsigned int>          chosen;
  };

  /// sqrt(sum of squares) of the numbers after the block names of "in
  /// tolerances: u a s b" up to the next ';' or ',' (the merit, to the 4
  /// digits printed).
  double
  merit_of(const std::string &line)
  {
    std::string blocks = line.substr(line.find("in tolerances:") + 14);
    blocks             = blocks.substr(0, blocks.find_first_of(";,"));
    std::istringstream in(blocks);
    double             sum = 0.;
    for (std::string name, value; in >> name >> value;)
      sum += std::stod(value) * std::stod(value);
    return std::sqrt(sum);
  }

  /// The plastic box of tests/plastic_box with the alpha bound.
  std::string
  plastic_box_prm(const std::string &predictor)
  {
    return Testing::unit_cube_prm(R"(  set Plasticity    = true
  subsection Plasticity
    set Initial yield stress    = 0.005
    set Saturation yield stress = 0.006
    set Saturation exponent     = 25
    set Viscosity               = 1e-6
    set Loading condition       = bound
  end
)") + Testing::uniaxial_pull_prm("0.02*t") +
           R"(
subsection Load stepping
  set End time  = 1
  set Time step = 0.1
  set Predictor = )" +
           predictor + R"(
end
subsection Newton
  set Relative tolerance = 1e-11
end
subsection Output
  set Interval = 0
end
)";
  }

  std::pair<Testing::Table, Starts>
  run(const std::string &predictor, const std::string &directory)
  {
    std::ostringstream screen;
    const auto         table =
      Testing::run_scene(bar_prm(predictor), directory, screen);
    Starts             starts;
    std::istringstream lines(screen.str());
    for (std::string line; std::getline(lines, line);)
      if (line.find("first guesses: merits ") != std::string::npos)
        {
          std::istringstream    in(line.substr(line.find("merits ") + 7));
          std::array<double, 2> m;
          char                  comma;
          std::string           rest;
          unsigned int          k;
          in >> m[0] >> comma >> m[1] >> rest >> rest >> rest >> rest >> k;
          starts.guesses.push_back(m);
          starts.chosen.push_back(k);
        }
      else if (line.find("Newton  0:") != std::string::npos)
        starts.newton_0.push_back(merit_of(line));
    return {table, starts};
  }

  bool
  close(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const auto [linear, starts_linear] = run("linear", "linear");
  const auto [displ, starts_displ]   = run("linear displacements", "displ");
  const auto [best, starts_best]     = run("best linear", "best");

  bool same_steps = linear.at("time") == displ.at("time") &&
                    linear.at("time") == best.at("time");
  double worst = 0., peak = 0.;
  for (const double f : linear.at("F1_x"))
    peak = std::max(peak, f);
  for (unsigned int n = 0; same_steps && n < linear.at("time").size(); ++n)
    for (const auto *other : {&displ, &best})
      worst =
        std::max({worst,
                  std::abs(other->at("F1_x")[n] - linear.at("F1_x")[n]) / peak,
                  std::abs(other->at("max_s")[n] - linear.at("max_s")[n])});
  out << "the three predictors give the same curve (same steps, force and s "
         "to 1e-6): "
      << Testing::yes_no(same_steps && worst < 1e-6) << std::endl;
  out << "largest s at the end = " << linear.at("max_s").back() << std::endl;

  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      // Step 1 has no last increment: no choice, one Newton 0 line more.
      const auto  &g     = starts_best.guesses;
      const size_t n     = g.size();
      bool         sizes = n + 1 == starts_best.newton_0.size() &&
                   n + 1 == starts_linear.newton_0.size() &&
                   n + 1 == starts_displ.newton_0.size();
      bool         guesses_match = sizes, starts_match = sizes;
      unsigned int first = 0, second = 0;
      for (unsigned int k = 0; sizes && k < n; ++k)
        {
          // Newton 0 prints 4 digits; the guesses' merits 6.
          const bool far = std::min(g[k][0], g[k][1]) > 100.;
          if (far)
            guesses_match =
              guesses_match &&
              close(g[k][0], starts_linear.newton_0[k + 1], 2e-3) &&
              close(g[k][1], starts_displ.newton_0[k + 1], 2e-3);
          const unsigned int c     = starts_best.chosen[k];
          const double       other = g[k][c == 1 ? 1 : 0];
          starts_match             = starts_match && (c == 1 || c == 2) &&
                         g[k][c - 1] <= other * (1. + 1e-5) &&
                         close(g[k][c - 1], starts_best.newton_0[k + 1], 2e-3);
          if (far && g[k][c - 1] < 0.9 * other)
            (c == 1 ? first : second) += 1;
          std::cout << "step " << k + 2 << ": merits " << g[k][0] << ", "
                    << g[k][1] << "; linear " << starts_linear.newton_0[k + 1]
                    << ", displacements " << starts_displ.newton_0[k + 1]
                    << "; chosen " << c << std::endl;
        }
      out << "best linear's guesses are those of 'linear' and 'linear "
             "displacements' (merits to 0.2 %): "
          << Testing::yes_no(guesses_match) << std::endl;
      out << "Newton starts from the guess with the smaller merit: "
          << Testing::yes_no(starts_match) << std::endl;
      out << "each guess is chosen by a clear margin in some step: "
          << Testing::yes_no(first > 0 && second > 0) << std::endl;
    }

  const auto plastic_linear =
    Testing::run_scene(plastic_box_prm("linear"), "plastic_linear");
  const auto plastic_best =
    Testing::run_scene(plastic_box_prm("best linear"), "plastic_best");
  bool   plastic_same  = plastic_linear.at("time") == plastic_best.at("time");
  double plastic_worst = 0.;
  const double end_reaction = plastic_linear.at("F1_x").back();
  for (unsigned int n = 0; plastic_same && n < plastic_linear.at("time").size();
       ++n)
    plastic_worst = std::max(plastic_worst,
                             std::abs(plastic_best.at("F1_x")[n] -
                                      plastic_linear.at("F1_x")[n]) /
                               std::abs(end_reaction));
  out << "plastic box with the alpha bound: 'best linear' reaches the end "
         "with the curve of 'linear' (same steps, force to 1e-6): "
      << Testing::yes_no(plastic_same && plastic_worst < 1e-6 &&
                         plastic_best.at("time").back() > 1. - 1e-12)
      << std::endl;
  out << "  end reaction " << std::setprecision(5) << end_reaction
      << ", largest alpha " << plastic_linear.at("max_alpha").back()
      << std::endl;
}
