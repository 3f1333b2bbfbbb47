// The one registry of the concrete patch types, and the only place that asks which type a
// `Patch` is. Whatever differs by type (a control net's lines, a flip, an exact CAD surface, a
// codec's fields) is written as one overload per type and reached through visit_patch_type, so a
// type left without an answer is a compile error where the overload set is visited, not a
// silent default in a chain of casts. tests/core/patch_type_table_test.cpp builds a sample of
// every registered type and checks every property on it.
#pragma once

#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

#include "core/patch/bezier_patch.hpp"
#include "core/patch/bspline_patch.hpp"
#include "core/patch/catmull_clark_patch.hpp"
#include "core/patch/coons_network_patch.hpp"
#include "core/patch/gap_fill_patch.hpp"
#include "core/patch/gb/gb_interior_patch.hpp"
#include "core/patch/gb/gb_patch.hpp"
#include "core/patch/gb/gb_ribbon_patch.hpp"
#include "core/patch/gregory_quad.hpp"
#include "core/patch/gregory_tri.hpp"
#include "core/patch/hermite_patch.hpp"
#include "core/patch/interpolating_patch.hpp"
#include "core/patch/nurbs_patch.hpp"
#include "core/patch/pair_join_patch.hpp"
#include "core/patch/patch.hpp"
#include "core/patch/transfinite/ribbon_patch.hpp"

namespace pl {

template <class... T>
struct PatchTypeList {};

// Every concrete patch class a scene, a network filling or a reader can produce. A new patch
// type is added here; then every visit_patch_type without an overload for it fails to compile
// (docs/developing.md, "Adding a patch type", lists them).
using PatchTypes =
    PatchTypeList<BezierPatch, BSplinePatch, NurbsPatch, InterpolatingPatch, HermitePatch,
                  CoonsNetworkPatch, GregoryQuadPatch, GregoryTriPatch, GBPatch, GBRibbonPatch,
                  GBInteriorPatch, CatmullClarkPatch, PairJoinPatch, GapFillPatch, RibbonPatch>;

// One overload set from several lambdas: visit_patch_type(p, Overloaded{[](const A&) {...}, ...}).
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// For one answer shared by several types: []<OneOf<A, B> T>(const T&) { ... } in an Overloaded
// set. A type in no group leaves the visit without an overload, a type in two makes it
// ambiguous: both fail to compile.
template <class T, class... U>
concept OneOf = (std::is_same_v<T, U> || ...);

template <class T, class List>
inline constexpr bool kInList = false;
template <class T, class... U>
inline constexpr bool kInList<T, PatchTypeList<U...>> = (std::is_same_v<T, U> || ...);

template <class T>
inline constexpr bool kRegisteredPatchType = kInList<T, PatchTypes>;

// Thrown for a Patch object whose class is not in PatchTypes (a programming error: the class was
// not registered), naming its type().
[[noreturn]] void throw_unregistered_patch_type(const Patch& patch);

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) visit_patch_type(const Patch& patch, F& f, PatchTypeList<First, Rest...>) {
  using Result = std::invoke_result_t<F&, const First&>;
  static_assert((std::is_same_v<Result, std::invoke_result_t<F&, const Rest&>> && ...),
                "every overload of a patch type visit must return the same type");
  // The exact class, not a base: a registered type is never a base of another.
  if (typeid(patch) == typeid(First)) return f(static_cast<const First&>(patch));
  if constexpr (sizeof...(Rest) == 0)
    throw_unregistered_patch_type(patch);
  else
    return detail::visit_patch_type(patch, f, PatchTypeList<Rest...>{});
}
}  // namespace detail

// Calls f(const T&) with the patch as its registered type T and returns what f returns; f must
// accept every registered type. Throws std::logic_error for an unregistered class.
template <class F>
decltype(auto) visit_patch_type(const Patch& patch, F&& f) {
  return detail::visit_patch_type(patch, f, PatchTypes{});
}

// Calls f.template operator()<T>() for every registered type T, in the order of PatchTypes (the
// tests go through every type this way).
template <class F>
void for_each_patch_type(F&& f) {
  [&]<class... T>(PatchTypeList<T...>) { (f.template operator()<T>(), ...); }(PatchTypes{});
}

// The patch as T when it is exactly a T, else nullptr: for code that needs one type's own data
// (a GB patch's index layout, a network face's interior offsets), not for per-type properties.
template <class T>
const T* patch_as(const Patch* patch) {
  static_assert(kRegisteredPatchType<T>, "patch_as: T is not in PatchTypes");
  return patch && typeid(*patch) == typeid(T) ? static_cast<const T*>(patch) : nullptr;
}
template <class T>
const T* patch_as(const Patch& patch) {
  return patch_as<T>(&patch);
}

// The patch as T; throws std::logic_error naming both types when it is not one (a codec handed
// another type's patch).
template <class T>
const T& patch_ref(const Patch& patch) {
  if (const T* p = patch_as<T>(patch)) return *p;
  throw std::logic_error(std::string("expected a \"") + T::kType + "\" patch, got \"" +
                         patch.type() + "\"");
}

// The scene-format names of the registered types, in the order of PatchTypes.
std::vector<std::string> patch_type_names();

}  // namespace pl
