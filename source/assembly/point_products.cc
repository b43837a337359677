#include <ductile_contact/assembly/point_products.h>

#include <algorithm>

namespace DuctileContact
{
  using namespace dealii;

  void
  PointProducts::reinit(const unsigned int n_rows,
                        const unsigned int n_cols,
                        const unsigned int n_q,
                        const unsigned int rank)
  {
    this->rank = rank;
    // reinit() zeroes: a point that is skipped (J <= 0) adds nothing.
    L.reinit(n_q * rank, n_rows);
    R.reinit(n_q * rank, n_cols);
    used = false;
  }



  void
  PointProducts::set_scaled(const unsigned int         q,
                            const unsigned int         r,
                            const double               scale,
                            const std::vector<double> &left_values,
                            const std::vector<double> &right_values)
  {
    if (left_values.empty() || right_values.empty())
      return;
    double *l = left(q, r);
    for (unsigned int i = 0; i < left_values.size(); ++i)
      l[i] = scale * left_values[i];
    std::copy(right_values.begin(), right_values.end(), right(q, r));
  }



  void
  PointProducts::add_to(const std::vector<unsigned int> &row_dofs,
                        const std::vector<unsigned int> &col_dofs,
                        FullMatrix<double>              &matrix)
  {
    if (!used || row_dofs.empty() || col_dofs.empty())
      return;
    product.reinit(row_dofs.size(), col_dofs.size(), true);
    L.Tmmult(product, R);
    for (unsigned int i = 0; i < row_dofs.size(); ++i)
      for (unsigned int j = 0; j < col_dofs.size(); ++j)
        matrix(row_dofs[i], col_dofs[j]) += product(i, j);
  }



  void
  CellTangentBlocks::reinit(const LocalDofs &dofs, const unsigned int n_q)
  {
    const unsigned int n_u = dofs.u.size(), n_a = dofs.alpha.size(),
                       n_s = dofs.s.size();
    for (unsigned int c = 0; c < dim; ++c)
      u_u[c].reinit(n_u, dofs.u_by_component[c].size(), n_q, dim);
    u_alpha.reinit(n_u, n_a, n_q, 1);
    u_s.reinit(n_u, n_s, n_q, 1);
    alpha_u.reinit(n_a, n_u, n_q, 1);
    alpha_alpha.reinit(n_a, n_a, n_q, 1 + dim);
    alpha_s.reinit(n_a, n_s, n_q, 1);
    s_u.reinit(n_s, n_u, n_q, 1);
    s_alpha.reinit(n_s, n_a, n_q, 1);
    s_s.reinit(n_s, n_s, n_q, 1);
  }



  void
  CellTangentBlocks::add_to(const LocalDofs &dofs, FullMatrix<double> &matrix)
  {
    for (unsigned int c = 0; c < dim; ++c)
      u_u[c].add_to(dofs.u, dofs.u_by_component[c], matrix);
    u_alpha.add_to(dofs.u, dofs.alpha, matrix);
    u_s.add_to(dofs.u, dofs.s, matrix);
    alpha_u.add_to(dofs.alpha, dofs.u, matrix);
    alpha_alpha.add_to(dofs.alpha, dofs.alpha, matrix);
    alpha_s.add_to(dofs.alpha, dofs.s, matrix);
    s_u.add_to(dofs.s, dofs.u, matrix);
    s_alpha.add_to(dofs.s, dofs.alpha, matrix);
    s_s.add_to(dofs.s, dofs.s, matrix);
  }
} // namespace DuctileContact
