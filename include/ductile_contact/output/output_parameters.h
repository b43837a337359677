#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ductile_contact/core/option.h>
#include <ductile_contact/core/types.h>

#include <string>
#include <vector>

namespace DuctileContact
{
  /// Output/Format of the field output.
  enum class OutputFormat
  {
    /// One .vtu per rank and step, a .pvtu and the series solution.pvd.
    vtu,
    /// One HDF5 file per step written by all ranks together, the mesh in
    /// mesh.h5, the series solution.xdmf.
    hdf5
  };

  inline const NameTable<OutputFormat> &
  output_format_names()
  {
    static const NameTable<OutputFormat> t{{OutputFormat::vtu, "vtu"},
                                           {OutputFormat::hdf5, "hdf5"}};
    return t;
  }

  /// Subsection `Output`.
  struct OutputParameters
  {
    std::string  directory = "results";
    OutputFormat format    = OutputFormat::vtu;
    unsigned int interval  = 1;
    unsigned int verbosity = 1;
    /// Probe points as written in the input, and parsed by check().
    std::string                     probe_points_text;
    std::vector<dealii::Point<dim>> probe_points;

    void
    declare(dealii::ParameterHandler &prm);
    /// Checks the entries and parses Probe points.
    void
    check();
  };
} // namespace DuctileContact
