// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the LRSplines text parser (.lr) on arbitrary bytes
// (vtkLRSplineParser::Parse, which validates what it read), and the Bezier
// extraction of whatever it accepts. Every input must either parse
// into valid patches or fail with a message that names a line; nothing may
// crash, leak, hang or allocate without bound. See README, "Fuzzing".
#include "SplineVizFuzzCommon.h"

#include "vtkLRSplineParser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<vtkLRSplinePatch> patches;
  std::string error;
  if (vtkLRSplineParser::Parse(text, vtkLRSplineParser::LRSPLINES, patches, &error))
  {
    SplineVizFuzz::ExtractAll(patches);
  }
  else
  {
    SplineVizFuzz::CheckMessage(error);
  }
  return 0;
}
