#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ductile_contact/core/option.h>
#include <ductile_contact/core/types.h>

#include <string>
#include <vector>

namespace DuctileContact
{
  /// A box of cells (all cells whose centre lies inside) refined n more times.
  struct RefinementBox
  {
    dealii::Point<dim> lower;
    dealii::Point<dim> upper;
    unsigned int       levels = 0;
  };

  /// Mesh/Scene: which builder makes the coarse mesh.
  enum class SceneType
  {
    box,
    two_bodies,
    round_bar,
    gmsh
  };

  inline const NameTable<SceneType> &
  scene_names()
  {
    static const NameTable<SceneType> t{{SceneType::box, "box"},
                                        {SceneType::two_bodies, "two bodies"},
                                        {SceneType::round_bar, "round bar"},
                                        {SceneType::gmsh, "gmsh"}};
    return t;
  }

  /// Mesh/Round bar/Model.
  enum class RoundBarModel
  {
    full,
    octant
  };

  inline const NameTable<RoundBarModel> &
  round_bar_model_names()
  {
    static const NameTable<RoundBarModel> t{{RoundBarModel::full, "full"},
                                            {RoundBarModel::octant, "octant"}};
    return t;
  }

  /**
   * Parameters of subsection `Mesh`: which scene builds the coarse mesh and
   * how it is refined. All lengths are in metres.
   */
  struct MeshParameters
  {
    SceneType scene = SceneType::box;

    unsigned int global_refinements = 0;

    /// Raw text of `Local refinement boxes`; parsed into refinement_boxes.
    std::string                refinement_boxes_text;
    std::vector<RefinementBox> refinement_boxes;

    struct Box
    {
      dealii::Point<dim>        lower_corner;
      dealii::Point<dim>        upper_corner = unit_corner();
      std::vector<unsigned int> subdivisions =
        std::vector<unsigned int>(dim, 1);

      /// (1, 1, 1), or (1, 1) in 2-D.
      static dealii::Point<dim>
      unit_corner()
      {
        dealii::Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = 1.;
        return p;
      }
    } box;

    /// Plate + block of the paper's scene (doc/model.md section 7); in
    /// plane strain a strip [0, Lx] x [0, Ly] and a square block above it.
    struct TwoBodies
    {
#if DUCTILE_CONTACT_DIM == 3
      dealii::Point<dim>        plate_size{0.3, 0.2, 0.02};
      std::vector<unsigned int> plate_subdivisions{19, 13, 2};
      double                    block_edge = 0.04;
      std::vector<unsigned int> block_subdivisions{5, 5, 5};
      /// In-plane (x, y) position of the block's centre.
      std::vector<double> block_centre{0.035, 0.1};
#else
      dealii::Point<dim>        plate_size{0.3, 0.02};
      std::vector<unsigned int> plate_subdivisions{19, 2};
      double                    block_edge = 0.04;
      std::vector<unsigned int> block_subdivisions{5, 5};
      /// Position x of the block's centre.
      std::vector<double> block_centre{0.035};
#endif
      /// Vertical gap between the plate's top and the block's bottom [m].
      double block_gap = 0.;
    } two_bodies;

    /// Round bar of validation rung 3 (necking), axis along x; 3-D only.
    struct RoundBar
    {
      double        radius             = 6.413e-3;
      double        length             = 53.334e-3;
      double        imperfection       = 0.018;
      unsigned int  axial_subdivisions = 10;
      unsigned int  refinements        = 1;
      RoundBarModel model              = RoundBarModel::full;
    } round_bar;

    /// A boundary of a Gmsh mesh that is a circle (2-D) or a sphere (3-D)
    /// around @p centre, or (3-D) a cylinder whose axis runs through
    /// @p centre along @p axis: its faces get that manifold, so that the
    /// mapping and the refinement follow the curve to the order of the
    /// elements instead of its chords.
    struct CurvedBoundary
    {
      unsigned int           boundary_id = 0;
      dealii::Point<dim>     centre;
      dealii::Tensor<1, dim> axis; ///< zero: a circle or a sphere
      std::string            text; ///< as given, for error messages
    };

    struct Gmsh
    {
      std::string file_name;
      /// `Curved boundaries` as given; parsed by check().
      std::string                 curved_boundaries_text;
      std::vector<CurvedBoundary> curved_boundaries;
    } gmsh;

    /// Subsection `Adaptive refinement`: cells refined during the run
    /// where the crack or the plastic zone calls for it (MeshAdaptation).
    struct AdaptiveRefinement
    {
      bool enabled = false;
      /// Refine where s exceeds it at a DoF of the cell; 0: not by s.
      double phase_field_threshold = 0.;
      /// Refine where alpha exceeds it at a DoF of the cell; 0: not by
      /// alpha.
      double hardening_threshold = 0.;
      /// Cells are refined up to this level (the coarse mesh is level 0).
      unsigned int maximum_level = 3;
      /// No refinement beyond this many cells (0: no limit).
      unsigned int maximum_cells = 0;
      /// Refinements of one load step before it is accepted.
      unsigned int maximum_passes = 4;
    } adaptive;

    void
    declare(dealii::ParameterHandler &prm);

    /// Checks values and parses the refinement boxes; throws InputError.
    void
    check();

  private:
    /// The entries of subsection Adaptive refinement (in subsection Mesh).
    void
    declare_adaptive_refinement(dealii::ParameterHandler &prm);

    /// The subsections of the scenes (Box, Two bodies, Round bar, Gmsh).
    void
    declare_scenes(dealii::ParameterHandler &prm);
  };
} // namespace DuctileContact
