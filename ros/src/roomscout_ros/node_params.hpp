#pragma once
// Reading a node's private parameters strictly: a parameter set with the wrong type is an
// error naming it, not a silent fall back to the default (what NodeHandle::param does).

#include <string>
#include <type_traits>

#include <ros/node_handle.h>

#include "roomscout/core/errors.hpp"

namespace roomscout::ros1 {

/// How an error message names the type a parameter must have.
template <class T>
constexpr const char* expectedType() {
  if constexpr (std::is_same_v<T, bool>)
    return "true or false";
  else if constexpr (std::is_same_v<T, int>)
    return "an integer";
  else if constexpr (std::is_same_v<T, double>)
    return "a number";
  else if constexpr (std::is_same_v<T, std::string>)
    return "a string";
  else
    static_assert(sizeof(T) == 0, "typedParam reads bool, int, double or std::string");
}

/// The parameter `name` if set, else `fallback`. Throws OptionError ("~name must be a
/// number", say) when it is set with another type.
template <class T>
T typedParam(const ros::NodeHandle& pnh, const std::string& name, const T& fallback) {
  if (!pnh.hasParam(name)) return fallback;
  T value;
  if (!pnh.getParam(name, value)) throw OptionError("~" + name + " must be " + expectedType<T>());
  return value;
}

}  // namespace roomscout::ros1
