// SPDX-License-Identifier: BSD-3-Clause
// Test scenes and image helpers shared by the tube-renderer tests.
//
// - MakeTestTubes(): polylines with coarse nodes (so that the splines bend a
//   lot between nodes), strongly varying radii, a scalar for coloring, a
//   one-segment tube and a tube with a sharp radius change;
// - ResampleSplines(): an independent evaluation of the cubic Hermite splines
//   documented in vtkSplineTubeCore (Catmull-Rom tangents inside a tube,
//   second-order one-sided differences at its ends, a straight line for two
//   nodes; the same rule for the radius), written here from that
//   documentation, so that a reference tube can be built without the code
//   under test;
// - masks of rendered images and their comparison "to about a pixel".
#ifndef SplineTubeTestScenes_h
#define SplineTubeTestScenes_h

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkImageData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace SplineTubeTest
{
using P3 = std::array<double, 3>;

/// One polyline: points and radii.
struct Line
{
  std::vector<P3> Points;
  std::vector<double> Radii;
};

inline vtkSmartPointer<vtkPolyData> MakePolyData(const std::vector<Line>& lines)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkFloatArray> scalar;
  scalar->SetName("Scalar");
  vtkNew<vtkCellArray> cells;
  for (const Line& line : lines)
  {
    cells->InsertNextCell(static_cast<int>(line.Points.size()));
    for (size_t i = 0; i < line.Points.size(); ++i)
    {
      const vtkIdType id = points->InsertNextPoint(line.Points[i].data());
      radius->InsertNextValue(static_cast<float>(line.Radii[i]));
      scalar->InsertNextValue(static_cast<float>(i) / std::max<size_t>(1, line.Points.size() - 1));
      cells->InsertCellPoint(id);
    }
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetLines(cells);
  pd->GetPointData()->AddArray(radius);
  pd->GetPointData()->AddArray(scalar);
  return pd;
}

/// A coarse helix (8 nodes per turn) with a varying radius, a curved tube
/// with a sharp radius change, a one-segment tube, a tilted loop with 100
/// degree turns per segment.
inline std::vector<Line> TestLines()
{
  std::vector<Line> lines(4);
  for (int i = 0; i <= 13; ++i)
  {
    const double a = 0.785398 * i;
    lines[0].Points.push_back({ std::cos(a), std::sin(a), 0.22 * i - 1.4 });
    lines[0].Radii.push_back(0.16 + 0.09 * std::sin(0.9 * i));
  }
  for (int i = 0; i <= 6; ++i)
  {
    lines[1].Points.push_back(
      { -2.4 + 0.15 * i * i * 0.3, -0.6 + 0.35 * i, 0.4 * std::sin(0.8 * i) });
    lines[1].Radii.push_back(i < 3 ? 0.1 : 0.2);
  }
  lines[2].Points = { { 2.0, -1.2, 0.3 }, { 2.2, 0.2, -0.2 } };
  lines[2].Radii = { 0.2, 0.1 };
  for (int i = 0; i <= 4; ++i)
  {
    const double a = 1.745329 * i;
    lines[3].Points.push_back({ 0.9 * std::cos(a), 0.9 * std::sin(a), 2.3 + 0.3 * std::cos(a) });
    lines[3].Radii.push_back(0.09);
  }
  return lines;
}

/// Derivatives of `n` values at unit spacing as vtkSplineTubeCore documents
/// them (Catmull-Rom inside, second-order one-sided at the ends, the chord
/// for two values).
inline std::vector<double> Derivatives(const std::vector<double>& v)
{
  const size_t n = v.size();
  std::vector<double> d(n, 0.0);
  if (n == 2)
  {
    d[0] = d[1] = v[1] - v[0];
    return d;
  }
  d[0] = 0.5 * (-3.0 * v[0] + 4.0 * v[1] - v[2]);
  for (size_t i = 1; i + 1 < n; ++i)
  {
    d[i] = 0.5 * (v[i + 1] - v[i - 1]);
  }
  d[n - 1] = 0.5 * (3.0 * v[n - 1] - 4.0 * v[n - 2] + v[n - 3]);
  return d;
}

/// Cubic Hermite interpolation on [0, 1].
inline double Hermite(double p0, double m0, double p1, double m1, double t)
{
  const double t2 = t * t;
  const double t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
    (t3 - t2) * m1;
}

/// The splines through the lines' nodes, sampled `samples` times per segment.
inline std::vector<Line> ResampleSplines(const std::vector<Line>& lines, int samples)
{
  std::vector<Line> out;
  for (const Line& line : lines)
  {
    const size_t n = line.Points.size();
    std::array<std::vector<double>, 4> values; // x, y, z, r
    for (size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        values[c].push_back(line.Points[i][c]);
      }
      values[3].push_back(line.Radii[i]);
    }
    std::array<std::vector<double>, 4> derivs;
    for (int c = 0; c < 4; ++c)
    {
      derivs[c] = Derivatives(values[c]);
    }
    Line dense;
    for (size_t s = 0; s + 1 < n; ++s)
    {
      for (int k = (s == 0 ? 0 : 1); k <= samples; ++k)
      {
        const double t = static_cast<double>(k) / samples;
        P3 p;
        for (int c = 0; c < 3; ++c)
        {
          p[c] = Hermite(values[c][s], derivs[c][s], values[c][s + 1], derivs[c][s + 1], t);
        }
        dense.Points.push_back(p);
        dense.Radii.push_back(
          Hermite(values[3][s], derivs[3][s], values[3][s + 1], derivs[3][s + 1], t));
      }
    }
    out.push_back(dense);
  }
  return out;
}

/// The window's image (RGB, bottom row first).
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> RGB;
  const unsigned char* At(int x, int y) const { return &RGB[3 * (y * Width + x)]; }
};

inline Image Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  Image result;
  int dims[3];
  image->GetDimensions(dims);
  result.Width = dims[0];
  result.Height = dims[1];
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  result.RGB.assign(scalars->GetPointer(0), scalars->GetPointer(0) + 3 * dims[0] * dims[1]);
  return result;
}

/// Pixels that differ from the background color.
inline std::vector<unsigned char> Mask(const Image& image, const unsigned char background[3])
{
  std::vector<unsigned char> mask(static_cast<size_t>(image.Width * image.Height), 0);
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      const unsigned char* c = image.At(x, y);
      mask[y * image.Width + x] =
        (c[0] != background[0] || c[1] != background[1] || c[2] != background[2]) ? 1 : 0;
    }
  }
  return mask;
}

/// Dilation (grow = true) or erosion by `r` pixels (Chebyshev distance).
inline std::vector<unsigned char> Morph(
  const std::vector<unsigned char>& mask, int width, int height, int r, bool grow)
{
  std::vector<unsigned char> out(mask.size(), 0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      bool any = false;
      bool all = true;
      for (int dy = -r; dy <= r; ++dy)
      {
        for (int dx = -r; dx <= r; ++dx)
        {
          const int xx = x + dx;
          const int yy = y + dy;
          const bool v = xx >= 0 && yy >= 0 && xx < width && yy < height && mask[yy * width + xx];
          any = any || v;
          all = all && v;
        }
      }
      out[y * width + x] = (grow ? any : all) ? 1 : 0;
    }
  }
  return out;
}

/// Coverage comparison to within `tolerance` pixels: pixels of `test` more
/// than `tolerance` outside `reference` (extra) and pixels of `reference`
/// more than `tolerance` inside it that `test` misses (missing).
struct Coverage
{
  long Reference = 0;
  long Extra = 0;
  long Missing = 0;
};

inline Coverage CompareCoverage(const std::vector<unsigned char>& reference,
  const std::vector<unsigned char>& test, int width, int height, int tolerance)
{
  Coverage result;
  const auto grown = Morph(reference, width, height, tolerance, true);
  const auto shrunk = Morph(reference, width, height, tolerance, false);
  for (size_t i = 0; i < reference.size(); ++i)
  {
    result.Reference += reference[i];
    result.Extra += (test[i] && !grown[i]) ? 1 : 0;
    result.Missing += (shrunk[i] && !test[i]) ? 1 : 0;
  }
  return result;
}
}

#endif
