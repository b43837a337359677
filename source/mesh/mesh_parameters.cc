#include <deal.II/base/utilities.h>

#include <ductile_contact/core/expression.h>
#include <ductile_contact/core/input_error.h>
#include <ductile_contact/mesh/mesh_parameters.h>

#include <fstream>

namespace DuctileContact
{
  using namespace dealii;

  void
  MeshParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    add_option(
      prm,
      "Scene",
      scene,
      scene_names(),
      "Which coarse mesh to build. 'box': one body, a brick given in "
      "subsection Box, boundary ids 0..5 on the faces x-, x+, y-, y+, z-, z+. "
      "'two bodies': the plate and block of the paper's scene (doc/model.md "
      "section 7), see subsection Two bodies for the ids. 'round bar': the "
      "necking bar of validation rung 3, see subsection Round bar. 'gmsh': "
      "a mesh "
      "read from a Gmsh .msh file; physical volume tags become material ids "
      "(bodies), physical surface tags become boundary ids.");
    prm.add_parameter("Global refinements",
                      global_refinements,
                      "Number of uniform refinements of the coarse mesh.",
                      Patterns::Integer(0, 12));
    prm.add_parameter(
      "Local refinement boxes",
      refinement_boxes_text,
      "Boxes in which cells are refined further, after the global "
      "refinements: 'x0,y0,z0 : x1,y1,z1 : n' with the lower and upper "
      "corners [m] ('x0,y0 : x1,y1 : n' in 2-D) and the number n of extra "
      "refinements; several boxes are "
      "separated by ';'. A cell is refined if its centre lies in the box. "
      "Empty: no local refinement.",
      Patterns::Anything());

    declare_adaptive_refinement(prm);
    declare_scenes(prm);
    prm.leave_subsection();
  }



  void
  MeshParameters::declare_adaptive_refinement(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptive refinement");
    prm.add_parameter(
      "Enabled",
      adaptive.enabled,
      "Refine the mesh during the run where s or alpha exceed the "
      "thresholds below (doc/input.md, 'Adaptive refinement'): after a "
      "converged load step the cells are flagged; if any are, the state of "
      "the last accepted step is carried to the refined mesh and the step "
      "is solved again, until nothing is flagged or Maximum passes per "
      "step is reached. Cells are never coarsened.");
    prm.add_parameter(
      "Phase-field threshold",
      adaptive.phase_field_threshold,
      "A cell is refined where s exceeds this value at one of its DoFs "
      "[-]; 0: s does not refine.",
      Patterns::Double(0., 1.));
    prm.add_parameter(
      "Hardening threshold",
      adaptive.hardening_threshold,
      "A cell is refined where the hardening variable alpha exceeds this "
      "value at one of its DoFs [-]; 0: alpha does not refine.",
      Patterns::Double(0.));
    prm.add_parameter("Maximum level",
                      adaptive.maximum_level,
                      "Cells are refined up to this level; the coarse mesh "
                      "(before Global refinements) is level 0.",
                      Patterns::Integer(0, 12));
    prm.add_parameter(
      "Maximum cells",
      adaptive.maximum_cells,
      "No refinement that would make more than this many cells (each "
      "refined cell adds 7); when the flagged cells would, those with the "
      "largest s (or alpha) relative to its threshold are refined. 0: no "
      "limit.",
      Patterns::Integer(0));
    prm.add_parameter("Maximum passes per step",
                      adaptive.maximum_passes,
                      "How often one load step may be refined and solved "
                      "again before it is accepted on the mesh it has.",
                      Patterns::Integer(1, 20));
    prm.leave_subsection();
  }



  void
  MeshParameters::declare_scenes(ParameterHandler &prm)
  {
    prm.enter_subsection("Box");
    prm.add_parameter("Lower corner",
                      box.lower_corner,
                      "Lower corner (x, y, z) of the box [m]; (x, y) in "
                      "2-D.");
    prm.add_parameter("Upper corner",
                      box.upper_corner,
                      "Upper corner (x, y, z) of the box [m]; (x, y) in "
                      "2-D. Boundary ids 0-5 on the faces x = x0, x = x1, "
                      "y = y0, y = y1, z = z0, z = z1 (0-3 on the edges of "
                      "the rectangle in 2-D); material id 0.");
    prm.add_parameter("Subdivisions",
                      box.subdivisions,
                      "Number of coarse cells along x, y, z (x, y in 2-D).",
                      Patterns::List(Patterns::Integer(1), dim, dim, ","));
    prm.leave_subsection();

    prm.enter_subsection("Two bodies");
    prm.add_parameter(
      "Plate size",
      two_bodies.plate_size,
      "Plate [0,Lx]x[0,Ly]x[0,Lz] [m] ([0,Lx]x[0,Ly] in 2-D, the block "
      "above y = Ly). Boundary ids: 1 = clamped face x = Lx, 3 = top face "
      "z = Lz (y = Ly in 2-D; contact surface of the plate), 0 = other "
      "plate faces; block: 2 = top face, 4 = bottom face (contact surface "
      "of the block), 5 = its side faces. Material ids: 0 = plate, 1 = "
      "block.");
    prm.add_parameter("Plate subdivisions",
                      two_bodies.plate_subdivisions,
                      "Number of coarse plate cells along x, y, z (x, y in "
                      "2-D).",
                      Patterns::List(Patterns::Integer(1), dim, dim, ","));
    prm.add_parameter("Block edge",
                      two_bodies.block_edge,
                      "Edge length of the cubic (square in 2-D) block [m].",
                      Patterns::Double(0.));
    prm.add_parameter("Block subdivisions",
                      two_bodies.block_subdivisions,
                      "Number of coarse block cells along x, y, z (x, y in "
                      "2-D).",
                      Patterns::List(Patterns::Integer(1), dim, dim, ","));
    prm.add_parameter(
      "Block centre",
      two_bodies.block_centre,
      "In-plane position (x, y) of the block's centre [m] "
      "(x in 2-D).",
      Patterns::List(Patterns::Double(), dim - 1, dim - 1, ","));
    prm.add_parameter("Block gap",
                      two_bodies.block_gap,
                      "Distance between the plate's top face and the block's "
                      "bottom face [m]; 0 = touching.",
                      Patterns::Double(0.));
    prm.leave_subsection();

    prm.enter_subsection("Round bar");
    prm.add_parameter("Radius",
                      round_bar.radius,
                      "Radius R of the bar at its ends [m].",
                      Patterns::Double(0.));
    prm.add_parameter("Length",
                      round_bar.length,
                      "Length L of the bar [m]; axis along x in [0, L]. "
                      "Boundary ids: 0 = hull, 1 = end x = 0, 2 = end x = L; "
                      "material id 0.",
                      Patterns::Double(0.));
    prm.add_parameter("Imperfection",
                      round_bar.imperfection,
                      "Relative reduction of the radius at mid-length "
                      "(linear taper from the ends), e.g. 0.018 for "
                      "0.982 R [-].",
                      Patterns::Double(0., 0.5));
    prm.add_parameter("Axial subdivisions",
                      round_bar.axial_subdivisions,
                      "Coarse cells along the axis (before Refinements).",
                      Patterns::Integer(1));
    prm.add_parameter("Refinements",
                      round_bar.refinements,
                      "Uniform refinements of the coarse cylinder (5 cells "
                      "per cross-section): 5 * 4^r cells per cross-section, "
                      "Axial subdivisions * 2^r along the axis. The hull is "
                      "the exact tapered surface at every level (also for "
                      "Mesh/Global refinements and refinement boxes), and "
                      "the cells are curved to the element degree.",
                      Patterns::Integer(0, 5));
    add_option(
      prm,
      "Model",
      round_bar.model,
      round_bar_model_names(),
      "'full': the whole bar, boundary ids 0 = hull, 1 = end x = 0, 2 = end "
      "x = L. 'octant': the eighth x >= L/2, y >= 0, z >= 0 (needs "
      "Refinements >= 1; the cells are those of the full bar), boundary ids "
      "0 = hull, 2 = end x = L, 3 = plane x = L/2, 4 = plane y = 0, 5 = "
      "plane z = 0: with symmetry conditions on 3, 4, 5 it is the full bar "
      "pulled at both ends by twice the end displacement, carrying 4 times "
      "the end force, without the stress singularity of clamped ends.");
    prm.leave_subsection();

    prm.enter_subsection("Gmsh");
    prm.add_parameter(
      "File name",
      gmsh.file_name,
      "Gmsh .msh file (format 2.2 or 4.1, hexahedra; "
      "quadrilaterals in the x-y plane in 2-D, with physical "
      "surfaces as bodies and physical curves as boundaries); a "
      "relative name is read from the folder of the input "
      "file, wherever the program is started (parameters.prm "
      "in the results records it as an absolute path).",
      Patterns::Anything());
    prm.add_parameter(
      "Curved boundaries",
      gmsh.curved_boundaries_text,
      "Boundaries of the mesh that are curved, separated by ';': "
      "'id : centre' for a circle (2-D) or a sphere (3-D) around the "
      "point centre, or 'id : point : direction' for a cylinder (3-D) "
      "whose axis runs through the point along the direction, e.g. "
      "'4 : 0, 1' (2-D) or '4 : 0, 1, 0 : 0, 0, 1' (3-D). Every vertex of "
      "the boundary must lie on the surface. Its faces then follow the "
      "surface under refinement, and the mapping (MappingQ of the "
      "elements' degree) places the mid-side nodes on it. Without this "
      "entry a curved boundary is the polygon of its vertices with its "
      "mid-side nodes on the chords, h^2/(8R) inside a circle of radius "
      "R, which contact feels as a pressure that alternates between "
      "vertex and mid-side nodes (doc/contact.md, section 12). Empty: "
      "none.",
      Patterns::Anything());
    prm.leave_subsection();
  }



  namespace
  {
    Point<dim>
    parse_point(const std::string &text, const std::string &entry)
    {
      const auto coords =
        Utilities::split_string_list(Utilities::trim(text), ',');
      check_input(coords.size() == dim,
                  entry,
                  text,
                  "a point needs " + vector_size_word() +
                    " comma-separated coordinates");
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        try
          {
            p[d] = Utilities::string_to_double(coords[d]);
          }
        catch (...)
          {
            throw InputError(entry, text, "coordinates must be numbers");
          }
      return p;
    }
  } // namespace



  namespace
  {
    /// One entry 'id : centre' or 'id : point : direction' of
    /// Mesh/Gmsh/Curved boundaries.
    MeshParameters::CurvedBoundary
    parse_curved_boundary(const std::string &text)
    {
      const std::string entry = "Mesh/Gmsh/Curved boundaries";
      const auto        parts = Utilities::split_string_list(text, ':');
      check_input(parts.size() == 2 || (dim == 3 && parts.size() == 3),
                  entry,
                  text,
                  dim == 2 ? "each curved boundary must read 'id : x, y' (a "
                             "circle around the point)"
                           : "each curved boundary must read 'id : x, y, z' "
                             "(a sphere) or 'id : x, y, z : dx, dy, dz' (a "
                             "cylinder around the axis through the point)");
      for (unsigned int k = 1; k < parts.size(); ++k)
        check_input(Utilities::split_string_list(parts[k], ',').size() == dim,
                    entry,
                    text,
                    "a point or a direction needs " + vector_size_word() +
                      " comma-separated coordinates");
      MeshParameters::CurvedBoundary b;
      b.text = text;
      int id = -1;
      try
        {
          id = Utilities::string_to_int(parts[0]);
        }
      catch (...)
        {
        }
      check_input(id >= 0,
                  entry,
                  text,
                  "the boundary id must be a non-negative integer");
      b.boundary_id = static_cast<unsigned int>(id);
      b.centre      = parse_point(parts[1], entry);
      if (parts.size() == 3)
        {
          b.axis = parse_point(parts[2], entry);
          check_input(b.axis.norm() > 0.,
                      entry,
                      text,
                      "the cylinder's axis direction must not be zero");
        }
      return b;
    }
  } // namespace



  void
  MeshParameters::check()
  {
    const std::string boxes_entry = "Mesh/Local refinement boxes";
    refinement_boxes.clear();
    for (const std::string &box_text :
         Utilities::split_string_list(refinement_boxes_text, ';'))
      {
        if (Utilities::trim(box_text).empty())
          continue;
        const auto parts = Utilities::split_string_list(box_text, ':');
        check_input(parts.size() == 3,
                    boxes_entry,
                    box_text,
                    dim == 2 ? "each box must read 'x0,y0 : x1,y1 : n'"
                             : "each box must read 'x0,y0,z0 : x1,y1,z1 : n'");
        RefinementBox b;
        b.lower    = parse_point(parts[0], boxes_entry);
        b.upper    = parse_point(parts[1], boxes_entry);
        int levels = -1;
        try
          {
            levels = Utilities::string_to_int(parts[2]);
          }
        catch (...)
          {
          }
        check_input(levels >= 1 && levels <= 8,
                    boxes_entry,
                    box_text,
                    "the number of extra refinements must be an integer "
                    "between 1 and 8");
        b.levels = levels;
        for (unsigned int d = 0; d < dim; ++d)
          check_input(b.lower[d] < b.upper[d],
                      boxes_entry,
                      box_text,
                      "the lower corner must be below the upper corner in "
                      "every coordinate");
        refinement_boxes.push_back(b);
      }

    if (adaptive.enabled)
      check_input(adaptive.phase_field_threshold > 0. ||
                    adaptive.hardening_threshold > 0.,
                  "Mesh/Adaptive refinement/Enabled",
                  "true",
                  "a Phase-field threshold or a Hardening threshold above 0 "
                  "(what the refinement follows)");

    if (scene == SceneType::box)
      for (unsigned int d = 0; d < dim; ++d)
        check_input(box.lower_corner[d] < box.upper_corner[d],
                    "Mesh/Box/Upper corner",
                    Utilities::to_string(box.upper_corner[d]),
                    "the upper corner must exceed the lower corner (" +
                      Utilities::to_string(box.lower_corner[d]) +
                      ") in every coordinate");

    check_input(dim == 3 || scene != SceneType::round_bar,
                "Mesh/Scene",
                name_of(scene_names(), scene),
                "'round bar' is a three-dimensional scene; with Dimension = 2 "
                "use 'box', 'two bodies' or 'gmsh'");

    if (scene == SceneType::two_bodies)
      {
        for (unsigned int d = 0; d < dim; ++d)
          check_input(two_bodies.plate_size[d] > 0.,
                      "Mesh/Two bodies/Plate size",
                      Utilities::to_string(two_bodies.plate_size[d]),
                      "all plate dimensions must be positive");
        check_input(two_bodies.block_edge > 0.,
                    "Mesh/Two bodies/Block edge",
                    Utilities::to_string(two_bodies.block_edge),
                    "the block edge must be positive");
      }

    if (scene == SceneType::round_bar)
      {
        check_input(round_bar.radius > 0. && round_bar.length > 0.,
                    "Mesh/Round bar/Radius",
                    Utilities::to_string(round_bar.radius) + " (Length " +
                      Utilities::to_string(round_bar.length) + ")",
                    "radius and length must be positive");
        check_input(round_bar.model == RoundBarModel::full ||
                      round_bar.refinements >= 1,
                    "Mesh/Round bar/Refinements",
                    Utilities::to_string(round_bar.refinements),
                    "Model = octant needs at least 1 (the coarse cylinder's "
                    "cells straddle the symmetry planes)");
      }

    if (scene == SceneType::gmsh)
      {
        check_input(!gmsh.file_name.empty(),
                    "Mesh/Gmsh/File name",
                    gmsh.file_name,
                    "scene 'gmsh' needs the name of a .msh file");
        std::ifstream in(gmsh.file_name);
        check_input(static_cast<bool>(in),
                    "Mesh/Gmsh/File name",
                    gmsh.file_name,
                    "this file cannot be opened (it must exist and be "
                    "readable; a relative name is read from the folder of "
                    "the input file)");
      }
    gmsh.curved_boundaries.clear();
    for (const std::string &text :
         Utilities::split_string_list(gmsh.curved_boundaries_text, ';'))
      if (!Utilities::trim(text).empty())
        {
          gmsh.curved_boundaries.push_back(parse_curved_boundary(text));
          for (unsigned int k = 0; k + 1 < gmsh.curved_boundaries.size(); ++k)
            check_input(gmsh.curved_boundaries[k].boundary_id !=
                          gmsh.curved_boundaries.back().boundary_id,
                        "Mesh/Gmsh/Curved boundaries",
                        gmsh.curved_boundaries_text,
                        "each boundary id may be given once (" +
                          std::to_string(
                            gmsh.curved_boundaries.back().boundary_id) +
                          " is given twice)");
        }
    check_input(gmsh.curved_boundaries.empty() || scene == SceneType::gmsh,
                "Mesh/Gmsh/Curved boundaries",
                gmsh.curved_boundaries_text,
                "curved boundaries are read for Scene = gmsh only");
  }
} // namespace DuctileContact
