// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSplineVizNameList.h
 * @brief  An ordered list of names (files, arrays) behind the Add.../RemoveAll.../
 * GetNumberOf.../Get... methods of the SplineViz readers and writers.
 *
 * Header-only, private to the library. Add() and Clear() return whether the
 * list changed, so that the caller calls Modified() only then.
 */
#ifndef vtkSplineVizNameList_h
#define vtkSplineVizNameList_h

#include <ostream>
#include <string>
#include <vector>

struct vtkSplineVizNameList
{
  std::vector<std::string> Names;

  /// Appends a non-empty name; true when added.
  bool Add(const char* name)
  {
    if (!name || !*name)
    {
      return false;
    }
    this->Names.emplace_back(name);
    return true;
  }
  /// Removes all names; true when there were any.
  bool Clear()
  {
    const bool changed = !this->Names.empty();
    this->Names.clear();
    return changed;
  }
  int Size() const { return static_cast<int>(this->Names.size()); }
  /// Name i, or nullptr when i is out of range.
  const char* Get(int i) const
  {
    return (i >= 0 && i < this->Size()) ? this->Names[static_cast<std::size_t>(i)].c_str()
                                        : nullptr;
  }
  void Print(std::ostream& os) const
  {
    for (const auto& n : this->Names)
    {
      os << " " << n;
    }
    os << "\n";
  }
};

#endif
