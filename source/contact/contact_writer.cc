#include <ductile_contact/contact/contact_writer.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace DuctileContact
{
  void
  write_contact_surface(const ContactNodalData                      &data,
                        const std::string                           &directory,
                        const std::string                           &name,
                        const unsigned int                           step,
                        const double                                 time,
                        std::vector<std::pair<double, std::string>> &records)
  {
    const ContactSurface &surface = *data.surface;
    std::ostringstream    number;
    number << std::setw(5) << std::setfill('0') << step;
    const std::string base = name + "_" + number.str();

    {
      std::ofstream table(directory + "/" + base + ".txt");
      table << "X Y Z x y z pressure gap active slip_x slip_y slip_z "
               "traction_x traction_y traction_z\n"
            << std::setprecision(12);
      for (unsigned int j = 0; j < surface.nodes.size(); ++j)
        {
          const auto &n = surface.nodes[j];
          table << n.reference << ' ' << n.current << ' ' << data.pressure[j]
                << ' ' << data.gap[j] << ' ' << (data.active[j] ? 1 : 0) << ' '
                << data.slip[j] << ' ' << data.traction[j] << '\n';
        }
    }

    {
      // VTK_BIQUADRATIC_QUAD: corners, edge mid-points, centre.
      constexpr unsigned int vtk_order[9] = {0, 2, 8, 6, 1, 5, 7, 3, 4};
      std::ofstream          vtu(directory + "/" + base + ".vtu");
      vtu << std::setprecision(10);
      vtu << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
          << "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
          << surface.nodes.size() << "\" NumberOfCells=\""
          << surface.faces.size() << "\">\n"
          << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
             "format=\"ascii\">\n";
      for (const auto &n : surface.nodes)
        vtu << n.current << '\n';
      vtu << "</DataArray></Points>\n<Cells>\n"
          << "<DataArray type=\"Int64\" Name=\"connectivity\" "
             "format=\"ascii\">\n";
      for (const auto &f : surface.faces)
        {
          for (const unsigned int i : vtk_order)
            vtu << f.nodes[i] << ' ';
          vtu << '\n';
        }
      vtu << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
             "format=\"ascii\">\n";
      for (unsigned int f = 1; f <= surface.faces.size(); ++f)
        vtu << 9 * f << ' ';
      vtu << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
             "format=\"ascii\">\n";
      for (unsigned int f = 0; f < surface.faces.size(); ++f)
        vtu << "28 ";
      vtu << "\n</DataArray>\n</Cells>\n<PointData>\n";
      const auto scalar = [&](const char *field, const auto &values) {
        vtu << "<DataArray type=\"Float64\" Name=\"" << field
            << "\" format=\"ascii\">\n";
        for (const auto v : values)
          vtu << static_cast<double>(v) << ' ';
        vtu << "\n</DataArray>\n";
      };
      scalar("pressure", data.pressure);
      scalar("gap", data.gap);
      scalar("active", data.active);
      const auto vector = [&](const char *field, const auto &values) {
        vtu << "<DataArray type=\"Float64\" Name=\"" << field
            << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &v : values)
          vtu << v << '\n';
        vtu << "</DataArray>\n";
      };
      vector("normal", data.normal);
      vector("slip", data.slip);
      vector("traction", data.traction);
      vtu << "</PointData>\n</Piece>\n</UnstructuredGrid>\n"
          << "</VTKFile>\n";
    }

    records.emplace_back(time, base + ".vtu");
    std::ofstream pvd(directory + "/" + name + ".pvd");
    pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
           "version=\"0.1\">\n<Collection>\n";
    for (const auto &[t, file] : records)
      pvd << "<DataSet timestep=\"" << t << "\" file=\"" << file << "\"/>\n";
    pvd << "</Collection>\n</VTKFile>\n";
  }
} // namespace DuctileContact
