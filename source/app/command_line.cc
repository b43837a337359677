#include <deal.II/base/parameter_handler.h>

#include <ductile_contact/app/command_line.h>
#include <ductile_contact/app/run_parameters.h>
#include <ductile_contact/app/version.h>
#include <ductile_contact/core/types.h>

#include <filesystem>
#include <iostream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    const char *usage =
      "Usage: ductile-contact [--validate] [--print-parameters[=FORMAT]] "
      "[--resume] [--set \"Subsection/Entry = value\"]... FILE.prm\n"
      "       mpirun -np N ductile-contact [--resume] [--set ...] FILE.prm\n"
      "       ductile-contact --version\n"
      "  --set               override one entry of FILE.prm, e.g. --set "
      "\"Body 0/Fracture/Critical energy release rate = 75e3\" (repeatable; "
      "applied after the file, in order; recorded in input.prm and "
      "parameters.prm of the results)\n"
      "  --version           print the version, git revision, deal.II "
      "version and build type, and exit\n"
      "  --resume            continue from the newest complete checkpoint in "
      "the output directory of FILE.prm (Checkpoint/Interval), on any "
      "number of ranks; FILE.prm may change the end time, output, solver "
      "and Newton settings, not the mesh, bodies or contact pairs\n"
      "  --validate          parse and check FILE.prm (and its scene), then "
      "exit: 0 if valid\n"
      "  --print-parameters  print every entry with its documentation and "
      "its default (the values of FILE.prm if given) as a .prm file and "
      "exit; FORMAT = prm (default), description (with the allowed values) "
      "or json (for scripts: value, default, pattern, documentation)\n";

    /// The format of --print-parameters[=FORMAT]; nothing if unknown.
    std::optional<ParameterHandler::OutputStyle>
    print_style(const std::string &arg)
    {
      const std::string format =
        arg.size() > 18 && arg[18] == '=' ? arg.substr(19) : "prm";
      if (format == "prm")
        return ParameterHandler::PRM;
      if (format == "description")
        return ParameterHandler::Description;
      if (format == "json")
        return ParameterHandler::JSON;
      return std::nullopt;
    }
  } // namespace



  /// The options and the input file; help and errors (with the usage)
  /// printed on the root rank.
  CommandLine
  parse_command_line(int argc, char **argv, const bool root)
  {
    CommandLine line;
    const auto  fail = [&](const std::string &message) {
      if (root)
        std::cerr << "Error: " << message << "\n" << usage;
      line.exit_code = 1;
      return line;
    };
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--validate")
          line.validate = true;
        else if (arg == "--resume")
          line.resume = true;
        else if (arg.rfind("--print-parameters", 0) == 0)
          {
            line.print_parameters = true;
            const auto style      = print_style(arg);
            if (!style)
              return fail("unknown format '" + arg.substr(19) +
                          "' of --print-parameters (prm, description or "
                          "json)");
            line.style = *style;
          }
        else if (arg == "--set" || arg.rfind("--set=", 0) == 0)
          {
            if (arg == "--set" && i + 1 >= argc)
              return fail("--set needs an argument \"Subsection/Entry = "
                          "value\"");
            line.overrides.push_back(arg == "--set" ? argv[++i]
                                                    : arg.substr(6));
          }
        else if (arg == "--version")
          {
            if (root)
              std::cout << version_line() << std::endl;
            line.exit_code = 0;
            return line;
          }
        else if (arg == "-h" || arg == "--help")
          {
            if (root)
              std::cout << usage;
            line.exit_code = 0;
            return line;
          }
        else if (!arg.empty() && arg[0] == '-')
          return fail("unknown option '" + arg + "'");
        else if (line.file_name.empty())
          line.file_name = arg;
        else
          return fail("more than one input file given ('" + line.file_name +
                      "', '" + arg + "')");
      }
    if (line.file_name.empty() && !line.print_parameters)
      return fail("no input file given");
    return line;
  }



  std::optional<std::string>
  program_for_dimension(int argc, char **argv)
  {
    const CommandLine line = parse_command_line(argc, argv, false);
    if (line.exit_code || line.file_name.empty())
      return std::nullopt;
    const std::optional<unsigned int> wanted =
      input_dimension(line.file_name, line.overrides);
    if (!wanted || *wanted == dim)
      return std::nullopt;
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path  self = fs::read_symlink("/proc/self/exe", error);
    const fs::path  folder =
      error ? fs::path(argv[0]).parent_path() : self.parent_path();
    return (folder / (*wanted == 2 ? "ductile-contact-2d" : "ductile-contact"))
      .string();
  }
} // namespace DuctileContact
