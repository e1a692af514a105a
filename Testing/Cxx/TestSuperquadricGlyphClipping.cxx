// SPDX-License-Identifier: BSD-3-Clause
// Clipping planes of vtkSuperquadricGlyphMapper: the glyphs are solids cut
// by the planes, checked pixel by pixel against an independent CPU
// evaluation (the glyph solids of SuperquadricGlyphTestUtilities.h: Jacobi
// eigen-systems, the shape rules written out in the test) for Kindlmann's
// glyphs and the Schultz-Kindlmann shapes, two planes, an oblique camera:
//  - beyond a plane nothing is drawn: every covered pixel's point (from the
//    depth buffer) lies on the kept side of both planes;
//  - where the unclipped picture shows a kept surface point, the clipped
//    picture shows the same point (within 2e-3, the root finders' tolerance);
//  - where the cut is seen, the depth is the plane's along the pixel's ray
//    and that point is inside a glyph (the CPU solid), and the cut's normal
//    is the plane's (diffuse shading of a headlight);
//  - no cut is missing: pixels empty in the clipped picture whose ray has a
//    kept part inside a glyph (sampled on the CPU) are counted (none of more
//    than 2 samples deep);
//  - the checks can fail: the unclipped picture has thousands of pixels
//    beyond the planes.
#include "vtkSuperquadricGlyphMapper.h"

#include "SplineVizTestUtilities.h"
#include "SuperquadricGlyphTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <array>
#include <iostream>
#include <vector>

namespace
{
constexpr int W = 360;
constexpr int H = 300;

struct Picture
{
  std::vector<float> Depth;
  std::vector<unsigned char> RGB;
};

Picture Grab(vtkRenderWindow* window)
{
  window->Render();
  Picture p;
  p.Depth.resize(W * H);
  window->GetZbufferData(0, 0, W - 1, H - 1, p.Depth.data());
  unsigned char* rgb = window->GetPixelData(0, 0, W - 1, H - 1, 0);
  p.RGB.assign(rgb, rgb + 3 * W * H);
  delete[] rgb;
  return p;
}
}

int TestSuperquadricGlyphClipping(int, char*[])
{
  SplineVizTestStatus status;
  // tensors: definite and indefinite, on a row
  const std::vector<sqtest::HandTensor> hand = {
    { { 1.0, 0.55, 0.3 }, { 20, 30, 40 }, "definite" },
    { { 1.0, 0.6, -0.4 }, { -30, 15, 60 }, "(+,+,-)" },
    { { 0.9, 0.3, 0.25 }, { 60, -40, 10 }, "linear" },
    { { 1.0, -0.3, -0.7 }, { 45, -25, 30 }, "(+,-,-)" },
  };
  std::vector<std::array<double, 6>> tensors;
  for (const auto& h : hand)
  {
    tensors.push_back(sqtest::Compose(h));
  }
  auto image = sqtest::TensorImage(tensors, 4);
  const double scale = 0.48;
  const double gamma = 3.0;

  vtkNew<vtkPlane> plane0;
  plane0->SetOrigin(1.2, 0.0, 0.05);
  plane0->SetNormal(0.25, 0.35, -1.0); // keeps z below about 0.05
  vtkNew<vtkPlane> plane1;
  plane1->SetOrigin(2.6, 0.0, 0.0);
  plane1->SetNormal(-1.0, 0.1, 0.0); // keeps x below 2.6

  vtkNew<vtkSuperquadricGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetScaleFactor(scale);
  mapper->SetGamma(gamma);
  mapper->SetGlyphColorMode(vtkSuperquadricGlyphMapper::COLOR_SOLID);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1, 1, 1);
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetDiffuse(1.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0, 0, 0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(W, H);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(1.5, 0.0, 0.0);
  camera->SetPosition(1.9, -3.6, 2.6);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(35);
  camera->SetClippingRange(1.0, 10.0);
  vtkNew<vtkMatrix4x4> worldToNDC;
  worldToNDC->DeepCopy(camera->GetCompositeProjectionTransformMatrix(double(W) / H, -1, 1));
  vtkNew<vtkMatrix4x4> ndcToWorld;
  vtkMatrix4x4::Invert(worldToNDC, ndcToWorld);
  auto unproject = [&](int x, int y, double zWindow, double p[3])
  {
    double ndc[4] = { 2.0 * (x + 0.5) / W - 1.0, 2.0 * (y + 0.5) / H - 1.0, 2.0 * zWindow - 1.0,
      1.0 };
    double w[4];
    ndcToWorld->MultiplyPoint(ndc, w);
    for (int c = 0; c < 3; ++c)
    {
      p[c] = w[c] / w[3];
    }
  };
  double eye[3], dop[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(dop); // the headlight
  const double d0 = 1e-3;                // world units (glyphs are about 0.5)

  for (int policy :
    { vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES, vtkSuperquadricGlyphMapper::SCHULTZ_KINDLMANN })
  {
    mapper->SetNegativeEigenvaluePolicy(policy);
    const bool sk = policy == vtkSuperquadricGlyphMapper::SCHULTZ_KINDLMANN;
    // the CPU solids (ABSOLUTE_VALUES: Kindlmann's glyph of |l|)
    std::vector<sqtest::GlyphSolid> solids;
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(tensors.size()); ++i)
    {
      double c[3];
      image->GetPoint(i, c);
      solids.push_back(sqtest::SKGlyphSolid(tensors[i].data(), c, gamma, scale, 0.2, 0.05,
        sk ? sqtest::SK_NONE : sqtest::SK_ABSOLUTE_KINDLMANN));
    }
    auto insideAny = [&](const double p[3])
    {
      for (const auto& s : solids)
      {
        if (s.Inside(p))
          return true;
      }
      return false;
    };
    mapper->RemoveAllClippingPlanes();
    const Picture full = Grab(window);
    mapper->AddClippingPlane(plane0);
    mapper->AddClippingPlane(plane1);
    const Picture clipped = Grab(window);

    long covered = 0, beyond = 0, keptSame = 0, keptDiffer = 0, cut = 0, cutOutside = 0,
         cutBadShade = 0, missing = 0, beyondUnclipped = 0;
    for (int y = 0; y < H; ++y)
    {
      for (int x = 0; x < W; ++x)
      {
        const int i = y * W + x;
        double ray[3], dir[3];
        unproject(x, y, 0.5, ray);
        for (int c = 0; c < 3; ++c)
        {
          dir[c] = ray[c] - eye[c];
        }
        if (clipped.Depth[i] < 1.0f)
        {
          ++covered;
          double p[3];
          unproject(x, y, clipped.Depth[i], p);
          const double v0 = plane0->EvaluateFunction(p), v1 = plane1->EvaluateFunction(p);
          beyond += (v0 < -d0 || v1 < -d0) ? 1 : 0;
          if (std::abs(v0) < d0 || std::abs(v1) < d0)
          {
            // on a cut: inside a glyph, shaded with the plane's normal
            ++cut;
            double q[3];
            unproject(x, y, clipped.Depth[i] + 2e-6, q); // a little behind
            cutOutside += insideAny(q) ? 0 : 1;
            vtkPlane* pl = std::abs(v0) < d0 ? plane0 : plane1;
            double n[3];
            pl->GetNormal(n);
            const double expected =
              255.0 * std::abs(vtkMath::Dot(n, dop)) / std::sqrt(vtkMath::Dot(n, n));
            cutBadShade += std::abs(clipped.RGB[3 * i] - expected) > 12 ? 1 : 0;
          }
        }
        if (full.Depth[i] < 1.0f)
        {
          double p[3];
          unproject(x, y, full.Depth[i], p);
          // negative control: the unclipped picture fails the first check
          beyondUnclipped +=
            (plane0->EvaluateFunction(p) < -d0 || plane1->EvaluateFunction(p) < -d0) ? 1 : 0;
          if (plane0->EvaluateFunction(p) > d0 && plane1->EvaluateFunction(p) > d0)
          {
            // a kept surface point: unchanged (within the root finders'
            // tolerance: the clipped ray may start at a plane)
            double q[3];
            unproject(x, y, clipped.Depth[i], q);
            const double dq[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
            (clipped.Depth[i] < 1.0f && vtkMath::Dot(dq, dq) < 4e-6 ? keptSame : keptDiffer)++;
          }
          else if (clipped.Depth[i] >= 1.0f)
          {
            // empty after clipping: the ray's kept part must miss the glyphs
            int inside = 0;
            for (int k = 1; k < 2000 && inside < 3; ++k)
            {
              const double s = k / 2000.0;
              double q[3];
              for (int c = 0; c < 3; ++c)
              {
                q[c] = eye[c] + (1.0 + 7.0 * s) * dir[c] / std::sqrt(vtkMath::Dot(dir, dir));
              }
              if (plane0->EvaluateFunction(q) > 0 && plane1->EvaluateFunction(q) > 0 &&
                insideAny(q))
              {
                ++inside;
              }
            }
            missing += inside >= 3 ? 1 : 0;
          }
        }
      }
    }
    std::cout << (sk ? "Schultz-Kindlmann" : "Kindlmann") << ": " << covered << " covered pixels, "
              << beyond << " beyond a plane; kept surface " << keptSame << " unchanged, "
              << keptDiffer << " changed; " << cut << " on the cut, " << cutOutside
              << " of them outside the glyphs, " << cutBadShade << " shaded unlike the plane; "
              << missing << " cut pixels missing; unclipped: " << beyondUnclipped
              << " beyond a plane" << std::endl;
    SV_CHECK(status, beyondUnclipped > 1000);
    SV_CHECK(status, covered > 3000);
    SV_CHECK(status, beyond == 0);
    SV_CHECK(status, keptSame > 1500);
    SV_CHECK(status, keptDiffer <= keptSame / 500);
    SV_CHECK(status, cut > 1000);
    SV_CHECK(status, cutOutside <= cut / 200);
    SV_CHECK(status, cutBadShade <= cut / 100);
    SV_CHECK(status, missing <= cut / 200);
  }
  mapper->RemoveAllClippingPlanes();
  return status.Result();
}
