#include <ductile_contact/core/input_error.h>
#include <ductile_contact/output/output_parameters.h>

namespace DuctileContact
{
  using namespace dealii;

  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.add_parameter(
      "Directory",
      directory,
      "Folder for results: solution-NNNNN.pvtu, solution.pvd, statistics, "
      "log.txt, input.prm (copy of the input) and parameters.prm (every "
      "entry as used). Created if missing.",
      Patterns::Anything());
    prm.add_parameter("Interval",
                      interval,
                      "Write graphical output every this many accepted load "
                      "steps (the last step is always written); 0: never.",
                      Patterns::Integer(0));
    prm.add_parameter("Verbosity",
                      verbosity,
                      "0: quiet; 1: one line per load step; 2: also the "
                      "Newton residuals and linear iterations.",
                      Patterns::Integer(0, 2));
    prm.leave_subsection();
  }



  void
  OutputParameters::check() const
  {
    check_input(!directory.empty(),
                "Output/Directory",
                directory,
                "it must name a folder");
  }
} // namespace DuctileContact
