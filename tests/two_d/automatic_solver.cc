// Linear solver/Type = automatic: the direct solver up to `Direct solver
// limit` unknowns, gmres-amg above. The rule itself: the default limits of
// the two dimensions, and the type picked at the limit and one unknown above
// it. Then the plane-strain paper scene (prm/block_on_strip_2d.prm, 1022
// unknowns, contact with friction, plasticity, the phase field; 3 steps to
// 3 mm) with Type = automatic under the default limit and under a limit of
// 1000 unknowns: the log must name the direct solver in the first run and
// gmres-amg in the second, and both runs must give the reaction (to 1e-6 of
// itself) and W_ext and the friction dissipation (to 1e-6 of W_ext) of the
// run with Type = direct at every step. On 1 and 2 MPI ranks with identical
// output.
#include "../tests.h"

#include <cmath>
#include <sstream>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// The scene with the entries @p entries of `Linear solver`; @p log
  /// receives its screen.
  Testing::Table
  run(const std::string &entries,
      const std::string &directory,
      std::ostream      &log)
  {
    const std::string prm = Testing::shipped_scene("block_on_strip_2d.prm") +
                            R"(
subsection Load stepping
  set End time  = 3
  set Time step = 1
end
subsection Output
  set Interval = 0
end
subsection Linear solver
)" + entries + R"(
end
)";
    return Testing::run_scene(prm, directory, log);
  }

  /// The text after "Linear solver: " in the log, up to the line's end.
  std::string
  chosen(const std::string &log)
  {
    const std::string key   = "Linear solver: ";
    const std::size_t begin = log.find(key);
    if (begin == std::string::npos)
      return "(none)";
    const std::size_t end = log.find('\n', begin);
    return log.substr(begin + key.size(), end - begin - key.size());
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();

  const auto &names = linear_solver_type_names();
  for (const unsigned int d : {2u, 3u})
    {
      LinearSolverParameters p(d);
      out << d << "-D: Type " << name_of(names, p.type) << ", limit "
          << p.direct_limit << " unknowns; at the limit "
          << name_of(names, p.resolved_type(p.direct_limit))
          << ", one above it "
          << name_of(names, p.resolved_type(p.direct_limit + 1)) << "\n";
    }

  std::ostringstream   ignored;
  const Testing::Table direct = run("  set Type = direct\n", "direct", ignored);
  for (const std::string limit : {"", "1000"})
    {
      std::ostringstream   log;
      const Testing::Table t =
        run("  set Type = automatic\n" +
              (limit.empty() ? std::string()
                             : "  set Direct solver limit = " + limit + "\n"),
            "automatic" + limit,
            log);
      const double worst = Testing::stepwise_difference(
        t, direct, "F2_y", {"external_work", "contact1_dissipation"});
      out << "automatic, limit " << (limit.empty() ? "default" : limit) << ": "
          << chosen(log.str()) << "; every step as Type = direct to 1e-6: "
          << Testing::yes_no(worst < 1e-6) << "\n";
      std::cout << "limit " << limit << ": worst relative difference " << worst
                << std::endl;
    }
  const std::size_t last = direct.at("time").size() - 1;
  out << std::setprecision(5) << "at 3 mm: F2_y " << direct.at("F2_y")[last]
      << " N/m, W_ext " << direct.at("external_work")[last] << " J/m\n";
}
