// SPDX-License-Identifier: BSD-3-Clause
// Occlusion culling of vtkSuperquadricGlyphMapper is exact: a dense volume of
// overlapping glyphs (32^3 points, glyphs overlapping 20-40 deep along the
// view) in two viewports of one window (a perspective camera in the left
// half, a parallel projection from another side in the right half, so the
// depth pyramids are read at a viewport origin other than 0), with an opaque
// polygon in front of part of the glyphs, multisampling off, rendered with
// culling off and on:
//  - Kindlmann's glyphs (SKIP_NEGATIVE) and the Schultz-Kindlmann glyphs of
//    indefinite tensors (the general ray caster, with its own early
//    rejection), and Kindlmann's glyphs cut by a clipping plane;
//  - the images agree within the image-test threshold (vtkImageDifference,
//    as vtkRegressionTestImageThreshold(window, 0.05)), and pixel by pixel:
//    at most 4 pixels differ at all (for depth ties between touching
//    glyphs; measured: none), the depth buffers likewise;
//  - culling does work: several depth pyramids are built, and the geometry
//    stage of the parallel view emits less than half the sprite triangles
//    (Kindlmann's glyphs; 80 % for the thinner indefinite and the clipped
//    glyphs, which hide less);
//  - the comparison can fail: leaving out one visible glyph (a mask array)
//    changes more pixels than the bound (vtkImageDifference does not see
//    it).
// The pictures with culling go to the test output directory.
#include "vtkSuperquadricGlyphMapper.h"

#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTesting.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int N = 32;  // points per side
constexpr int W = 480; // window: two viewports of 240 x 300
constexpr int H = 300;

/// A smooth tensor field on an N^3 grid (spacing 1): a twisting, varying
/// frame; eigenvalues 1 >= l2 >= l3 > 0, or, indefinite, l3 of either sign.
vtkSmartPointer<vtkImageData> Field(bool indefinite)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(N, N, N);
  vtkNew<vtkDoubleArray> tensors;
  tensors->SetName("T");
  tensors->SetNumberOfComponents(9);
  tensors->SetNumberOfTuples(static_cast<vtkIdType>(N) * N * N);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("mask");
  mask->SetNumberOfTuples(tensors->GetNumberOfTuples());
  mask->Fill(1);
  vtkIdType id = 0;
  for (int k = 0; k < N; ++k)
  {
    for (int j = 0; j < N; ++j)
    {
      for (int i = 0; i < N; ++i, ++id)
      {
        const double x = double(i) / N, y = double(j) / N, z = double(k) / N;
        const double a = 3.0 * z + 2.0 * x;
        double e1[3] = { std::cos(a), std::sin(a), 0.3 * std::sin(5.0 * y) };
        double n1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        for (double& c : e1)
          c /= n1;
        // e2 = z x e1 (normalized), e3 = e1 x e2
        double e2[3] = { -e1[1], e1[0], 0.0 };
        const double n2 = std::sqrt(e2[0] * e2[0] + e2[1] * e2[1]);
        for (double& c : e2)
          c /= n2;
        const double e3[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
          e1[0] * e2[1] - e1[1] * e2[0] };
        const double l1 = 1.0;
        const double l2 = 0.15 + 0.8 * (0.5 + 0.5 * std::sin(6.0 * x + 4.0 * y));
        double l3 = l2 * (0.2 + 0.75 * (0.5 + 0.5 * std::cos(5.0 * z + 3.0 * x)));
        if (indefinite)
        {
          l3 = -l3 * std::sin(4.0 * y + 2.0 * z); // both signs, through 0
        }
        double t[9];
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            t[3 * r + c] = l1 * e1[r] * e1[c] + l2 * e2[r] * e2[c] + l3 * e3[r] * e3[c];
        tensors->SetTuple(id, t);
      }
    }
  }
  image->GetPointData()->SetTensors(tensors);
  image->GetPointData()->AddArray(mask);
  return image;
}

struct Picture
{
  std::vector<unsigned char> RGB;
  std::vector<float> Depth;
  vtkSmartPointer<vtkImageData> Image;
};

Picture Grab(vtkRenderWindow* window)
{
  window->Render();
  Picture p;
  unsigned char* rgb = window->GetPixelData(0, 0, W - 1, H - 1, 0);
  p.RGB.assign(rgb, rgb + 3 * W * H);
  delete[] rgb;
  p.Depth.resize(W * H);
  window->GetZbufferData(0, 0, W - 1, H - 1, p.Depth.data());
  p.Image = vtkSmartPointer<vtkImageData>::New();
  p.Image->SetDimensions(W, H, 1);
  vtkNew<vtkUnsignedCharArray> scalars;
  scalars->SetNumberOfComponents(3);
  scalars->SetNumberOfTuples(W * H);
  std::copy(p.RGB.begin(), p.RGB.end(), scalars->GetPointer(0));
  p.Image->GetPointData()->SetScalars(scalars);
  return p;
}

struct Difference
{
  long Pixels = 0;      // pixels whose color differs at all
  long DepthPixels = 0; // pixels whose depth differs by more than 1e-6
  double ImageError = 0.0;
  double WorstDepth = 0.0;
};

Difference Compare(const Picture& a, const Picture& b)
{
  Difference d;
  for (int i = 0; i < W * H; ++i)
  {
    d.Pixels += a.RGB[3 * i] != b.RGB[3 * i] || a.RGB[3 * i + 1] != b.RGB[3 * i + 1] ||
      a.RGB[3 * i + 2] != b.RGB[3 * i + 2];
    d.DepthPixels += std::abs(a.Depth[i] - b.Depth[i]) > 1e-6f;
    d.WorstDepth = std::max(d.WorstDepth, double(std::abs(a.Depth[i] - b.Depth[i])));
  }
  vtkNew<vtkImageDifference> diff;
  diff->SetInputData(a.Image);
  diff->SetImageData(b.Image);
  diff->Update();
  d.ImageError = diff->GetThresholdedError();
  return d;
}
}

int TestSuperquadricGlyphCulling(int argc, char* argv[])
{
  SplineVizTestStatus status;
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string out = testing->GetTempDirectory() ? testing->GetTempDirectory() : ".";

  vtkNew<vtkSuperquadricGlyphMapper> mapper;
  mapper->SetScaleFactor(0.45);
  mapper->SetGamma(3.0);
  mapper->SetCountSprites(true);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  // an opaque square in front of a corner of the volume
  vtkNew<vtkPlaneSource> square;
  square->SetOrigin(-4, -6, 20);
  square->SetPoint1(12, -6, 20);
  square->SetPoint2(-4, -6, 36);
  vtkNew<vtkPolyDataMapper> squareMapper;
  squareMapper->SetInputConnection(square->GetOutputPort());
  vtkNew<vtkActor> squareActor;
  squareActor->SetMapper(squareMapper);
  squareActor->GetProperty()->SetColor(0.8, 0.7, 0.3);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(W, H);
  window->SetMultiSamples(0);
  const double c = 0.5 * (N - 1), d = 2.2 * N;
  vtkNew<vtkRenderer> left;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  for (vtkRenderer* r : { left.Get(), right.Get() })
  {
    r->AddActor(actor);
    r->AddActor(squareActor);
    r->SetBackground(0.1, 0.1, 0.12);
    window->AddRenderer(r);
  }
  vtkCamera* perspective = left->GetActiveCamera();
  perspective->SetFocalPoint(c, c, c);
  perspective->SetPosition(c + 0.35 * d, c - 0.8 * d, c + 0.5 * d);
  perspective->SetViewUp(0, 0, 1);
  perspective->SetViewAngle(30);
  perspective->SetClippingRange(0.2 * N, 4.0 * N);
  vtkCamera* parallel = right->GetActiveCamera();
  parallel->ParallelProjectionOn();
  parallel->SetFocalPoint(c, c, c);
  parallel->SetPosition(c - 0.6 * d, c - 0.7 * d, c - 0.3 * d);
  parallel->SetViewUp(0, 0, 1);
  parallel->SetParallelScale(0.75 * N);
  parallel->SetClippingRange(0.2 * N, 4.0 * N);

  const long bound = 4; // pixels (0.003 %), for depth ties
  struct Case
  {
    const char* What;
    bool Indefinite;
    bool Clip;
  };
  const Case cases[] = { { "Kindlmann", false, false },
    { "Schultz-Kindlmann, indefinite", true, false }, { "Kindlmann, clipped", false, true } };
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(c, c, c);
  plane->SetNormal(-0.3, 0.8, -0.5);
  for (const Case& k : cases)
  {
    auto field = Field(k.Indefinite);
    mapper->SetInputData(field);
    mapper->SetNegativeEigenvaluePolicy(k.Indefinite ? vtkSuperquadricGlyphMapper::SCHULTZ_KINDLMANN
                                                     : vtkSuperquadricGlyphMapper::SKIP_NEGATIVE);
    mapper->RemoveAllClippingPlanes();
    if (k.Clip)
    {
      mapper->AddClippingPlane(plane);
    }
    mapper->CullingOff();
    const Picture off = Grab(window);
    const vtkIdType spritesOff = mapper->GetLastSpriteTriangles();
    mapper->CullingOn();
    const Picture on = Grab(window);
    const vtkIdType spritesOn = mapper->GetLastSpriteTriangles();
    const int pyramids = mapper->GetLastNumberOfDepthPyramids();
    const Difference diff = Compare(off, on);
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(
      (out + "/TestSuperquadricGlyphCulling-" + std::to_string(&k - cases) + ".png").c_str());
    writer->SetInputData(on.Image);
    writer->Write();
    long covered = 0;
    for (int i = 0; i < W * H; ++i)
    {
      covered += off.Depth[i] < 1.0f;
    }
    std::cout << k.What << ": " << covered << " covered pixels; culling on/off: " << diff.Pixels
              << " pixels differ in color, " << diff.DepthPixels << " in depth (worst "
              << diff.WorstDepth << "), image error " << diff.ImageError << "; sprite triangles "
              << spritesOn << " of " << spritesOff << " (right viewport), " << pyramids
              << " depth pyramids" << std::endl;
    SV_CHECK_MSG(status, covered > W * H / 3, k.What << ": the glyphs do not fill the views");
    SV_CHECK_MSG(status, diff.ImageError <= 0.05, k.What << ": image error " << diff.ImageError);
    SV_CHECK_MSG(status, diff.Pixels <= bound, k.What << ": " << diff.Pixels << " pixels differ");
    SV_CHECK_MSG(
      status, diff.DepthPixels <= bound, k.What << ": " << diff.DepthPixels << " depths differ");
    SV_CHECK_MSG(status, pyramids >= 2, k.What << ": " << pyramids << " depth pyramids");
    SV_CHECK_MSG(status, spritesOn > 0 && spritesOn < (&k == cases ? 0.5 : 0.8) * spritesOff,
      k.What << ": culling did not cull (" << spritesOn << " of " << spritesOff << ")");

    if (&k == cases)
    {
      // Negative control: one visible glyph left out (the corner nearest to
      // the perspective camera).
      vtkUnsignedCharArray* mask =
        vtkUnsignedCharArray::SafeDownCast(field->GetPointData()->GetArray("mask"));
      const vtkIdType corner = (N - 1) + static_cast<vtkIdType>(N) * N * (N - 1);
      mask->SetValue(corner, 0);
      mask->Modified();
      mapper->SetMaskArray("mask");
      const Picture masked = Grab(window);
      const Difference control = Compare(on, masked);
      std::cout << "one glyph left out: " << control.Pixels << " pixels differ, worst depth "
                << control.WorstDepth << ", image error " << control.ImageError << std::endl;
      SV_CHECK_MSG(status, control.Pixels > 3 * bound,
        "the comparison cannot see a missing glyph (" << control.Pixels << " pixels)");
      mapper->SetMaskArray(nullptr);
    }
  }
  return status.Result();
}
