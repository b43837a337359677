#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/discretisation.h>

#include <string>
#include <vector>

namespace DuctileContact
{
  /// The fields at one probe point: displacement [m], alpha and s [-]
  /// (0 in a body that does not carry them).
  struct ProbeValue
  {
    dealii::Tensor<1, dim> u;
    double                 alpha = 0., s = 0.;
  };

  /**
   * The fields at fixed material points (Output/Probe points, given in
   * the reference configuration): u(X_k) = sum_i N_i(X_k) u_i on the cell
   * that contains X_k. Each point is located once (setup()) on the rank
   * that owns a cell containing it (the lowest such rank if it lies on a
   * cell boundary); evaluate() returns the same values on every rank. For
   * comparisons with closed forms that need the motion of one point, e.g.
   * the mutual approach of two points on the axis of a contact.
   */
  class ProbePoints
  {
  public:
    explicit ProbePoints(const std::vector<dealii::Point<dim>> &points);

    /// Throws InputError naming Output/Probe points if one of @p points
    /// lies outside @p tria (its cells with straight edges); for
    /// --validate, on the coarse mesh.
    static void
    check_inside(const dealii::Triangulation<dim>      &tria,
                 const std::vector<dealii::Point<dim>> &points);

    /// Locates the points; throws InputError naming Output/Probe points if
    /// one lies outside the mesh.
    void
    setup(const Discretisation &discretisation);

    /// The fields at every point for the solution @p u (ghosted).
    std::vector<ProbeValue>
    evaluate(const dealii::TrilinosWrappers::MPI::BlockVector &u) const;

    std::size_t
    size() const
    {
      return points.size();
    }

  private:
    struct Location
    {
      bool                                          here = false;
      dealii::DoFHandler<dim>::active_cell_iterator cell;
      dealii::Point<dim>                            unit_point;
    };

    std::vector<dealii::Point<dim>> points;
    std::vector<Location>           locations;
    const Discretisation           *discretisation = nullptr;
  };
} // namespace DuctileContact
