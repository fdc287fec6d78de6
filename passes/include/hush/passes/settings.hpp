#pragma once
// One description per settings struct. Next to each settings struct of a node or a
// chain stands a function
//
//   template <class V> void describe(V&& v, SvgfTemporalSettings& s) {
//       v.field("alpha", s.alpha, Range{0, 1});
//       ...
//   }
//
// that lists every field once, with the key it has in chain files (the C++ name), its
// accepted range or names, and nested sections. Everything that walks settings uses
// it: the chain-file reader, the JSON writer of reports, the push constants a node
// sends its shader (a field and a shader push constant of the same name are one
// value), and the test that proves no field is missing (fieldCount below).
//
// A visitor V provides:
//   field(key, float&, Range)        field(key, uint32_t&, Range)   field(key, int&, Range)
//   field(key, uint32_t&, Choices<N>)
//   field(key, bool&)                field(key, Enum&, names)       field(key, std::vector<Enum>&, names, maxItems)
//   field(key, std::string&)         (a file name; never a push constant)
//   section(key, Sub&)               (a nested object: describe(v, sub) inside it)
//   flatten(Sub&)                    (Sub's fields at this level, as if they were this struct's)
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>
#include <utility>

#include <hush/rhi/format.hpp>

namespace hush::passes {

// An accepted closed range [lo, hi].
struct Range {
    double lo = -std::numeric_limits<double>::max();
    double hi = std::numeric_limits<double>::max();
};
inline constexpr double kUnbounded = std::numeric_limits<float>::max();

// The only values an integer field accepts (BMFR's block size: 0, 8, 16, 32 or 64).
template <size_t N> struct Choices {
    uint32_t values[N];
};

// An enum's values by name, in the enum's order: names[i].first spells names[i].second.
template <class E, size_t N> using EnumNames = std::array<std::pair<std::string_view, E>, N>;

// The storage format of a node's intermediate textures.
inline constexpr EnumNames<rhi::Format, 2> kStorageFormatNames{{{"rgba32f", rhi::Format::RGBA32Float},
                                                               {"rgba16f", rhi::Format::RGBA16Float}}};

// The number of fields of an aggregate, counted by how many initialisers it takes
// (each field of any type is initialised from one AnyField). The settings test
// compares it with the number of fields describe() visits.
namespace detail {
struct AnyField {
    template <class T> constexpr operator T() const;   // declared only: used in unevaluated contexts
};
template <class T, size_t... I>
constexpr bool initialisableFrom(std::index_sequence<I...>) {
    return requires { T{(void(I), AnyField{})...}; };
}
} // namespace detail

template <class T, size_t N = 0> constexpr size_t fieldCount() {
    if constexpr (detail::initialisableFrom<T>(std::make_index_sequence<N + 1>{})) return fieldCount<T, N + 1>();
    else return N;
}

} // namespace hush::passes
