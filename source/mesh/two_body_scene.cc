#include <deal.II/grid/tria.h>

#include <ductile_contact/mesh/scene.h>

// A three-dimensional scene: MeshParameters::check() refuses it in the
// plane-strain build, which therefore has no builder for it.
#if DUCTILE_CONTACT_DIM == 3
namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /**
     * Appends a brick of n[0] x n[1] x n[2] hexahedra to a raw cell list.
     * Each brick gets its own vertices, so two bricks never share a vertex
     * even where their faces touch: the bodies stay disconnected (contact,
     * not glue, couples them).
     */
    void
    append_brick(const Point<dim>                &lower,
                 const Point<dim>                &upper,
                 const std::vector<unsigned int> &n,
                 const types::material_id         material_id,
                 std::vector<Point<dim>>         &vertices,
                 std::vector<CellData<dim>>      &cells)
    {
      const unsigned int offset = vertices.size();
      for (unsigned int k = 0; k <= n[2]; ++k)
        for (unsigned int j = 0; j <= n[1]; ++j)
          for (unsigned int i = 0; i <= n[0]; ++i)
            {
              const std::array<unsigned int, dim> index{{i, j, k}};
              Point<dim>                          p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = lower[d] + (upper[d] - lower[d]) * index[d] / n[d];
              vertices.push_back(p);
            }
      const auto vertex =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          return offset + i + (n[0] + 1) * (j + (n[1] + 1) * k);
        };
      for (unsigned int k = 0; k < n[2]; ++k)
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0]; ++i)
            {
              CellData<dim> cell;
              // deal.II's lexicographic vertex order: v = a + 2b + 4c.
              for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
                   ++v)
                cell.vertices[v] =
                  vertex(i + (v & 1), j + ((v >> 1) & 1), k + ((v >> 2) & 1));
              cell.material_id = material_id;
              cells.push_back(cell);
            }
    }
  } // namespace



  void
  create_two_body_scene(const MeshParameters::TwoBodies &parameters,
                        Triangulation<dim>              &tria)
  {
    const Point<dim> &L  = parameters.plate_size;
    const double      a  = parameters.block_edge;
    const double      z0 = L[2] + parameters.block_gap;
    const Point<dim>  block_lower(parameters.block_centre[0] - a / 2,
                                 parameters.block_centre[1] - a / 2,
                                 z0);
    const Point<dim>  block_upper(parameters.block_centre[0] + a / 2,
                                 parameters.block_centre[1] + a / 2,
                                 z0 + a);

    std::vector<Point<dim>>    vertices;
    std::vector<CellData<dim>> cells;
    append_brick(
      Point<dim>(), L, parameters.plate_subdivisions, 0, vertices, cells);
    append_brick(block_lower,
                 block_upper,
                 parameters.block_subdivisions,
                 1,
                 vertices,
                 cells);
    tria.create_triangulation(vertices, cells, SubCellData());

    // Boundary ids from the face position and the body the cell belongs to.
    for (const auto &cell : tria.cell_iterators_on_level(0))
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<dim> c   = face->center();
            const double     tol = 1e-8 * L.norm();
            if (cell->material_id() == 0)
              {
                if (std::abs(c[0] - L[0]) < tol)
                  face->set_boundary_id(1);
                else if (std::abs(c[2] - L[2]) < tol)
                  face->set_boundary_id(3);
                else
                  face->set_boundary_id(0);
              }
            else
              {
                if (std::abs(c[2] - block_upper[2]) < tol)
                  face->set_boundary_id(2);
                else if (std::abs(c[2] - block_lower[2]) < tol)
                  face->set_boundary_id(4);
                else
                  face->set_boundary_id(5);
              }
          }
  }
} // namespace DuctileContact
#endif
