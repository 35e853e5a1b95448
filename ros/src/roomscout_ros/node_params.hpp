#pragma once
// Reading a node's private parameters strictly: a parameter set with the wrong type is an
// error naming it, not a silent fall back to the default (what NodeHandle::param does).

#include <string>

#include <ros/node_handle.h>

#include "roomscout/core/errors.hpp"

namespace roomscout::ros1 {

/// The parameter `name` if set, else `fallback`. Throws OptionError ("~name must be
/// <expected>") when it is set with another type.
template <class T>
T typedParam(const ros::NodeHandle& pnh, const std::string& name, const T& fallback, const char* expected) {
  if (!pnh.hasParam(name)) return fallback;
  T value;
  if (!pnh.getParam(name, value)) throw OptionError("~" + name + " must be " + expected);
  return value;
}

}  // namespace roomscout::ros1
