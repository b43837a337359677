#pragma once

#include <deal.II/base/template_constraints.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <Sacado.hpp>

/**
 * @file
 * deal.II 9.4 declares the product types of its tensors with Sacado's
 * dynamic DFad only. These declarations do the same for the static SFad
 * (Sacado::Fad::SFad<T, N> = Exp::GeneralFad<Exp::StaticFixedStorage<T,
 * N>>), whose derivatives live on the stack: Tensor<rank, dim, SFad> then
 * works like Tensor<rank, dim, DFad> without a heap allocation per
 * operation (the plastic update, materials/plasticity.cc).
 */
namespace dealii
{
  namespace internal
  {
    template <typename T, int N>
    struct ProductTypeImpl<Sacado::Fad::SFad<T, N>, double>
    {
      using type = Sacado::Fad::SFad<T, N>;
    };

    template <typename T, int N>
    struct ProductTypeImpl<double, Sacado::Fad::SFad<T, N>>
    {
      using type = Sacado::Fad::SFad<T, N>;
    };

    template <typename T, int N>
    struct ProductTypeImpl<Sacado::Fad::SFad<T, N>, int>
    {
      using type = Sacado::Fad::SFad<T, N>;
    };

    template <typename T, int N>
    struct ProductTypeImpl<int, Sacado::Fad::SFad<T, N>>
    {
      using type = Sacado::Fad::SFad<T, N>;
    };

    template <typename T, int N>
    struct ProductTypeImpl<Sacado::Fad::SFad<T, N>, Sacado::Fad::SFad<T, N>>
    {
      using type = Sacado::Fad::SFad<T, N>;
    };
  } // namespace internal

  template <typename T, int N>
  struct EnableIfScalar<Sacado::Fad::SFad<T, N>>
  {
    using type = Sacado::Fad::SFad<T, N>;
  };
} // namespace dealii
