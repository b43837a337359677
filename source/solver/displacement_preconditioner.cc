// The approximate inverse of the displacement block in the Krylov solvers:
// AMG, or AMG on the Schur complement of the constrained components
// (displacement_preconditioner.h).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <ductile_contact/solver/amg.h>
#include <ductile_contact/solver/displacement_preconditioner.h>

#include <EpetraExt_MatrixMatrix.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_MpiComm.h>
#include <Epetra_Vector.h>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace DuctileContact
{
  using namespace dealii;

  /**
   * The rotated block and its split (displacement_preconditioner.h): the
   * nodal frames of the owned constrained nodes, the couplings A_rc and
   * W C_cr, the pivots W, and the Schur complement S whose AMG is the
   * preconditioner's.
   */
  class DisplacementPreconditioner::Elimination
  {
  public:
    Elimination(const Epetra_CrsMatrix &A, const ConstrainedNodes &nodes);

    /// S, on A's maps.
    const Epetra_CrsMatrix &
    schur() const
    {
      return *schur_matrix;
    }

    /// The near-null space @p modes in the frames, zero on c.
    std::unique_ptr<Epetra_MultiVector>
    rotated_modes(const Epetra_MultiVector &modes) const;

    /// The steps of vmult() around the AMG: @p b := Q b, and b_r - A_rc W
    /// b_c in @p rest_rhs (0 on c); then from x_r in @p x the whole x, and
    /// x := Q^T x.
    void
    before(Epetra_MultiVector &b, Epetra_MultiVector &rest_rhs) const;
    void
    after(Epetra_MultiVector &x) const;

    /// Multiplies the entries of c by 0.
    void
    clear_constrained(Epetra_MultiVector &v) const
    {
      v.Multiply(1., *rest, v, 0.);
    }

    unsigned int n_eliminated = 0;

  private:
    /// v := Q v (forward) or Q^T v on the owned nodes.
    void
    rotate(Epetra_MultiVector &v, bool forward) const;

    /// (node, component) of every DoF of @p nodes, by global number.
    using NodeOfDof =
      std::unordered_map<int, std::pair<unsigned int, unsigned int>>;

    /// Q A Q^T with A's pattern (an entry the pattern lacks is dropped).
    std::unique_ptr<Epetra_CrsMatrix>
    rotated_matrix(const Epetra_CrsMatrix &A,
                   const ConstrainedNodes &nodes,
                   const NodeOfDof        &node_of) const;

    /// The owned nodes: their frames and row numbers (local).
    std::vector<const ConstrainedNode *> owned;
    std::vector<std::vector<int>>        owned_rows;

    std::unique_ptr<Epetra_CrsMatrix>      coupling_rc;  // A_rc
    std::unique_ptr<Epetra_CrsMatrix>      coupling_cr;  // W C_cr
    std::unique_ptr<Epetra_CrsMatrix>      schur_matrix; // S
    std::unique_ptr<Epetra_Vector>         pivots, rest; // W on c; 1 on r
    mutable std::unique_ptr<Epetra_Vector> y, product;
  };



  DisplacementPreconditioner::Elimination::Elimination(
    const Epetra_CrsMatrix &A,
    const ConstrainedNodes &nodes)
  {
    const Epetra_Map &rows    = A.RowMap();
    const Epetra_Map &columns = A.ColMap();
    for (const ConstrainedNode &node : nodes)
      if (rows.LID(static_cast<int>(node.dofs[0])) >= 0)
        {
          owned.push_back(&node);
          std::vector<int> lids;
          for (const auto dof : node.dofs)
            {
              lids.push_back(rows.LID(static_cast<int>(dof)));
              AssertThrow(lids.back() >= 0,
                          ExcMessage("a constrained node's DoFs lie on "
                                     "more than one rank"));
            }
          owned_rows.push_back(lids);
        }

    // Which columns (and owned rows) are constrained components: the
    // first n_constrained of each node, in its frame.
    NodeOfDof node_of;
    for (unsigned int m = 0; m < nodes.size(); ++m)
      for (unsigned int k = 0; k < nodes[m].dofs.size(); ++k)
        node_of[static_cast<int>(nodes[m].dofs[k])] = {m, k};
    const auto is_c = [&](const int gid) {
      const auto it = node_of.find(gid);
      return it != node_of.end() &&
             it->second.second < nodes[it->second.first].n_constrained;
    };
    std::vector<bool> c_column(columns.NumMyElements());
    for (int l = 0; l < columns.NumMyElements(); ++l)
      c_column[l] = is_c(columns.GID(l));

    std::unique_ptr<Epetra_CrsMatrix> rotated =
      rotated_matrix(A, nodes, node_of);

    pivots      = std::make_unique<Epetra_Vector>(rows);
    rest        = std::make_unique<Epetra_Vector>(rows);
    y           = std::make_unique<Epetra_Vector>(rows);
    product     = std::make_unique<Epetra_Vector>(rows);
    coupling_rc = std::make_unique<Epetra_CrsMatrix>(Copy, rows, 0);
    coupling_cr = std::make_unique<Epetra_CrsMatrix>(Copy, rows, 0);
    std::vector<int>    gids;
    std::vector<double> values;
    for (int row = 0; row < rows.NumMyElements(); ++row)
      {
        const int  gid = rows.GID(row);
        const bool c   = is_c(gid);
        int        n   = 0;
        double    *v   = nullptr;
        int       *l   = nullptr;
        rotated->ExtractMyRowView(row, n, v, l);
        double diagonal = 0.;
        gids.clear();
        values.clear();
        for (int e = 0; e < n; ++e)
          {
            if (columns.GID(l[e]) == gid)
              diagonal = v[e];
            // Row r: its entries in c columns (A_rc); row c: those in r
            // columns (C_cr).
            if (c_column[l[e]] != c && v[e] != 0.)
              {
                gids.push_back(columns.GID(l[e]));
                values.push_back(v[e]);
              }
          }
        (*rest)[row] = c ? 0. : 1.;
        if (c)
          {
            ++n_eliminated;
            // A constraint row without a pivot leaves its component at 0.
            (*pivots)[row] = diagonal != 0. ? 1. / diagonal : 0.;
            for (double &value : values)
              value *= (*pivots)[row];
          }
        if (!gids.empty())
          (c ? coupling_cr : coupling_rc)
            ->InsertGlobalValues(gid,
                                 static_cast<int>(gids.size()),
                                 values.data(),
                                 gids.data());
        // What S keeps of the rotated matrix: A_rr, and 1 on c's diagonal.
        for (int e = 0; e < n; ++e)
          if (c)
            v[e] = (columns.GID(l[e]) == gid) ? 1. : 0.;
          else if (c_column[l[e]])
            v[e] = 0.;
      }
    coupling_rc->FillComplete(A.DomainMap(), A.RangeMap());
    coupling_cr->FillComplete(A.DomainMap(), A.RangeMap());
    n_eliminated = Utilities::MPI::sum(
      n_eliminated, dynamic_cast<const Epetra_MpiComm &>(rows.Comm()).Comm());

    // S = A_rr - A_rc (W C_cr).
    Epetra_CrsMatrix correction(Copy, rows, 0);
    AssertThrow(EpetraExt::MatrixMatrix::Multiply(
                  *coupling_rc, false, *coupling_cr, false, correction) == 0,
                ExcMessage("the product A_rc W C_cr failed"));
    Epetra_CrsMatrix *S = nullptr;
    AssertThrow(EpetraExt::MatrixMatrix::Add(
                  *rotated, false, 1., correction, false, -1., S) == 0,
                ExcMessage("the sum A_rr - A_rc W C_cr failed"));
    schur_matrix.reset(S);
    schur_matrix->FillComplete(A.DomainMap(), A.RangeMap());
  }



  std::unique_ptr<Epetra_CrsMatrix>
  DisplacementPreconditioner::Elimination::rotated_matrix(
    const Epetra_CrsMatrix &A,
    const ConstrainedNodes &nodes,
    const NodeOfDof        &node_of) const
  {
    auto              rotated = std::make_unique<Epetra_CrsMatrix>(A);
    const Epetra_Map &columns = A.ColMap();
    // A Q^T: in every row, the entries of a constrained node's columns
    // (its components, by local column) are turned into its frame.
    std::vector<int> column_node(columns.NumMyElements(), -1),
      column_component(columns.NumMyElements(), 0);
    for (int l = 0; l < columns.NumMyElements(); ++l)
      if (const auto it = node_of.find(columns.GID(l)); it != node_of.end())
        {
          column_node[l]      = static_cast<int>(it->second.first);
          column_component[l] = static_cast<int>(it->second.second);
        }
    // (node, component, entry) of a row's constrained-node entries.
    std::vector<std::tuple<int, int, int>> hits;
    for (int row = 0; row < rotated->NumMyRows(); ++row)
      {
        int     n = 0;
        double *v = nullptr;
        int    *l = nullptr;
        rotated->ExtractMyRowView(row, n, v, l);
        hits.clear();
        for (int e = 0; e < n; ++e)
          if (column_node[l[e]] >= 0)
            hits.emplace_back(column_node[l[e]], column_component[l[e]], e);
        std::sort(hits.begin(), hits.end());
        for (std::size_t h = 0; h < hits.size();)
          {
            const int           m  = std::get<0>(hits[h]);
            const auto         &Q  = nodes[m].frame;
            const unsigned int  nc = nodes[m].dofs.size();
            std::vector<int>    entry(nc, -1);
            std::vector<double> value(nc, 0.);
            for (; h < hits.size() && std::get<0>(hits[h]) == m; ++h)
              {
                entry[std::get<1>(hits[h])] = std::get<2>(hits[h]);
                value[std::get<1>(hits[h])] = v[std::get<2>(hits[h])];
              }
            for (unsigned int k = 0; k < nc; ++k)
              if (entry[k] >= 0)
                {
                  double sum = 0.;
                  for (unsigned int c = 0; c < nc; ++c)
                    sum += Q[k * nc + c] * value[c];
                  v[entry[k]] = sum;
                }
          }
      }
    // Q (A Q^T): the rows of each owned node, combined; an entry that one
    // of them lacks in its pattern is dropped.
    for (unsigned int m = 0; m < owned.size(); ++m)
      {
        const auto                                  &Q  = owned[m]->frame;
        const unsigned int                           nc = owned_rows[m].size();
        std::unordered_map<int, std::vector<double>> sums;
        std::vector<int>                             n(nc);
        std::vector<double *>                        v(nc);
        std::vector<int *>                           l(nc);
        for (unsigned int c = 0; c < nc; ++c)
          rotated->ExtractMyRowView(owned_rows[m][c], n[c], v[c], l[c]);
        for (unsigned int c = 0; c < nc; ++c)
          for (int e = 0; e < n[c]; ++e)
            {
              auto &sum = sums[l[c][e]];
              sum.resize(nc, 0.);
              for (unsigned int k = 0; k < nc; ++k)
                sum[k] += Q[k * nc + c] * v[c][e];
            }
        for (unsigned int k = 0; k < nc; ++k)
          for (int e = 0; e < n[k]; ++e)
            v[k][e] = sums[l[k][e]][k];
      }
    return rotated;
  }



  void
  DisplacementPreconditioner::Elimination::rotate(Epetra_MultiVector &v,
                                                  const bool forward) const
  {
    for (unsigned int m = 0; m < owned.size(); ++m)
      {
        const auto        &Q  = owned[m]->frame;
        const auto        &r  = owned_rows[m];
        const unsigned int nc = r.size();
        for (int i = 0; i < v.NumVectors(); ++i)
          {
            double             *values = v[i];
            std::vector<double> in(nc), out(nc, 0.);
            for (unsigned int c = 0; c < nc; ++c)
              in[c] = values[r[c]];
            for (unsigned int k = 0; k < nc; ++k)
              for (unsigned int c = 0; c < nc; ++c)
                {
                  if (forward)
                    out[k] += Q[k * nc + c] * in[c];
                  else
                    out[c] += Q[k * nc + c] * in[k];
                }
            for (unsigned int c = 0; c < nc; ++c)
              values[r[c]] = out[c];
          }
      }
  }



  std::unique_ptr<Epetra_MultiVector>
  DisplacementPreconditioner::Elimination::rotated_modes(
    const Epetra_MultiVector &modes) const
  {
    auto rotated = std::make_unique<Epetra_MultiVector>(modes);
    rotate(*rotated, true);
    for (int i = 0; i < rotated->NumVectors(); ++i)
      (*rotated)(i)->Multiply(1., *rest, *(*rotated)(i), 0.);
    return rotated;
  }



  void
  DisplacementPreconditioner::Elimination::before(
    Epetra_MultiVector &b,
    Epetra_MultiVector &rest_rhs) const
  {
    rotate(b, true);
    // y = W b_c; r_r - A_rc y.
    y->Multiply(1., *pivots, b, 0.);
    coupling_rc->Multiply(false, *y, *product);
    rest_rhs.Update(1., b, -1., *product, 0.);
    clear_constrained(rest_rhs);
  }



  void
  DisplacementPreconditioner::Elimination::after(Epetra_MultiVector &x) const
  {
    // x_c = W b_c - W C_cr x_r (y holds W b_c from before()).
    clear_constrained(x);
    coupling_cr->Multiply(false, x, *product);
    x.Update(1., *y, -1., *product, 1.);
    rotate(x, false);
  }



  DisplacementPreconditioner::DisplacementPreconditioner()  = default;
  DisplacementPreconditioner::~DisplacementPreconditioner() = default;



  void
  DisplacementPreconditioner::initialize(
    const TrilinosWrappers::SparseMatrix &A,
    const ConstrainedNodes               *nodes,
    const LinearSolverParameters         &parameters,
    const unsigned int                    degree,
    const Epetra_MultiVector             *modes)
  {
    elimination.reset();
    if (parameters.constrained_rows == ConstrainedRows::eliminate && nodes &&
        !nodes->empty())
      {
        elimination =
          std::make_unique<Elimination>(A.trilinos_matrix(), *nodes);
        const auto rotated =
          modes ? elimination->rotated_modes(*modes) : nullptr;
        initialize_amg(elimination->schur(),
                       amg,
                       parameters,
                       degree,
                       parameters.aggregation_threshold,
                       rotated.get());
        rotated_rhs.reinit(A.locally_owned_range_indices(),
                           A.get_mpi_communicator());
        rest_rhs.reinit(rotated_rhs);
        return;
      }
    initialize_amg(
      A, amg, parameters, degree, parameters.aggregation_threshold, modes);
  }



  void
  DisplacementPreconditioner::vmult(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!elimination)
      {
        amg.vmult(dst, src);
        return;
      }
    rotated_rhs = src;
    elimination->before(rotated_rhs.trilinos_vector(),
                        rest_rhs.trilinos_vector());
    amg.vmult(dst, rest_rhs);
    elimination->after(dst.trilinos_vector());
  }



  unsigned int
  DisplacementPreconditioner::n_eliminated() const
  {
    return elimination ? elimination->n_eliminated : 0;
  }
} // namespace DuctileContact
