#pragma once

#include <deal.II/lac/full_matrix.h>

#include <ductile_contact/discretisation/discretisation.h>

#include <array>
#include <vector>

namespace DuctileContact
{
  /**
   * One block of a cell's tangent written as a sum over the cell's points
   * of products of point vectors,
   *   K(i, j) = sum_q sum_r L_{q r}(i) R_{q r}(j),
   * e.g. int N_i c N_j dV with L_q = c N JxW and R_q = N (rank 1), or
   * int Grad N_i . Grad N_j dV with one pair per direction (rank dim).
   * The row functions store L_{q r} and R_{q r} while the points are
   * visited; add_to() forms K = L^T R once per cell as one matrix product
   * (BLAS) instead of n_i n_j indexed additions per point.
   */
  class PointProducts
  {
  public:
    /// Zero for @p n_rows by @p n_cols entries, @p n_q points and
    /// @p rank pairs per point.
    void
    reinit(const unsigned int n_rows,
           const unsigned int n_cols,
           const unsigned int n_q,
           const unsigned int rank);

    /// L_{q r}, n_rows entries to fill.
    double *
    left(const unsigned int q, const unsigned int r)
    {
      used = true;
      return &L(q * rank + r, 0);
    }

    /// R_{q r}, n_cols entries to fill.
    double *
    right(const unsigned int q, const unsigned int r)
    {
      used = true;
      return &R(q * rank + r, 0);
    }

    /// The pair (@p scale @p left_values, @p right_values) as L_{q r} and
    /// R_{q r}: a term scale N_i M_j at point @p q. Nothing when either
    /// side has no DoFs (a field the cell does not carry).
    void
    set_scaled(const unsigned int         q,
               const unsigned int         r,
               const double               scale,
               const std::vector<double> &left_values,
               const std::vector<double> &right_values);

    /// Adds K to @p matrix in the rows @p row_dofs and the columns
    /// @p col_dofs (cell-local indices); nothing if no point wrote.
    void
    add_to(const std::vector<unsigned int> &row_dofs,
           const std::vector<unsigned int> &col_dofs,
           dealii::FullMatrix<double>      &matrix);

  private:
    dealii::FullMatrix<double> L, R, product;
    unsigned int               rank = 1;
    bool                       used = false;
  };

  /**
   * The blocks of one cell's tangent that its points add (the row
   * functions of cell_rows.h), each a PointProducts. The u-u block is
   * split by the component c of the columns, whose DoFs are then ordered
   * by node (LocalDofs::u_by_component), so that its right factor is the
   * gradients of the scalar shape functions (rank dim).
   */
  struct CellTangentBlocks
  {
    std::array<PointProducts, dim> u_u;
    PointProducts u_alpha, u_s, alpha_u, alpha_alpha, alpha_s, s_u, s_alpha,
      s_s;

    /// Zero for the fields of @p dofs and @p n_q points.
    void
    reinit(const LocalDofs &dofs, const unsigned int n_q);

    /// Adds every block to @p matrix (the element's numbering).
    void
    add_to(const LocalDofs &dofs, dealii::FullMatrix<double> &matrix);
  };
} // namespace DuctileContact
