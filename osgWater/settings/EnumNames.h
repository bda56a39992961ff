// Private to the library: an enum's names in a table in its values' order, read both ways (the
// settings' and the surface's enums, for files, the demo's options and messages).
#pragma once
#include <cstddef>
#include <string>

namespace osgWater {
namespace detail {

//! The name of `value`, or `unknown` for a value past the table.
template <typename E, std::size_t N>
const char* nameOf(const char* const (&names)[N], E value, const char* unknown)
{
    return int(value) >= 0 && int(value) < int(N) ? names[int(value)] : unknown;
}

//! Every name of the table in its values' order, joined by '|' (help texts and error messages).
template <std::size_t N>
std::string joinedNames(const char* const (&names)[N])
{
    std::string joined;
    for (std::size_t i = 0; i < N; ++i) joined += (i ? "|" : "") + std::string(names[i]);
    return joined;
}

//! The value named `name`; false (and `value` untouched) for a name not in the table.
template <typename E, std::size_t N>
bool valueOf(const char* const (&names)[N], const std::string& name, E& value)
{
    for (std::size_t i = 0; i < N; ++i)
        if (name == names[i]) {
            value = E(i);
            return true;
        }
    return false;
}

}
}
