// Test scenes and measures shared by the stylized-line tests.
//
// - Curls(): helices of different radii, pitches and orientations, a loop
//   and a straight line, densely sampled (a few degrees of turn per segment,
//   so the straight segments of the lines follow smooth curves), with
//   per-point radii;
// - Ring(): a ring whose tangent a camera can look along exactly;
// - Bundle(): wavy lines running along +x side by side (a fibre bundle),
//   which a camera on the x axis sees end-on: there most tangents point at
//   the viewer (the singular view of Stoll §4.3);
// - ReferenceTubes(): the independent polygonal reference, vtkTubeFilter
//   with 64 sides and flat caps around the same polylines (radius by
//   absolute scalar), the same model as the stylized lines (circular
//   profiles orthogonal to the vertex tangents, straight segments);
// - Measure(): coverage IoU and the share of the common pixels whose eye
//   depth agrees within a given distance, from two frames rendered with the
//   same camera.
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
using SplineVizTest::Vec4;

inline std::vector<std::vector<Vec4>> Curls()
{
  std::vector<std::vector<Vec4>> curves;
  // Helices: axis z, radius R, pitch c, around different centers; tilted by
  // swapping coordinates so that they do not share an axis.
  struct Helix
  {
    double cx, cy, cz, R, c, r0, r1;
    int turns, axis;
  };
  const Helix helices[] = { { -1.2, 0.8, 0.0, 0.7, 0.12, 0.06, 0.11, 2, 2 },
    { 1.1, 0.9, -0.5, 0.5, 0.18, 0.05, 0.05, 2, 0 },
    { 0.0, -1.0, 0.3, 0.9, 0.08, 0.08, 0.04, 1, 1 },
    { 1.3, -1.1, 0.8, 0.35, 0.1, 0.07, 0.07, 3, 2 } };
  for (const Helix& h : helices)
  {
    std::vector<Vec4> curve;
    const int n = 72 * h.turns; // 5 degrees per segment
    for (int i = 0; i <= n; ++i)
    {
      const double a = 2.0 * 3.141592653589793 * i / 72.0;
      double p[3] = { h.R * std::cos(a), h.R * std::sin(a), h.c * a - h.c * 3.14159 * h.turns };
      if (h.axis == 0)
      {
        std::swap(p[0], p[2]);
      }
      else if (h.axis == 1)
      {
        std::swap(p[1], p[2]);
      }
      const double s = static_cast<double>(i) / n;
      curve.push_back({ h.cx + p[0], h.cy + p[1], h.cz + p[2], h.r0 + (h.r1 - h.r0) * s });
    }
    curves.push_back(curve);
  }
  // A straight line and a loop.
  std::vector<Vec4> line;
  for (int i = 0; i <= 40; ++i)
  {
    line.push_back({ -2.0 + 0.1 * i, 2.0, -0.4, 0.08 });
  }
  curves.push_back(line);
  std::vector<Vec4> loop;
  for (int i = 0; i <= 100; ++i)
  {
    const double a = 2.0 * 3.141592653589793 * i / 100.0;
    loop.push_back({ 0.6 * std::cos(a), -2.0 + 0.3 * std::sin(2.0 * a), 0.6 * std::sin(a), 0.06 });
  }
  curves.push_back(loop);
  return curves;
}

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

/// vtkTubeFilter, 64 sides, flat caps, radius by absolute scalar "Radius".
inline vtkSmartPointer<vtkPolyData> ReferenceTubes(vtkPolyData* lines)
{
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(lines);
  input->GetPointData()->SetActiveScalars("Radius");
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(input);
  tubes->SetNumberOfSides(64);
  tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
  tubes->CappingOn();
  tubes->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(tubes->GetOutput());
  out->GetPointData()->SetActiveScalars(nullptr);
  return out;
}

struct Measures
{
  long Covered[2] = { 0, 0 }; ///< test, reference
  double IoU = 0.0;
  double DepthShare = 0.0; ///< common pixels whose eye depths agree within the tolerance
  long Common = 0;
};

/// IoU of the covered pixels and the share of the common pixels whose eye
/// depths (linearized with the camera's clipping range) differ by at most
/// `depthTolerance`.
inline Measures Measure(const SplineVizTest::Frame& test, const SplineVizTest::Frame& reference,
  vtkCamera* camera, double depthTolerance)
{
  Measures m;
  long both = 0;
  long either = 0;
  long close = 0;
  for (int y = 0; y < test.Height; ++y)
  {
    for (int x = 0; x < test.Width; ++x)
    {
      const bool a = test.Covered(x, y);
      const bool b = reference.Covered(x, y);
      m.Covered[0] += a ? 1 : 0;
      m.Covered[1] += b ? 1 : 0;
      either += (a || b) ? 1 : 0;
      if (a && b)
      {
        ++both;
        const size_t i = static_cast<size_t>(y * test.Width + x);
        const double da = SplineVizTest::ViewDepth(test.Depth[i], camera);
        const double db = SplineVizTest::ViewDepth(reference.Depth[i], camera);
        close += std::abs(da - db) <= depthTolerance ? 1 : 0;
      }
    }
  }
  m.Common = both;
  m.IoU = either > 0 ? static_cast<double>(both) / either : 1.0;
  m.DepthShare = both > 0 ? static_cast<double>(close) / both : 1.0;
  return m;
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

/// With SPLINEVIZ_TEST_IMAGES=<dir>, write the frame's colors as <dir>/<name>.png.
inline void Save(const SplineVizTest::Frame& frame, const std::string& name)
{
  const char* dir = std::getenv("SPLINEVIZ_TEST_IMAGES");
  if (!dir)
  {
    return;
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(frame.Width, frame.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(
    frame.RGB.begin(), frame.RGB.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((std::string(dir) + "/" + name + ".png").c_str());
  writer->Write();
}
}

#endif
