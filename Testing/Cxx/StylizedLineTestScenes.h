// SPDX-License-Identifier: BSD-3-Clause
// Test scenes and measures shared by the stylized-line tests.
//
// - Curls(), Measure(), Save(): see SplineVizRenderingTestUtilities.h;
// - Ring(): a ring whose tangent a camera can look along exactly;
// - Bundle(): wavy lines running along +x side by side (a fibre bundle),
//   which a camera on the x axis sees end-on: there most tangents point at
//   the viewer (the singular view of Stoll §4.3);
// - PolylineReferenceTubes() (SplineVizRenderingTestUtilities.h): the
//   independent polygonal reference, vtkTubeFilter with 64 sides and flat
//   caps around the same polylines, the stylized lines' model;
#ifndef StylizedLineTestScenes_h
#define StylizedLineTestScenes_h

#include "SplineVizRenderingTestUtilities.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTubeFilter.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace StylizedLineTest
{
using SplineVizTest::Curls;
using SplineVizTest::Measure;
using SplineVizTest::Measures;
using SplineVizTest::PolylineReferenceTubes;
using SplineVizTest::Save;
using SplineVizTest::Vec4;

inline std::vector<std::vector<Vec4>> Bundle()
{
  std::vector<std::vector<Vec4>> curves;
  for (int k = 0; k < 16; ++k)
  {
    const double y0 = 0.35 * (k % 4) - 0.525;
    const double z0 = 0.35 * (k / 4) - 0.525;
    const double phase = 0.7 * k;
    std::vector<Vec4> curve;
    for (int i = 0; i <= 100; ++i)
    {
      const double x = -3.0 + 0.06 * i;
      curve.push_back({ x, y0 + 0.08 * std::sin(1.3 * x + phase),
        z0 + 0.08 * std::cos(1.1 * x + 2.0 * phase), 0.07 + 0.02 * std::sin(0.9 * x + phase) });
    }
    curves.push_back(curve);
  }
  return curves;
}

/// A ring of radius 1 in the x-z plane (240 points, radius 0.08): a camera
/// on the line x = 1, y = 0 sees its tangent at (1, 0, 0) exactly end-on.
inline std::vector<std::vector<Vec4>> Ring()
{
  std::vector<Vec4> ring;
  for (int i = 0; i <= 240; ++i)
  {
    const double a = 2.0 * 3.141592653589793 * i / 240.0 + 0.01;
    ring.push_back({ std::cos(a), 0.0, std::sin(a), 0.08 });
  }
  return { ring };
}

/// Pixels whose coverage differs between two frames.
inline long CoverageChanges(const SplineVizTest::Frame& a, const SplineVizTest::Frame& b)
{
  long n = 0;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      n += a.Covered(x, y) != b.Covered(x, y) ? 1 : 0;
    }
  }
  return n;
}

/// Pixels whose color differs by more than `tolerance` in a channel.
inline long ColorChanges(
  const SplineVizTest::Frame& a, const SplineVizTest::Frame& b, int tolerance)
{
  long n = 0;
  for (size_t i = 0; i + 2 < a.RGB.size(); i += 3)
  {
    bool differs = false;
    for (int c = 0; c < 3; ++c)
    {
      differs = differs || std::abs(int(a.RGB[i + c]) - int(b.RGB[i + c])) > tolerance;
    }
    n += differs ? 1 : 0;
  }
  return n;
}

}

#endif
