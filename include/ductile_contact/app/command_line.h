#pragma once

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>
#include <vector>

namespace DuctileContact
{
  /// What the command line asks for.
  struct CommandLine
  {
    bool        validate = false, print_parameters = false;
    bool        resume = false;
    std::string file_name;
    /// The --set overrides, "Subsection/Entry = value", in order.
    std::vector<std::string>              overrides;
    dealii::ParameterHandler::OutputStyle style = dealii::ParameterHandler::PRM;
    /// Set when the command line is answered without reading an input
    /// file (help, a bad option): the exit code.
    std::optional<int> exit_code;
  };

  /// The options and the input file of `ductile-contact [options] FILE.prm`;
  /// help and errors (with the usage) printed when @p root.
  CommandLine
  parse_command_line(int argc, char **argv, const bool root);

  /**
   * The program of the other build, when the input of the command line
   * asks for the dimension that this build is not: `Dimension` of the file
   * and its --set overrides, read before anything else. The 3-D build is
   * `ductile-contact`, the plane-strain build `ductile-contact-2d`, side by
   * side in one folder. Nothing when this build serves the input, and when
   * the command line or the file cannot be read (this build then reports
   * the error).
   */
  std::optional<std::string>
  program_for_dimension(int argc, char **argv);
} // namespace DuctileContact
