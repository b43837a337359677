#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <ductile_contact/contact/contact_surface.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// Parents of a hanging node on a quad9 face: the three nodes of the
    /// coarse edge it lies on (a line3 face of a 2-D mesh has no hanging
    /// nodes: its ends are vertices of the coarse neighbour too).
    constexpr unsigned int max_parents = 3;
    /// Doubles per gathered node: 3 DoF indices, 3 reference coordinates
    /// (the last of each unused in 2-D), the number of parents and (DoF of
    /// the parent's x component, weight) for each.
    constexpr unsigned int node_record = 6 + 1 + 2 * max_parents;
    /// Doubles per gathered face: material id, then its nodes.
    constexpr unsigned int face_record = 1 + face_nodes * node_record;



    /// Appends the record of face @p f of @p cell (material id, then per
    /// node its DoFs, position and parents) to @p local.
    void
    append_face_record(const Discretisation &discretisation,
                       const DoFHandler<dim>::active_cell_iterator &cell,
                       const unsigned int                           f,
                       std::vector<types::global_dof_index>        &cell_dofs,
                       std::vector<double>                         &local)
    {
      const FiniteElement<dim> &fe   = cell->get_fe();
      const auto               &base = fe.base_element(0);
      if (base.degree != 2 ||
          base.dofs_per_cell != Utilities::fixed_power<dim>(3u))
        throw InputError("Finite elements/Polynomial degree",
                         std::to_string(base.degree),
                         "2 in a scene with contact (the mortar contact works "
                         "on the faces of quadratic cells: quad9, line3)");
      cell_dofs.resize(fe.n_dofs_per_cell());
      cell->get_dof_indices(cell_dofs);

      // Parameters of the face: the free cell coordinates in cyclic order
      // after the face's normal direction.
      const unsigned int d = f / 2, c1 = (d + 1) % dim;
#if DUCTILE_CONTACT_DIM == 3
      const unsigned int c2 = (d + 2) % 3;
#endif
      std::array<std::array<double, node_record>, face_nodes> node_data{};
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto ci = fe.system_to_component_index(i);
          if (ci.first != 0 || !fe.has_support_on_face(i, f))
            continue;
          const Point<dim>   p = base.unit_support_point(ci.second);
          const unsigned int a = std::lround(2. * p[c1]);
#if DUCTILE_CONTACT_DIM == 3
          const unsigned int b    = std::lround(2. * p[c2]);
          auto              &data = node_data[a + 3 * b];
#else
          auto &data = node_data[a];
#endif
          const Point<dim> X =
            discretisation.mapping[0].transform_unit_to_real_cell(cell, p);
          for (unsigned int c = 0; c < dim; ++c)
            {
              data[c] = static_cast<double>(
                cell_dofs[fe.component_to_system_index(c, ci.second)]);
              data[3 + c] = X[c];
            }
          const auto *parents =
            discretisation.hanging_node_constraints.get_constraint_entries(
              static_cast<types::global_dof_index>(data[0]));
          if (parents != nullptr)
            {
              AssertThrow(parents->size() <= max_parents, ExcInternalError());
              data[6] = parents->size();
              for (unsigned int p = 0; p < parents->size(); ++p)
                {
                  data[7 + 2 * p] = static_cast<double>((*parents)[p].first);
                  data[8 + 2 * p] = (*parents)[p].second;
                }
            }
        }
      // Orientation: the normal (x_xi x x_eta; x_xi turned by -90 degrees
      // in 2-D) must point out of the cell.
      ContactFace q;
      for (unsigned int n = 0; n < face_nodes; ++n)
        for (unsigned int c = 0; c < dim; ++c)
          q.x[n][c] = node_data[n][3 + c];
      const Tensor<1, dim> out = q.x[ContactFace::centre_node] - cell->center();
      if (q.normal(ContactFace::centre()) * out < 0.)
        {
#if DUCTILE_CONTACT_DIM == 3
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = a + 1; b < 3; ++b)
              std::swap(node_data[a + 3 * b], node_data[b + 3 * a]);
#else
          std::swap(node_data[0], node_data[2]);
#endif
        }
      local.push_back(cell->material_id());
      for (const auto &data : node_data)
        local.insert(local.end(), data.begin(), data.end());
    }
  } // namespace



  void
  ContactSurface::gather(const Discretisation    &discretisation,
                         const types::boundary_id id)
  {
    boundary_id             = id;
    const auto &dof_handler = discretisation.dof_handler;

    std::vector<double>                  local;
    std::vector<types::global_dof_index> cell_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            append_face_record(discretisation, cell, f, cell_dofs, local);

    const std::vector<std::vector<double>> all =
      Utilities::MPI::all_gather(dof_handler.get_communicator(), local);
    nodes.clear();
    faces.clear();
    std::map<types::global_dof_index, unsigned int> node_index;
    // Parent DoFs of each hanging node, numbered once every node is known.
    std::map<unsigned int, std::vector<std::pair<double, double>>> hanging;
    for (const auto &records : all)
      for (std::size_t r = 0; r + face_record <= records.size();
           r += face_record)
        {
          Face face;
          face.material_id = static_cast<types::material_id>(records[r]);
          for (unsigned int n = 0; n < face_nodes; ++n)
            {
              const double *data = &records[r + 1 + node_record * n];
              Node          node;
              for (unsigned int c = 0; c < dim; ++c)
                {
                  node.dofs[c] = static_cast<types::global_dof_index>(data[c]);
                  node.reference[c] = data[3 + c];
                }
              node.current = node.reference;
              const auto [it, inserted] =
                node_index.emplace(node.dofs[0], nodes.size());
              if (inserted)
                nodes.push_back(node);
              face.nodes[n] = it->second;
              if (inserted)
                for (unsigned int p = 0; p < static_cast<unsigned int>(data[6]);
                     ++p)
                  hanging[it->second].emplace_back(data[7 + 2 * p],
                                                   data[8 + 2 * p]);
            }
          faces.push_back(face);
        }
    // A fixed face order (by reference centre) whatever the partition.
    const auto centre = [&](const Face &f) {
      return nodes[f.nodes[ContactFace::centre_node]].reference;
    };
    std::sort(faces.begin(), faces.end(), [&](const Face &a, const Face &b) {
      const Point<dim> pa = centre(a), pb = centre(b);
      return std::lexicographical_compare(pa.begin_raw(),
                                          pa.end_raw(),
                                          pb.begin_raw(),
                                          pb.end_raw());
    });
    node_faces.assign(nodes.size(), {});
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (const unsigned int n : faces[f].nodes)
        node_faces[n].push_back(f);

    // A hanging node of a contact surface lies on an edge of a coarser
    // face, usually of the same surface, whose nodes are its parents (a
    // parent off the surface: invalid_unsigned_int).
    children.assign(nodes.size(), {});
    for (const auto &[n, parents] : hanging)
      for (const auto &[dof, weight] : parents)
        {
          const auto it =
            node_index.find(static_cast<types::global_dof_index>(dof));
          if (it == node_index.end())
            {
              nodes[n].parents.emplace_back(numbers::invalid_unsigned_int,
                                            weight);
              continue;
            }
          nodes[n].parents.emplace_back(it->second, weight);
          children[it->second].emplace_back(n, weight);
        }
  }



  bool
  ContactSurface::has_hanging_nodes() const
  {
    return std::any_of(nodes.begin(), nodes.end(), [](const Node &n) {
      return !n.parents.empty();
    });
  }



  void
  ContactSurface::update(const TrilinosWrappers::MPI::BlockVector &u,
                         const Discretisation &discretisation)
  {
    std::vector<double> x(dim * nodes.size(), 0.);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (discretisation.locally_owned_dofs.is_element(nodes[n].dofs[0]))
        for (unsigned int c = 0; c < dim; ++c)
          x[dim * n + c] = u(nodes[n].dofs[c]);
    Utilities::MPI::sum(x, discretisation.dof_handler.get_communicator(), x);
    for (unsigned int n = 0; n < nodes.size(); ++n)
      for (unsigned int c = 0; c < dim; ++c)
        nodes[n].current[c] = nodes[n].reference[c] + x[dim * n + c];
  }



  ContactFace
  ContactSurface::current_face(const unsigned int f) const
  {
    ContactFace q;
    for (unsigned int n = 0; n < face_nodes; ++n)
      q.x[n] = nodes[faces[f].nodes[n]].current;
    return q;
  }



  double
  ContactSurface::smallest_face_size() const
  {
    double h = std::numeric_limits<double>::max();
#if DUCTILE_CONTACT_DIM == 3
    const auto edges = {std::pair{0u, 2u},
                        std::pair{2u, 8u},
                        std::pair{8u, 6u},
                        std::pair{6u, 0u}};
#else
    const auto edges     = {std::pair{0u, 2u}};
#endif
    for (const Face &f : faces)
      for (const auto &[a, b] : edges)
        h = std::min(
          h,
          (nodes[f.nodes[a]].reference - nodes[f.nodes[b]].reference).norm());
    return h;
  }



  double
  ContactSurface::largest_face_size() const
  {
    double h = 0;
#if DUCTILE_CONTACT_DIM == 3
    const auto diagonals = {std::pair{0u, 8u}, std::pair{2u, 6u}};
#else
    const auto diagonals = {std::pair{0u, 2u}};
#endif
    for (const Face &f : faces)
      for (const auto &[a, b] : diagonals)
        h = std::max(
          h,
          (nodes[f.nodes[a]].reference - nodes[f.nodes[b]].reference).norm());
    return h;
  }
} // namespace DuctileContact
