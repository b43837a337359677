#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/app/application.h>
#include <ductile_contact/app/checkpoint.h>
#include <ductile_contact/app/command_line.h>
#include <ductile_contact/app/prm_writer.h>
#include <ductile_contact/app/simulation.h>
#include <ductile_contact/app/stop_request.h>
#include <ductile_contact/app/version.h>
#include <ductile_contact/core/input_error.h>
#include <ductile_contact/core/one_line.h>
#include <ductile_contact/mesh/scene.h>
#include <ductile_contact/output/probe_points.h>
#include <ductile_contact/output/tee_stream.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// deal.II's multi-line parser messages as one line, with the line
    /// number of the input file ("line 13: ...").
    std::string
    parser_message(const std::string &message)
    {
      std::string       out    = one_line(message);
      const std::string source = " of file <input string>";
      const auto        pos    = out.find(source);
      if (pos != std::string::npos)
        out.erase(pos, source.size());
      if (out.rfind("Line <", 0) == 0)
        {
          out.replace(0, 6, "line ");
          const auto close = out.find('>');
          if (close != std::string::npos)
            out.erase(close, 1);
        }
      return Utilities::trim(out);
    }



    /// Throws InputError when a boundary condition's expression is not
    /// finite at a vertex or face centre of its boundary (coarse mesh) at
    /// t = 0 or at the end time.
    void
    check_boundary_expressions(const RunParameters      &parameters,
                               const Triangulation<dim> &tria)
    {
      const double end = parameters.load_stepping.end_time;
      for (const BoundaryCondition &bc : parameters.boundary_conditions)
        for (const auto &cell : tria.cell_iterators_on_level(0))
          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (!face->at_boundary() || face->boundary_id() != bc.boundary_id)
                continue;
              std::vector<Point<dim>> points{face->center()};
              for (const unsigned int v : face->vertex_indices())
                points.push_back(face->vertex(v));
              for (const auto &[name, function] :
                   {std::pair{"Displacement", bc.displacement.get()},
                    std::pair{"Traction", bc.traction.get()}})
                {
                  if (function == nullptr)
                    continue;
                  Vector<double> values(function->n_components);
                  for (const double t : {0., end})
                    for (const Point<dim> &p : points)
                      {
                        function->set_time(t);
                        function->vector_value(p, values);
                        for (unsigned int d = 0; d < dim; ++d)
                          if (!std::isfinite(values[d]))
                            {
                              std::ostringstream where;
                              where << "it must be finite on the boundary at "
                                       "t = 0 and at the end time; it is "
                                    << (std::isnan(values[d]) ? "NaN"
                                        : values[d] > 0       ? "Inf"
                                                              : "-Inf")
                                    << " at (" << p << ") at t = " << t;
                              function->set_time(0.);
                              throw InputError(bc.subsection() + "/" + name,
                                               name == std::string("Traction")
                                                 ? bc.traction_text
                                                 : bc.displacement_text,
                                               where.str());
                            }
                      }
                  function->set_time(0.);
                }
            }
    }



    /// Throws InputError when the mesh after the global refinements cannot
    /// fit into the memory of the hosts of this run: a lower bound, the
    /// tangent matrix alone (FE_Q(p): (2p + 1)^dim nodes couple with a node,
    /// 12 bytes per entry), against MemTotal summed over the hosts.
    void
    check_memory(const RunParameters                             &parameters,
                 const parallel::distributed::Triangulation<dim> &coarse)
    {
      const MPI_Comm comm    = coarse.get_communicator();
      bool           plastic = false, cracking = false;
      for (const BodyParameters &b : parameters.bodies)
        {
          plastic  = plastic || b.plasticity;
          cracking = cracking || b.fracture;
        }
      const double components = dim + (plastic ? 1 : 0) + (cracking ? 1 : 0);
      const double p          = parameters.fe_degree;
      const double cells =
        coarse.n_global_active_cells() *
        std::pow(std::pow(2., dim), parameters.mesh.global_refinements);
      const double unknowns = cells * std::pow(p, dim) * components;
      const double bytes =
        unknowns * std::pow(2. * p + 1., dim) * components * 12.;

      // MemTotal of each host, counted once.
      double      host_memory = 0.;
      std::string host;
      {
        std::ifstream meminfo("/proc/meminfo");
        std::string   key;
        double        kb = 0.;
        while (meminfo >> key >> kb)
          {
            if (key == "MemTotal:")
              {
                host_memory = kb * 1024.;
                break;
              }
            meminfo.ignore(256, '\n');
          }
        char name[MPI_MAX_PROCESSOR_NAME];
        int  length = 0;
        MPI_Get_processor_name(name, &length);
        host = std::string(name, length);
      }
      const auto hosts  = Utilities::MPI::all_gather(comm, host);
      const auto memory = Utilities::MPI::all_gather(comm, host_memory);
      std::map<std::string, double> per_host;
      for (unsigned int r = 0; r < hosts.size(); ++r)
        per_host[hosts[r]] = memory[r];
      double total = 0.;
      for (const auto &h : per_host)
        total += h.second;
      if (total <= 0. || bytes <= total)
        return;
      std::ostringstream why;
      why << std::setprecision(2)
          << "it must give a mesh that fits into memory: with it "
          << "the run would have about " << cells << " cells and " << unknowns
          << " unknowns, whose tangent matrix alone needs about "
          << bytes / std::pow(1024., 3) << " GiB, against "
          << total / std::pow(1024., 3) << " GiB on the " << per_host.size()
          << " host(s) of this run";
      throw InputError("Mesh/Global refinements",
                       std::to_string(parameters.mesh.global_refinements),
                       why.str());
    }



    /// Throws InputError when Output/Directory can neither be used nor
    /// created: its nearest existing ancestor must be a folder this
    /// process may write to. Creates nothing (also used by --validate).
    void
    check_output_directory(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      fs::path        existing = fs::absolute(directory, ec);
      while (!existing.empty() && !fs::exists(existing, ec) &&
             existing != existing.parent_path())
        existing = existing.parent_path();
      if (!fs::is_directory(existing, ec))
        throw InputError("Output/Directory",
                         directory,
                         "it must be a folder or a path where one can be "
                         "created ('" +
                           existing.string() + "' is not a folder)");
      if (access(existing.c_str(), W_OK | X_OK) != 0)
        throw InputError("Output/Directory",
                         directory,
                         "it must be a folder this run may write to (no "
                         "write permission in '" +
                           existing.string() + "')");
    }



    /// Warnings for fractured bodies whose crack band the mesh cannot
    /// resolve: l_f below the node spacing h / p of the body's finest cells
    /// (h the mean edge length of a cell of the coarse mesh, halved per
    /// global refinement and per level of the deepest refinement box; the
    /// paper's scene has l_f = h with p = 2). The run goes on: the answer is
    /// then a property of the mesh, not of the model.
    std::vector<std::string>
    crack_resolution_warnings(
      const RunParameters                             &parameters,
      const parallel::distributed::Triangulation<dim> &coarse)
    {
      unsigned int levels = parameters.mesh.global_refinements;
      unsigned int boxes  = 0;
      for (const RefinementBox &box : parameters.mesh.refinement_boxes)
        boxes = std::max(boxes, box.levels);
      levels += boxes;
      // Adaptive refinement by s takes the crack's cells to Maximum level.
      const auto &adaptive = parameters.mesh.adaptive;
      if (adaptive.enabled && adaptive.phase_field_threshold > 0.)
        levels = std::max(levels, adaptive.maximum_level);

      std::vector<std::string> warnings;
      for (const BodyParameters &body : parameters.bodies)
        {
          if (!body.fracture)
            continue;
          double h = std::numeric_limits<double>::max();
          for (const auto &cell : coarse.active_cell_iterators())
            if (cell->material_id() == body.material_id)
              {
                double edges = 0.;
                for (const unsigned int l : cell->line_indices())
                  edges += cell->line(l)->diameter();
                h = std::min(h, edges / cell->n_lines());
              }
          h /= std::pow(2., levels);
          const double spacing = h / parameters.fe_degree;
          const double l_f     = body.crack.length_scale;
          if (l_f >= spacing)
            continue;
          std::ostringstream w;
          w << std::setprecision(3) << "Warning: " << body.subsection()
            << "/Fracture/Length scale = " << l_f
            << " m is below the node spacing of body '" << body.name
            << "': its finest cells are " << h << " m across, FE_Q("
            << parameters.fe_degree << ") nodes " << spacing
            << " m apart. The crack band (about 4 l_f wide) is not resolved: "
               "the crack energy and the force at which it grows depend on "
               "the mesh. Refine (Mesh/Global refinements, Local refinement "
               "boxes or Adaptive refinement/Maximum level) until the node "
               "spacing is at most l_f.";
          warnings.push_back(w.str());
        }
      return warnings;
    }



    std::string
    join(const std::set<unsigned int> &ids)
    {
      std::ostringstream s;
      for (auto it = ids.begin(); it != ids.end(); ++it)
        s << (it == ids.begin() ? "" : ", ") << *it;
      return s.str();
    }
  } // namespace



  void
  build_and_check_mesh(const RunParameters                       &parameters,
                       parallel::distributed::Triangulation<dim> &tria,
                       const bool                                 refine)
  {
    MeshParameters mesh = parameters.mesh;
    if (!refine)
      {
        mesh.global_refinements = 0;
        mesh.refinement_boxes.clear();
      }
    create_scene_mesh(mesh, tria);

    std::set<unsigned int> in_mesh, listed;
    for (const auto id : material_ids_in_mesh(tria))
      in_mesh.insert(id);
    for (const BodyParameters &b : parameters.bodies)
      listed.insert(b.material_id);
    if (in_mesh != listed)
      throw InputError("Bodies/Material ids",
                       join(listed),
                       "the mesh of scene '" +
                         name_of(scene_names(), parameters.mesh.scene) +
                         "' has the material ids " + join(in_mesh) +
                         "; list exactly these, each with a subsection "
                         "'Body <id>'");

    std::set<unsigned int> boundaries;
    for (const auto id : boundary_ids_in_mesh(tria))
      boundaries.insert(id);
    for (const BoundaryCondition &bc : parameters.boundary_conditions)
      check_input(boundaries.count(bc.boundary_id) > 0,
                  "Boundary conditions/Boundary ids",
                  Utilities::to_string(bc.boundary_id),
                  "the mesh of scene '" +
                    name_of(scene_names(), parameters.mesh.scene) +
                    "' has no boundary with this id (it has " +
                    join(boundaries) + ")");
    for (const ContactPairParameters &c : parameters.contact_pairs)
      for (const auto &[entry, id] :
           {std::pair{"Slave boundary id", c.slave_boundary_id},
            std::pair{"Master boundary id", c.master_boundary_id}})
        check_input(boundaries.count(id) > 0,
                    c.subsection() + "/" + entry,
                    Utilities::to_string(id),
                    "the id of a boundary of the mesh of scene '" +
                      name_of(scene_names(), parameters.mesh.scene) +
                      "' (it has " + join(boundaries) + ")");
    ProbePoints::check_inside(tria, parameters.output.probe_points);
    if (!parameters.contact_pairs.empty())
      check_input(parameters.fe_degree == 2,
                  "Finite elements/Polynomial degree",
                  Utilities::to_string(parameters.fe_degree),
                  "2 in a scene with contact (the mortar contact works on "
                  "the faces of quadratic cells: quad9, line3)");
  }



  namespace
  {
    /// Parses and checks the input file and (for --validate and runs)
    /// builds the coarse scene: every input error surfaces here, before
    /// any work. False after the message on an error.
    bool
    read_input(const CommandLine        &line,
               const MPI_Comm            comm,
               const bool                root,
               RunParameters            &parameters,
               std::vector<std::string> &warnings)
    {
      const std::string &file_name = line.file_name;
      try
        {
          parameters.parse(file_name, line.overrides);
          if (!line.print_parameters)
            {
              parallel::distributed::Triangulation<dim> coarse(comm);
              build_and_check_mesh(parameters, coarse, false);
              check_boundary_expressions(parameters, coarse);
              check_memory(parameters, coarse);
              check_output_directory(parameters.output.directory);
              warnings = crack_resolution_warnings(parameters, coarse);
            }
          return true;
        }
      catch (const InputError &e)
        {
          if (root)
            std::cerr << "Error in input file '" << file_name
                      << "': " << e.what() << std::endl;
        }
      catch (const ExceptionBase &e)
        {
          // ParameterHandler's messages name the line, entry, value and
          // pattern; print them without deal.II's stack-trace header.
          std::ostringstream info;
          e.print_info(info);
          std::string message = parser_message(info.str());
          for (auto pos = message.find("<input string>");
               pos != std::string::npos;
               pos = message.find("<input string>"))
            message.replace(pos, 14, "'" + file_name + "'");
          // A line past the file's end is one of the --set overrides.
          if (!line.overrides.empty())
            {
              std::ifstream file(file_name);
              const auto    n_lines =
                std::count(std::istreambuf_iterator<char>(file),
                           std::istreambuf_iterator<char>(),
                           '\n');
              unsigned int number = 0;
              if (std::sscanf(message.c_str(), "line %u:", &number) == 1 &&
                  number > n_lines)
                message = "--set: " + message.substr(message.find(':') + 2);
            }
          if (root)
            std::cerr << "Error in input file '" << file_name
                      << "': " << message << std::endl;
        }
      return false;
    }



    /// The newest complete checkpoint in the output directory, and in
    /// @p accepted_changes the entries changed since it that it allows;
    /// InputError if there is none or a change invalidates it.
    std::string
    checkpoint_to_resume(const RunParameters      &parameters,
                         const MPI_Comm            comm,
                         std::vector<std::string> &accepted_changes)
    {
      const std::string &dir = parameters.output.directory;
      const Checkpoint   checkpoints(dir, parameters.checkpoint.keep, comm);
      const std::string  checkpoint = checkpoints.newest();
      if (checkpoint.empty())
        throw InputError("Output/Directory",
                         dir,
                         "a folder with a complete checkpoint to resume "
                         "from (there is none in '" +
                           dir + "/checkpoints')");
      std::ostringstream current;
      write_prm(parameters.prm, current);
      accepted_changes =
        compare_parameters(checkpoints.read(checkpoint, "parameters.prm"),
                           current.str());
      return checkpoint;
    }



    /// The results folder with a copy of the input and all parameters,
    /// and the log file in it; false if the folder cannot be made.
    bool
    open_results(const CommandLine   &line,
                 const RunParameters &parameters,
                 const MPI_Comm       comm,
                 const bool           root,
                 TeeStream           &log)
    {
      const std::string &dir = parameters.output.directory;
      if (root)
        {
          std::error_code ec;
          std::filesystem::create_directories(dir, ec);
          if (ec || !std::filesystem::is_directory(dir))
            std::cerr << "Error: cannot create the output directory '" << dir
                      << "' (entry 'Output/Directory'): " << ec.message()
                      << std::endl;
        }
      if (Utilities::MPI::broadcast(comm,
                                    std::filesystem::is_directory(dir) ? 1 : 0,
                                    0) == 0)
        return false;
      if (root)
        {
          log.open_file(dir + "/log.txt", line.resume);
          std::filesystem::copy_file(
            line.file_name,
            dir + "/input.prm",
            std::filesystem::copy_options::overwrite_existing);
          if (!line.overrides.empty())
            {
              std::ofstream input(dir + "/input.prm", std::ios::app);
              input << "\n# Overrides given on the command line (--set):\n"
                    << overrides_as_prm(line.overrides);
            }
          std::ofstream all(dir + "/parameters.prm");
          write_prm(parameters.prm, all);
        }
      return true;
    }
  } // namespace



  int
  run_application(int argc, char **argv, const MPI_Comm comm)
  {
    const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
    const CommandLine line = parse_command_line(argc, argv, root);
    if (line.exit_code)
      return *line.exit_code;

    RunParameters            parameters;
    std::vector<std::string> warnings;
    if (!read_input(line, comm, root, parameters, warnings))
      return 1;
    if (line.print_parameters)
      {
        if (root)
          {
            if (line.style == ParameterHandler::PRM)
              write_prm(parameters.prm, std::cout);
            else
              parameters.prm.print_parameters(
                std::cout, line.style | ParameterHandler::KeepDeclarationOrder);
          }
        return 0;
      }
    if (line.validate)
      {
        if (root)
          {
            for (const std::string &w : warnings)
              std::cout << w << std::endl;
            std::cout << line.file_name << ": valid" << std::endl;
          }
        return 0;
      }

    std::string              checkpoint;
    std::vector<std::string> accepted_changes;
    if (line.resume)
      try
        {
          checkpoint = checkpoint_to_resume(parameters, comm, accepted_changes);
        }
      catch (const InputError &e)
        {
          if (root)
            std::cerr << "Error in input file '" << line.file_name
                      << "' (--resume): " << e.what() << std::endl;
          return 1;
        }
    TeeStream log(std::cout);
    if (!open_results(line, parameters, comm, root, log))
      return 1;
    if (root)
      {
        log << version_line() << "\n";
        for (const std::string &o : line.overrides)
          log << "--set " << o << "\n";
        log << "ductile-contact: " << line.file_name << " on "
            << Utilities::MPI::n_mpi_processes(comm)
            << " MPI rank(s), results in " << parameters.output.directory << "/"
            << std::endl;
        for (const std::string &w : warnings)
          log << w << std::endl;
        if (line.resume)
          {
            log << "Resuming from " << checkpoint << std::endl;
            for (const std::string &change : accepted_changes)
              log << "  changed since the checkpoint, taken: " << change
                  << std::endl;
          }
      }

    install_stop_handlers();
    try
      {
        Simulation simulation(parameters, comm, log, checkpoint);
        return simulation.run();
      }
    catch (const InputError &e)
      {
        if (root)
          log << "Error: " << e.what() << std::endl;
        return 1;
      }
  }
} // namespace DuctileContact
