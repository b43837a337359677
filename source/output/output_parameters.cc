#include <ductile_contact/core/expression.h>
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
      "Folder for results: the field output (see Format), statistics, "
      "log.txt, input.prm (copy of the input) and parameters.prm (every "
      "entry as used). Created if missing.",
      Patterns::Anything());
    add_option(
      prm,
      "Format",
      format,
      output_format_names(),
      "Format of the field output. 'vtu': solution_NNNNN.pvtu with one .vtu "
      "per rank and step, and the series solution.pvd. 'hdf5': one "
      "solution_NNNNN.h5 per step written by all ranks together (parallel "
      "HDF5), the mesh once in mesh.h5, and the series solution.xdmf that "
      "ParaView and VisIt open; for large runs. Both keep the nodes of "
      "different bodies apart where they touch.");
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
    prm.add_parameter(
      "Probe points",
      probe_points_text,
      "Material points (reference coordinates x, y, z [m], points separated "
      "by ';') whose displacement goes to the statistics columns "
      "probe<k>_u_x/y/z [m], k = 1, 2, ... in the order given, and alpha "
      "and s to probe<k>_alpha and probe<k>_s [-] in scenes that have "
      "these fields (0 in a body without them); empty: none.",
      Patterns::Anything());
    prm.leave_subsection();
  }



  void
  OutputParameters::check()
  {
    probe_points.clear();
    for (const std::string &text :
         Utilities::split_string_list(probe_points_text, ';'))
      {
        const auto coordinates = Utilities::split_string_list(text, ',');
        Point<dim> p;
        bool       valid = coordinates.size() == dim;
        for (unsigned int d = 0; valid && d < dim; ++d)
          try
            {
              p[d] = Utilities::string_to_double(coordinates[d]);
            }
          catch (...)
            {
              valid = false;
            }
        check_input(valid,
                    "Output/Probe points",
                    text,
                    "points of " + vector_size_word() + " coordinates " +
                      coordinate_list() + " separated by ';'");
        probe_points.push_back(p);
      }
    check_input(!directory.empty(),
                "Output/Directory",
                directory,
                "it must name a folder");
  }
} // namespace DuctileContact
