// The names of every choice among a few (an enum of params.h), one table per enum, in the order
// the front ends list them, the default first. The command line parses and shows these names, the
// Python package takes them, and QGIS lists its options in this order: a saved model or script
// keeps an option's position, so an entry is only ever added at the end.
#pragma once

#include <cstddef>
#include <string>

#include "core/base/errors.h"
#include "core/method/params.h"

namespace tsk {

template <typename Enum>
struct ChoiceName {
  Enum value;
  const char* name;
};

inline constexpr ChoiceName<FilterMode> kFilterModeNames[] = {{FilterMode::adaptive, "adaptive"},
                                                              {FilterMode::fixed, "fixed"}};
inline constexpr ChoiceName<Adaptivity> kAdaptivityNames[] = {{Adaptivity::whole, "whole"},
                                                              {Adaptivity::local, "local"}};
inline constexpr ChoiceName<StrokeMode> kStrokeModeNames[] = {{StrokeMode::drawn, "drawn"},
                                                              {StrokeMode::exact, "exact"}};
inline constexpr ChoiceName<Placement> kPlacementNames[] = {
    {Placement::far, "far"}, {Placement::near_and_far, "near_and_far"}};
inline constexpr ChoiceName<Geometry> kGeometryNames[] = {{Geometry::map, "map"},
                                                          {Geometry::oblique, "oblique"}};

// Where `value` stands in `table`.
template <typename Enum, std::size_t N>
std::size_t index_of(const ChoiceName<Enum> (&table)[N], Enum value) {
  for (std::size_t k = 0; k < N; ++k) {
    if (table[k].value == value) return k;
  }
  return 0;
}

// `table`'s names as "'a' or 'b'", for messages and help.
template <typename Enum, std::size_t N>
std::string choice_list(const ChoiceName<Enum> (&table)[N]) {
  std::string list;
  for (std::size_t k = 0; k < N; ++k) {
    list += (k == 0 ? "'" : k + 1 == N ? " or '" : ", '") + std::string(table[k].name) + "'";
  }
  return list;
}

// The choice at `index` of `table`; Error naming `what` when there is none.
template <typename Enum, std::size_t N>
Enum choice_at(const ChoiceName<Enum> (&table)[N], long long index, const char* what) {
  if (index < 0 || static_cast<unsigned long long>(index) >= N)
    throw Error(std::string(what) + " has no option " + std::to_string(index));
  return table[index].value;
}

// The choice named `name`; Error naming `what` and every name when there is none.
template <typename Enum, std::size_t N>
Enum parse_choice(const ChoiceName<Enum> (&table)[N], const std::string& name, const char* what) {
  for (const ChoiceName<Enum>& choice : table) {
    if (name == choice.name) return choice.value;
  }
  throw Error(std::string(what) + " must be " + choice_list(table) + ", got '" + name + "'");
}

}  // namespace tsk
