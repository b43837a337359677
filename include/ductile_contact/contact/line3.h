#pragma once

#include <ductile_contact/core/types.h>

// The face of a plane-strain cell: the 3-D build has no use for it and
// compiles this header (and line3.cc) empty; its faces are Quad9.
#if DUCTILE_CONTACT_DIM == 2
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>

namespace DuctileContact
{
  /**
   * A 3-node quadratic curve x(xi) = sum_i N_i(xi) x_i, xi in [0, 1]: the
   * face of an FE_Q(2) quadrilateral of the plane-strain build in the
   * current configuration, the 2-D counterpart of Quad9 (with the same
   * members, one parameter instead of two). Node a in {0, 1, 2} sits at xi
   * = a/2 (end, middle, end: the 1-D factor of Quad9's order), with the
   * quadratic Lagrange polynomials
   *   N_0 = 2 (xi - 1/2)(xi - 1), N_1 = 4 xi (1 - xi), N_2 = 2 xi (xi - 1/2).
   * The tangent is t = x_xi = sum_i N_i' x_i and the normal the tangent
   * turned by -90 degrees, n = c/|c| with
   *   c = R t = (t_y, -t_x),   R = [[0, 1], [-1, 0]],
   * the 2-D analogue of x_xi x x_eta. The nodes are ordered so that the
   * body lies on the left of increasing xi; n then points out of the body.
   */
  struct Line3
  {
    /// Number of nodes, the middle node and the two end nodes.
    static constexpr unsigned int                n_nodes     = 3;
    static constexpr unsigned int                centre_node = 1;
    static constexpr std::array<unsigned int, 2> vertices{{0, 2}};

    /// Parameter point of the centre node.
    static dealii::Point<1>
    centre()
    {
      return dealii::Point<1>(0.5);
    }

    std::array<dealii::Point<dim>, 3> x;

    /// Lagrange shape functions N_i(xi) and their derivatives.
    static void
    shape(const dealii::Point<1> &xi,
          std::array<double, 3>  &values,
          std::array<double, 3>  *d_xi = nullptr);

    dealii::Point<dim>
    position(const dealii::Point<1> &xi) const;

    /// Tangent x_xi at @p xi (an array of one, as Quad9's two).
    std::array<dealii::Tensor<1, dim>, 1>
    tangents(const dealii::Point<1> &xi) const;

    /// Outward unit normal at @p xi: n = R x_xi / |x_xi|.
    dealii::Tensor<1, dim>
    normal(const dealii::Point<1> &xi) const;

    /// Derivatives of normal(@p xi) with respect to the node positions:
    /// entry [i][r][m] = d n_r / d x_i,m = N_i'(xi) ((I - n n) R)_rm / |c|.
    std::array<dealii::Tensor<2, dim>, 3>
    normal_derivatives(const dealii::Point<1> &xi) const;

    /// The parameter point where the line p + t d meets the curve (Newton
    /// on (xi, t) from @p start, Jacobian [x_xi | -d]); returns false if
    /// Newton does not converge or the line is parallel to the curve.
    bool
    project_along(const dealii::Point<dim>     &p,
                  const dealii::Tensor<1, dim> &d,
                  const dealii::Point<1>       &start,
                  dealii::Point<1>             &xi) const;

    /// shape() in a number type that may carry derivatives.
    template <typename Number>
    static void
    shape_of(const std::array<Number, 1> &xi, std::array<Number, 3> &values)
    {
      const Number &t = xi[0];
      values[0]       = 2. * (t - 0.5) * (t - 1.);
      values[1]       = 4. * t * (1. - t);
      values[2]       = 2. * t * (t - 0.5);
    }

    /// Parameter point of node @p i.
    static dealii::Point<1>
    node_parameter(const unsigned int i)
    {
      return dealii::Point<1>(0.5 * i);
    }
  };
} // namespace DuctileContact
#endif
