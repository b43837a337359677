#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <ductile_contact/contact/contact_writer.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// The scalar and vector fields of the surface output, in the order
    /// of their rows in a patch (each vector's name once per component).
    std::vector<std::string>
    make_field_names()
    {
      std::vector<std::string> names = {"pressure",
                                        "gap",
                                        "active",
                                        "friction_state"};
      for (const char *vector : {"normal", "slip", "traction"})
        names.insert(names.end(), dim, vector);
      return names;
    }
    const std::vector<std::string> field_names = make_field_names();

    /**
     * A slave surface as DataOut patches: each face (quad9, line3) a patch
     * with two subdivisions whose points are its nodes (the face's node
     * order is the lexicographic order of a patch's points), at their
     * current positions, so that DataOutInterface writes it in parallel as
     * vtu or HDF5.
     */
    class SurfacePatches : public DataOutInterface<dim - 1, dim>
    {
    public:
      SurfacePatches(const ContactNodalData &data, const MPI_Comm comm)
      {
        const ContactSurface &surface = *data.surface;
        const unsigned int    rank    = Utilities::MPI::this_mpi_process(comm);
        const unsigned int    ranks   = Utilities::MPI::n_mpi_processes(comm);
        // deal.II's vertex order of the face, in face node numbering.
        constexpr auto corners = ContactFace::vertices;
        for (unsigned int f = rank; f < surface.faces.size(); f += ranks)
          {
            const auto                      &face = surface.faces[f];
            DataOutBase::Patch<dim - 1, dim> patch;
            patch.n_subdivisions = 2;
            patch.reference_cell = ReferenceCells::get_hypercube<dim - 1>();
            for (unsigned int v = 0; v < corners.size(); ++v)
              patch.vertices[v] = surface.nodes[face.nodes[corners[v]]].current;
            patch.points_are_available = true;
            patch.data.reinit(field_names.size() + dim, face_nodes);
            for (unsigned int k = 0; k < face_nodes; ++k)
              {
                const unsigned int j   = face.nodes[k];
                unsigned int       row = 0;
                for (const double v :
                     {data.pressure[j],
                      data.gap[j],
                      data.active[j] ? 1. : 0.,
                      static_cast<double>(data.friction_state[j])})
                  patch.data(row++, k) = v;
                for (const auto *vector :
                     {&data.normal[j], &data.slip[j], &data.traction[j]})
                  for (unsigned int d = 0; d < dim; ++d)
                    patch.data(row++, k) = (*vector)[d];
                for (unsigned int d = 0; d < dim; ++d)
                  patch.data(row++, k) = surface.nodes[j].current[d];
              }
            patch.patch_index = patches.size();
            patches.push_back(patch);
          }
      }

    private:
      const std::vector<DataOutBase::Patch<dim - 1, dim>> &
      get_patches() const override
      {
        return patches;
      }

      std::vector<std::string>
      get_dataset_names() const override
      {
        return field_names;
      }

      std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
      get_nonscalar_data_ranges() const override
      {
        const auto vector =
          DataComponentInterpretation::component_is_part_of_vector;
        return {{4, 3 + dim, "normal", vector},
                {4 + dim, 3 + 2 * dim, "slip", vector},
                {4 + 2 * dim, 3 + 3 * dim, "traction", vector}};
      }

      std::vector<DataOutBase::Patch<dim - 1, dim>> patches;
    };



    /// The node table for scripts (rank 0).
    void
    write_table(const ContactNodalData &data, const std::string &file)
    {
      const ContactSurface &surface = *data.surface;
      std::ofstream         table(file);
      if constexpr (dim == 3)
        table << "X Y Z x y z pressure gap active slip_x slip_y slip_z "
                 "traction_x traction_y traction_z\n";
      else
        table << "X Y x y pressure gap active slip_x slip_y traction_x "
                 "traction_y\n";
      table << std::setprecision(12);
      for (unsigned int j = 0; j < surface.nodes.size(); ++j)
        {
          const auto &n = surface.nodes[j];
          table << n.reference << ' ' << n.current << ' ' << data.pressure[j]
                << ' ' << data.gap[j] << ' ' << (data.active[j] ? 1 : 0) << ' '
                << data.slip[j] << ' ' << data.traction[j] << '\n';
        }
    }
  } // namespace



  void
  write_contact_surface(const ContactNodalData                      &data,
                        const std::string                           &directory,
                        const std::string                           &name,
                        const unsigned int                           step,
                        const double                                 time,
                        const OutputFormat                           format,
                        const MPI_Comm                               comm,
                        std::vector<std::pair<double, std::string>> &records)
  {
    const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string base = name + "_" + Utilities::int_to_string(step, 5);
    if (root)
      write_table(data, directory + "/" + base + ".txt");

    const SurfacePatches surface(data, comm);
    if (format == OutputFormat::vtu)
      {
        records.emplace_back(time,
                             surface.write_vtu_with_pvtu_record(
                               directory + "/", name, step, comm, 5));
        if (root)
          {
            std::ofstream pvd(directory + "/" + name + ".pvd");
            DataOutBase::write_pvd_record(pvd, records);
          }
        return;
      }

    // hdf5: mesh and fields of the step in one file (the surface moves);
    // the series written by hand from the steps' grids, which the
    // records keep (checkpoints carry them as text).
    DataOutBase::DataOutFilter filter(
      DataOutBase::DataOutFilterFlags(/*filter_duplicate_vertices=*/false,
                                      /*xdmf_hdf5_output=*/true));
    surface.write_filtered_data(filter);
    const std::string h5 = base + ".h5";
    surface.write_hdf5_parallel(filter, directory + "/" + h5, comm);
    const XDMFEntry entry = surface.create_xdmf_entry(filter, h5, time, comm);
    records.emplace_back(time, entry.get_xdmf_content(3));
    if (root)
      {
        std::ofstream xdmf(directory + "/" + name + ".xdmf");
        xdmf << "<?xml version=\"1.0\" ?>\n"
             << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
             << "<Xdmf Version=\"2.0\">\n  <Domain>\n"
             << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
                "CollectionType=\"Temporal\">\n";
        for (const auto &record : records)
          xdmf << record.second;
        xdmf << "    </Grid>\n  </Domain>\n</Xdmf>\n";
      }
  }
} // namespace DuctileContact
