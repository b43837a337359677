#include <deal.II/grid/tria.h>

#include <ductile_contact/mesh/scene.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /**
     * Appends a brick of n[0] x n[1] x n[2] hexahedra (n[0] x n[1]
     * quadrilaterals in 2-D) to a raw cell list. Each brick gets its own
     * vertices, so two bricks never share a vertex even where their faces
     * touch: the bodies stay disconnected (contact, not glue, couples
     * them).
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
      // Points and cells along z: one layer of neither in 2-D.
      const unsigned int nz = dim == 3 ? n[dim - 1] : 0;
      for (unsigned int k = 0; k <= nz; ++k)
        for (unsigned int j = 0; j <= n[1]; ++j)
          for (unsigned int i = 0; i <= n[0]; ++i)
            {
              const std::array<unsigned int, 3> index{{i, j, k}};
              Point<dim>                        p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = lower[d] + (upper[d] - lower[d]) * index[d] / n[d];
              vertices.push_back(p);
            }
      const auto vertex =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          return offset + i + (n[0] + 1) * (j + (n[1] + 1) * k);
        };
      for (unsigned int k = 0; k < std::max(nz, 1u); ++k)
        for (unsigned int j = 0; j < n[1]; ++j)
          for (unsigned int i = 0; i < n[0]; ++i)
            {
              CellData<dim> cell;
              // deal.II's lexicographic vertex order: v = a + 2b (+ 4c).
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
    // The plate's thickness and the block's height run along the last
    // coordinate (z; y in 2-D).
    constexpr unsigned int up = dim - 1;
    const Point<dim>      &L  = parameters.plate_size;
    const double           a  = parameters.block_edge;
    Point<dim>             block_lower, block_upper;
    for (unsigned int d = 0; d < up; ++d)
      {
        block_lower[d] = parameters.block_centre[d] - a / 2;
        block_upper[d] = parameters.block_centre[d] + a / 2;
      }
    block_lower[up] = L[up] + parameters.block_gap;
    block_upper[up] = block_lower[up] + a;

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
                else if (std::abs(c[up] - L[up]) < tol)
                  face->set_boundary_id(3);
                else
                  face->set_boundary_id(0);
              }
            else
              {
                if (std::abs(c[up] - block_upper[up]) < tol)
                  face->set_boundary_id(2);
                else if (std::abs(c[up] - block_lower[up]) < tol)
                  face->set_boundary_id(4);
                else
                  face->set_boundary_id(5);
              }
          }
  }
} // namespace DuctileContact
