// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the GoTools g2 parser (.g2: classes 200, 700, 293, 793) on arbitrary bytes,
// and the Bezier extraction of whatever it accepts (see FuzzLRSplineParser).
#include "SplineVizFuzzCommon.h"

#include "vtkLRSplineParser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<vtkLRSplinePatch> patches;
  std::string error;
  if (vtkLRSplineParser::Parse(text, vtkLRSplineParser::G2, patches, &error))
  {
    SplineVizFuzz::ExtractAll(patches);
  }
  else
  {
    SplineVizFuzz::CheckMessage(error);
  }
  return 0;
}
