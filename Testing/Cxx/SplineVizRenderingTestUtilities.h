// SPDX-License-Identifier: BSD-3-Clause
// Helpers for the rendering tests: independent reference geometry for spline
// tubes and image/depth comparisons.
// - Curls(): helices of different radii, pitches and orientations, a loop
//   and a straight line, densely sampled (a few degrees of turn per segment,
//   so the straight segments of the lines follow smooth curves), with
//   per-point radii;
// - Measure(): coverage IoU and the share of the common pixels whose eye
//   depth agrees within a given distance, from two frames rendered with the
//   same camera; Save(): the frame as a PNG file for inspection.
#ifndef SplineVizRenderingTestUtilities_h
#define SplineVizRenderingTestUtilities_h

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkClipPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkPNGWriter.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace SplineVizTest
{
using Vec4 = std::array<double, 4>; // x, y, z, radius

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
/// spheres (`capResolution` in both angles) for the rounded caps of
/// sphere-swept tubes (vtkRayCastTubeMapper) or, with `flatCaps`, the
/// filter's flat caps (the disk model of vtkTessellatedTubeMapper). With
/// `hemispheres`, only the half of each cap sphere outside the tube (cut by
/// the plane normal to the end segment, where the tube's last ring lies), so
/// that the front faces cover every pixel of a tube once.
inline vtkSmartPointer<vtkPolyData> ReferenceTubes(const std::vector<std::vector<Vec4>>& curves,
  int perSegment, int sides, bool flatCaps = false, int capResolution = 64,
  bool hemispheres = false)
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
    tubes->SetCapping(flatCaps);
    tubes->Update();
    append->AddInputData(tubes->GetOutput());
    for (int e = 0; e < 2 && !flatCaps; ++e)
    {
      const Vec4& end = e == 0 ? dense.front() : dense.back();
      const Vec4& inner = e == 0 ? dense[1] : dense[dense.size() - 2];
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(end[0], end[1], end[2]);
      sphere->SetRadius(end[3]);
      sphere->SetThetaResolution(capResolution);
      sphere->SetPhiResolution(capResolution);
      sphere->Update();
      vtkSmartPointer<vtkPolyData> cap = sphere->GetOutput();
      if (hemispheres)
      {
        vtkNew<vtkPlane> plane;
        plane->SetOrigin(end[0], end[1], end[2]);
        plane->SetNormal(end[0] - inner[0], end[1] - inner[1], end[2] - inner[2]);
        vtkNew<vtkClipPolyData> clip;
        clip->SetInputData(cap);
        clip->SetClipFunction(plane);
        clip->Update();
        cap = clip->GetOutput();
      }
      vtkNew<vtkDoubleArray> radius; // kept by the append filter (RadiusFrame)
      radius->SetName("Radius");
      radius->SetNumberOfValues(cap->GetNumberOfPoints());
      radius->Fill(end[3]);
      cap->GetPointData()->AddArray(radius);
      append->AddInputData(cap);
    }
  }
  append->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(append->GetOutput());
  out->GetPointData()->SetActiveScalars(nullptr);
  return out;
}

/// vtkTubeFilter (`sides` sides), flat caps, radius by absolute scalar
/// "Radius", around the polylines themselves (the model of the stylized
/// lines: circular profiles orthogonal to the vertex tangents, straight
/// segments).
inline vtkSmartPointer<vtkPolyData> PolylineReferenceTubes(vtkPolyData* lines, int sides = 64)
{
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(lines);
  input->GetPointData()->SetActiveScalars("Radius");
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(input);
  tubes->SetNumberOfSides(sides);
  tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
  tubes->CappingOn();
  tubes->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(tubes->GetOutput());
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

/// Pixel-for-pixel comparison of two frames of the same scene drawn two
/// ways (an optimization on and off): covered pixels (depth < 1 or a color
/// away from `background`, 0-255, in either), pixels whose color differs by
/// more than 2 in a channel, pixels whose window depth differs by more than
/// 1e-5.
struct PixelDifference
{
  long Covered = 0;
  long Color = 0;
  long Depth = 0;
};

inline PixelDifference ComparePixels(const Frame& a, const Frame& b, const int background[3])
{
  PixelDifference d;
  for (int i = 0; i < a.Width * a.Height; ++i)
  {
    // (translucent geometry writes no depth, so its color counts too)
    bool covered = a.Depth[i] < 1.0f || b.Depth[i] < 1.0f;
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      covered = covered || std::abs(int(a.RGB[3 * i + c]) - background[c]) > 3 ||
        std::abs(int(b.RGB[3 * i + c]) - background[c]) > 3;
      worst = std::max(worst, std::abs(int(a.RGB[3 * i + c]) - int(b.RGB[3 * i + c])));
    }
    d.Covered += covered ? 1 : 0;
    d.Color += worst > 2 ? 1 : 0;
    d.Depth += std::abs(a.Depth[i] - b.Depth[i]) > 1e-5f ? 1 : 0;
  }
  return d;
}

/// The camera on an orbit around the origin at `distance` (30 degree view
/// angle, parallel scale 20 when `parallel`), clipping range reset.
inline void SetOrbitView(vtkRenderer* renderer, int parallel, double distance)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.35 * distance, 0.25 * distance, distance);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(20.0);
  renderer->ResetCameraClippingRange();
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

struct Measures
{
  long Covered[2] = { 0, 0 }; ///< test, reference
  double IoU = 0.0;
  double DepthShare = 0.0; ///< common pixels whose eye depths agree within the tolerance
  long Common = 0;
  double MeanDepthDifference = 0.0; ///< test - reference over the common pixels (view units)
};

/// IoU of the covered pixels and the share of the common pixels whose eye
/// depths (linearized with the camera's clipping range) differ by at most
/// `depthTolerance`, or by at most the pixel's value of `tolerances` if given.
inline Measures Measure(const SplineVizTest::Frame& test, const SplineVizTest::Frame& reference,
  vtkCamera* camera, double depthTolerance, const std::vector<double>* tolerances = nullptr)
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
        close += std::abs(da - db) <= (tolerances ? (*tolerances)[i] : depthTolerance) ? 1 : 0;
        m.MeanDepthDifference += da - db;
      }
    }
  }
  m.Common = both;
  m.MeanDepthDifference /= static_cast<double>(std::max(both, 1L));
  m.IoU = either > 0 ? static_cast<double>(both) / either : 1.0;
  m.DepthShare = both > 0 ? static_cast<double>(close) / both : 1.0;
  return m;
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

using CameraSetup = std::function<void(vtkCamera*)>;

/// Render `mapper` in a renderer of its own in `window`, shaded (gray,
/// diffuse) with the camera `setup`; the clipping range is fixed from
/// `bounds` so that renderings of the same bounds share it. The actor is
/// moved to `actorPosition` if given (negative controls).
inline Frame Render(vtkRenderWindow* window, vtkMapper* mapper, const CameraSetup& setup,
  const double bounds[6], vtkCamera* cameraOut, const double* actorPosition = nullptr)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  if (actorPosition)
  {
    actor->SetPosition(actorPosition[0], actorPosition[1], actorPosition[2]);
  }
  actor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  actor->GetProperty()->SetAmbient(0.1);
  actor->GetProperty()->SetDiffuse(0.9);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.0, 0.0, 0.0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  setup(camera);
  renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
  Frame frame = SplineVizTest::Grab(window);
  cameraOut->DeepCopy(camera);
  window->RemoveRenderer(renderer);
  return frame;
}

/// The radius of the tube seen at each pixel: `reference` (tubes with the
/// point array "Radius") rendered unlit with the radius mapped to gray over
/// [rMin, rMax], with the camera `setup`; 0 where nothing is seen.
inline std::vector<double> RadiusFrame(vtkRenderWindow* window, vtkPolyData* reference,
  const CameraSetup& setup, const double bounds[6], double rMin, double rMax)
{
  vtkNew<vtkLookupTable> gray;
  gray->SetTableRange(rMin, rMax);
  gray->SetSaturationRange(0.0, 0.0);
  gray->SetValueRange(0.0, 1.0);
  gray->SetRampToLinear();
  gray->SetNumberOfTableValues(256);
  gray->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(reference);
  mapper->SetLookupTable(gray);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Radius");
  mapper->SetScalarRange(rMin, rMax);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  window->AddRenderer(renderer);
  setup(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange(const_cast<double*>(bounds));
  const Frame frame = Grab(window);
  window->RemoveRenderer(renderer);
  std::vector<double> radius(frame.Depth.size(), 0.0);
  for (size_t i = 0; i < radius.size(); ++i)
  {
    if (frame.Depth[i] < 1.0f)
    {
      radius[i] = rMin + (rMax - rMin) * frame.RGB[3 * i] / 255.0;
    }
  }
  return radius;
}
}

#endif
