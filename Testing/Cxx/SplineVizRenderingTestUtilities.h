// Helpers for the rendering tests: independent reference geometry for spline
// tubes and image/depth comparisons.
#ifndef SplineVizRenderingTestUtilities_h
#define SplineVizRenderingTestUtilities_h

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace SplineVizTest
{
using Vec4 = std::array<double, 4>; // x, y, z, radius

/// Polylines with a per-point "Radius" array, one cell per curve.
inline vtkSmartPointer<vtkPolyData> MakePolylines(const std::vector<std::vector<Vec4>>& curves)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  for (const auto& curve : curves)
  {
    lines->InsertNextCell(static_cast<int>(curve.size()));
    for (const auto& p : curve)
    {
      lines->InsertCellPoint(points->InsertNextPoint(p[0], p[1], p[2]));
      radius->InsertNextValue(p[3]);
    }
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(radius);
  return pd;
}

/// Independent evaluation of the documented spline (Catmull-Rom tangents
/// inside, second-order one-sided differences at the ends, cubic Hermite
/// segments), for position and radius, `perSegment` samples per segment.
inline std::vector<Vec4> DenseSpline(const std::vector<Vec4>& nodes, int perSegment)
{
  const size_t n = nodes.size();
  std::vector<Vec4> m(n);
  for (size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      if (n == 2)
        m[i][c] = nodes[1][c] - nodes[0][c];
      else if (i == 0)
        m[i][c] = 0.5 * (-3 * nodes[0][c] + 4 * nodes[1][c] - nodes[2][c]);
      else if (i == n - 1)
        m[i][c] = 0.5 * (3 * nodes[n - 1][c] - 4 * nodes[n - 2][c] + nodes[n - 3][c]);
      else
        m[i][c] = 0.5 * (nodes[i + 1][c] - nodes[i - 1][c]);
    }
  }
  std::vector<Vec4> out;
  for (size_t i = 0; i + 1 < n; ++i)
  {
    for (int k = 0; k < perSegment; ++k)
    {
      const double t = static_cast<double>(k) / perSegment;
      const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
      const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
      Vec4 p;
      for (int c = 0; c < 4; ++c)
        p[c] = h00 * nodes[i][c] + h10 * m[i][c] + h01 * nodes[i + 1][c] + h11 * m[i + 1][c];
      out.push_back(p);
    }
  }
  out.push_back(nodes.back());
  return out;
}

/// High-resolution polygonal reference of the tubes: vtkTubeFilter (radius by
/// absolute scalar, `sides` sides) along the densely resampled spline, plus
/// spheres for the rounded caps.
inline vtkSmartPointer<vtkPolyData> ReferenceTubes(
  const std::vector<std::vector<Vec4>>& curves, int perSegment, int sides)
{
  vtkNew<vtkAppendPolyData> append;
  for (const auto& curve : curves)
  {
    const auto dense = DenseSpline(curve, perSegment);
    auto line = MakePolylines({ dense });
    line->GetPointData()->SetActiveScalars("Radius");
    vtkNew<vtkTubeFilter> tubes;
    tubes->SetInputData(line);
    tubes->SetNumberOfSides(sides);
    tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    tubes->CappingOff();
    tubes->Update();
    append->AddInputData(tubes->GetOutput());
    for (const Vec4* end : { &dense.front(), &dense.back() })
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter((*end)[0], (*end)[1], (*end)[2]);
      sphere->SetRadius((*end)[3]);
      sphere->SetThetaResolution(64);
      sphere->SetPhiResolution(64);
      sphere->Update();
      append->AddInputData(sphere->GetOutput());
    }
  }
  append->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(append->GetOutput());
  out->GetPointData()->SetActiveScalars(nullptr);
  return out;
}

/// Rendered frame: RGB and window depth of a render window.
struct Frame
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> RGB;
  std::vector<float> Depth;
  bool Covered(int x, int y) const { return this->Depth[y * this->Width + x] < 1.0f; }
};

inline Frame Grab(vtkRenderWindow* window)
{
  window->Render();
  Frame f;
  const int* size = window->GetSize();
  f.Width = size[0];
  f.Height = size[1];
  unsigned char* rgb = window->GetPixelData(0, 0, f.Width - 1, f.Height - 1, 0);
  f.RGB.assign(rgb, rgb + 3 * f.Width * f.Height);
  delete[] rgb;
  float* z = window->GetZbufferData(0, 0, f.Width - 1, f.Height - 1);
  f.Depth.assign(z, z + f.Width * f.Height);
  delete[] z;
  return f;
}

/// Coverage comparison with a one-pixel tolerance: pixels covered in one
/// frame with no covered pixel within `tolerance` pixels in the other.
struct CoverageDifference
{
  long Covered[2] = { 0, 0 };
  long Unexplained[2] = { 0, 0 }; ///< covered in a, not near b (and vice versa)
};

inline CoverageDifference CompareCoverage(const Frame& a, const Frame& b, int tolerance = 1)
{
  CoverageDifference d;
  const Frame* frames[2] = { &a, &b };
  for (int which = 0; which < 2; ++which)
  {
    const Frame& f = *frames[which];
    const Frame& g = *frames[1 - which];
    for (int y = 0; y < f.Height; ++y)
    {
      for (int x = 0; x < f.Width; ++x)
      {
        if (!f.Covered(x, y))
          continue;
        ++d.Covered[which];
        bool near = false;
        for (int dy = -tolerance; dy <= tolerance && !near; ++dy)
          for (int dx = -tolerance; dx <= tolerance && !near; ++dx)
          {
            const int xx = x + dx, yy = y + dy;
            near = xx >= 0 && yy >= 0 && xx < g.Width && yy < g.Height && g.Covered(xx, yy);
          }
        if (!near)
          ++d.Unexplained[which];
      }
    }
  }
  return d;
}

/// View-space distance along -z of a window depth, for the camera's
/// (fixed) clipping range.
inline double ViewDepth(double windowDepth, vtkCamera* camera)
{
  double range[2];
  camera->GetClippingRange(range);
  const double n = range[0], f = range[1];
  const double ndc = 2.0 * windowDepth - 1.0;
  if (camera->GetParallelProjection())
    return 0.5 * (ndc * (f - n) + (f + n));
  return 2.0 * f * n / ((f + n) - ndc * (f - n));
}
}

#endif
