// SPDX-License-Identifier: BSD-3-Clause
/**
 * The one way the module's plain C++ parts (LR-spline patches, fields,
 * builders, locators, the IFEM readers' helpers) report a failure to their
 * caller: the message into an optional `std::string* error`, and false.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizError_h
#define vtkSplineVizError_h

#include <string>

namespace vtkSplineVizError
{
/// Store `message` in `*error` (when `error` is not null); return false.
inline bool Fail(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
  return false;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkSplineVizError.h
