#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/cell_data_transfer.h>
#include <deal.II/distributed/cell_data_transfer.templates.h>
#include <deal.II/distributed/solution_transfer.h>

#include <ductile_contact/app/checkpoint.h>
#include <ductile_contact/app/version.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;
  namespace fs = std::filesystem;

  namespace
  {
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    void
    write_file(const std::string &name, const std::string &text)
    {
      std::ofstream out(name, std::ios::binary);
      out << text;
      out.close();
      AssertThrow(out, ExcMessage("cannot write the checkpoint file " + name));
    }

    /// Test hook: a run with DUCTILE_CONTACT_TEST_KILL_IN_CHECKPOINT = k
    /// kills itself (SIGKILL on rank 0) after writing the data of the
    /// checkpoint of step k and before making it complete, as a job killed
    /// by its scheduler at that moment (tests/checkpoint).
    void
    test_kill_hook(const unsigned int step, const MPI_Comm comm)
    {
      const char *value =
        std::getenv("DUCTILE_CONTACT_TEST_KILL_IN_CHECKPOINT");
      if (value != nullptr && std::atoi(value) == static_cast<int>(step) &&
          Utilities::MPI::this_mpi_process(comm) == 0)
        std::raise(SIGKILL);
    }
  } // namespace



  Checkpoint::Checkpoint(const std::string &output_directory,
                         const unsigned int keep,
                         const MPI_Comm     comm)
      : root(output_directory + "/checkpoints")
      , keep(keep)
      , comm(comm)
  {
  }



  std::string
  Checkpoint::folder_name(const unsigned int step)
  {
    std::ostringstream name;
    name << "step_" << std::setw(6) << std::setfill('0') << step;
    return name.str();
  }



  void
  Checkpoint::write(const unsigned int                      step,
                    const DoFHandler<dim>                  &dof_handler,
                    const std::vector<const BlockVector *> &ghosted,
                    const CellData                         &cell_data,
                    const std::string                      &state,
                    const std::string                      &parameters) const
  {
    const bool        root_rank = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string writing   = root + "/.writing";
    if (root_rank)
      {
        fs::remove_all(writing);
        fs::create_directories(writing);
      }
    MPI_Barrier(comm);

    // The mesh with the data attached to its cells, in this order (the
    // order load_data() reads them in).
    const auto &tria =
      dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
        dof_handler.get_triangulation());
    parallel::distributed::SolutionTransfer<dim, BlockVector> vectors(
      dof_handler);
    vectors.prepare_for_serialization(ghosted);
    parallel::distributed::CellDataTransfer<dim, dim, CellData> cells(tria,
                                                                      true);
    cells.prepare_for_serialization(cell_data);
    tria.save(writing + "/mesh");

    if (root_rank)
      {
        write_file(writing + "/state.bin", state);
        write_file(writing + "/parameters.prm", parameters);
        write_file(writing + "/version.txt", version_line() + "\n");
        write_file(writing + "/coarse_mesh", coarse_mesh_fingerprint(tria));
      }
    MPI_Barrier(comm);
    test_kill_hook(step, comm);

    if (root_rank)
      {
        const std::string name = folder_name(step);
        fs::remove_all(root + "/" + name);
        fs::rename(writing, root + "/" + name);
        write_file(root + "/last.new", name + "\n");
        fs::rename(root + "/last.new", root + "/last");
        prune();
      }
    MPI_Barrier(comm);
  }



  void
  Checkpoint::prune() const
  {
    std::vector<std::string> complete;
    for (const auto &entry : fs::directory_iterator(root))
      {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() && name.rfind("step_", 0) == 0)
          complete.push_back(name);
      }
    std::sort(complete.begin(), complete.end());
    for (std::size_t i = 0; i + keep < complete.size(); ++i)
      fs::remove_all(root + "/" + complete[i]);
  }



  std::string
  Checkpoint::newest() const
  {
    std::string folder;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ifstream marker(root + "/last");
        std::string   name;
        if (marker >> name &&
            fs::is_regular_file(root + "/" + name + "/state.bin"))
          folder = root + "/" + name;
      }
    return Utilities::MPI::broadcast(comm, folder, 0);
  }



  std::string
  Checkpoint::read(const std::string &folder, const std::string &file) const
  {
    std::string text;
    int         ok = 1;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ifstream      in(folder + "/" + file, std::ios::binary);
        std::ostringstream content;
        content << in.rdbuf();
        ok   = in ? 1 : 0;
        text = content.str();
      }
    if (Utilities::MPI::broadcast(comm, ok, 0) == 0)
      throw InputError("the checkpoint file '" + folder + "/" + file +
                       "' cannot be read");
    return Utilities::MPI::broadcast(comm, text, 0);
  }



  void
  Checkpoint::load_mesh(const std::string                         &folder,
                        parallel::distributed::Triangulation<dim> &tria)
  {
    tria.load(folder + "/mesh");
  }



  void
  Checkpoint::load_data(const DoFHandler<dim>            &dof_handler,
                        const std::vector<BlockVector *> &owned,
                        CellData                         &cell_data)
  {
    const auto &tria =
      dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
        dof_handler.get_triangulation());
    parallel::distributed::SolutionTransfer<dim, BlockVector> vectors(
      dof_handler);
    std::vector<BlockVector *> out = owned;
    vectors.deserialize(out);
    parallel::distributed::CellDataTransfer<dim, dim, CellData> cells(tria,
                                                                      true);
    cell_data.assign(tria.n_active_cells(), {});
    cells.deserialize(cell_data);
  }
} // namespace DuctileContact

namespace DuctileContact
{
  namespace
  {
    /// "Subsection/.../Entry" -> value of a PRM-style parameter listing.
    std::map<std::string, std::string>
    flatten(const std::string &prm)
    {
      std::map<std::string, std::string> entries;
      std::vector<std::string>           path;
      std::istringstream                 in(prm);
      std::string                        line;
      while (std::getline(in, line))
        {
          line = Utilities::trim(line.substr(0, line.find('#')));
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0 &&
                   line.find('=') != std::string::npos)
            {
              const auto  eq   = line.find('=');
              std::string name = Utilities::trim(line.substr(4, eq - 4));
              for (auto it = path.rbegin(); it != path.rend(); ++it)
                name = *it + "/" + name;
              entries[name] = Utilities::trim(line.substr(eq + 1));
            }
        }
      return entries;
    }

    bool
    invalidates(const std::string &entry)
    {
      // The checkpoint holds the adapted mesh; the criteria only steer
      // further refinement.
      if (entry.rfind("Mesh/Adaptive refinement/", 0) == 0)
        return false;
      // The number of vectors a checkpoint holds depends on it.
      if (entry == "Load stepping/Time integration")
        return true;
      for (const char *prefix : {"Mesh/",
                                 "Finite elements/",
                                 "Bodies/",
                                 "Body ",
                                 "Boundary conditions/",
                                 "Contact/",
                                 "Contact pair "})
        if (entry.rfind(prefix, 0) == 0)
          return true;
      return false;
    }
  } // namespace



  std::vector<std::string>
  compare_parameters(const std::string &saved, const std::string &current)
  {
    const auto old_entries = flatten(saved), new_entries = flatten(current);
    std::set<std::string> names;
    for (const auto &e : old_entries)
      names.insert(e.first);
    for (const auto &e : new_entries)
      names.insert(e.first);
    std::vector<std::string> accepted;
    for (const std::string &name : names)
      {
        const auto o = old_entries.find(name), n = new_entries.find(name);
        const std::string old_value =
          o == old_entries.end() ? "(not there)" : o->second;
        const std::string new_value =
          n == new_entries.end() ? "(not there)" : n->second;
        if (old_value == new_value)
          continue;
        if (invalidates(name))
          throw InputError(name,
                           new_value,
                           "the value the checkpoint was made with, '" +
                             old_value +
                             "': a resumed run cannot change the mesh, the "
                             "bodies and their physics, the finite elements "
                             "or the contact pairs (start a new run instead)");
        accepted.push_back(name + ": " + old_value + " -> " + new_value);
      }
    return accepted;
  }



  std::string
  Checkpoint::coarse_mesh_fingerprint(
    const parallel::distributed::Triangulation<dim> &tria)
  {
    double sum = 0.;
    for (const auto &cell : tria.cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          sum += (d + 1.) * cell->vertex(v)[d] +
                 1e-3 * cell->material_id() * (v + 1);
    std::ostringstream s;
    s << tria.n_cells(0) << " cells, " << std::setprecision(12) << sum;
    return s.str();
  }
} // namespace DuctileContact
