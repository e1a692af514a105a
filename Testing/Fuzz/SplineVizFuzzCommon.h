// Shared by the SplineViz libFuzzer targets (Testing/Fuzz).
#ifndef SplineVizFuzzCommon_h
#define SplineVizFuzzCommon_h

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplinePatch.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace SplineVizFuzz
{
/// A broken promise of the code under test: report and abort (libFuzzer
/// keeps the input as a crash).
[[noreturn]] inline void Fail(const std::string& what)
{
  std::fprintf(stderr, "SplineViz fuzz target: %s\n", what.c_str());
  std::abort();
}

/// A failed parse or read must say why.
inline void CheckMessage(const std::string& error)
{
  if (error.empty())
  {
    Fail("an input was rejected without a message");
  }
}

/// Every accepted patch must be valid and its Bezier form extractable (or
/// refused with a message).
inline void ExtractAll(const std::vector<vtkLRSplinePatch>& patches)
{
  for (const vtkLRSplinePatch& patch : patches)
  {
    std::string error, warning;
    if (!patch.Validate(&error))
    {
      Fail("the parser accepted a patch that does not validate: " + error);
    }
    vtkLRSplineBezierVolume volume;
    if (!patch.ExtractBezier(volume, &error, &warning, 0, patch.GetNumberOfElements()))
    {
      CheckMessage(error);
    }
  }
}
}

#endif
