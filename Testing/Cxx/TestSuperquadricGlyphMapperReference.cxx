// SPDX-License-Identifier: BSD-3-Clause
// The GPU superquadric glyphs against an independent polygonal reference
// (SuperquadricGlyphTestUtilities.h: vtkMath::Jacobi, Kindlmann's rule written
// out in the test, vtkSuperquadricSource at 256 x 128, vtkPolyDataMapper):
//  - hand-made tensors (linear, planar, spherical, cl == cp, repeated
//    eigenvalues, mixed signs, thin plate, needle, ...) at gamma 0, 3 and 20;
//  - coverage: every pixel where the two renderings differ lies within one
//    pixel of the reference silhouette;
//  - depth: the eye-space depth of pixels covered by both agrees (exact depth
//    of the ray caster against the fine mesh);
//  - the comparison is sensitive: the same code run on deliberately wrong
//    CPU references (axis switch inverted, alpha and beta swapped, eigenvector
//    order reversed) reports clear failures.
// Images of each rendering and of the differences go to the test output
// directory (-T) for inspection.
#include "vtkSuperquadricGlyphMapper.h"

#include "SplineVizTestUtilities.h"
#include "SuperquadricGlyphTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTesting.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <string>
#include <vector>

namespace
{
constexpr int W = 480;
constexpr int H = 360;

struct Capture
{
  std::vector<unsigned char> Mask; // 1 = covered
  std::vector<float> Depth;        // eye-space distance along -z
};

Capture Grab(vtkRenderWindow* window, vtkRenderer* renderer, const std::string& png)
{
  window->Render();
  Capture c;
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  const int nc = rgb->GetNumberOfComponents();
  c.Mask.resize(W * H);
  for (int i = 0; i < W * H; ++i)
  {
    c.Mask[i] = rgb->GetValue(i * nc) > 127 ? 1 : 0;
  }
  std::vector<float> z(W * H);
  window->GetZbufferData(0, 0, W - 1, H - 1, z.data());
  double range[2];
  renderer->GetActiveCamera()->GetClippingRange(range);
  const double n = range[0], f = range[1];
  c.Depth.resize(W * H);
  for (int i = 0; i < W * H; ++i)
  {
    const double ndc = 2.0 * z[i] - 1.0;
    c.Depth[i] = static_cast<float>(2.0 * n * f / (f + n - ndc * (f - n)));
  }
  if (!png.empty())
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(png.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
  }
  return c;
}

struct Comparison
{
  int Mismatches = 0;
  int Untolerated = 0;
  int Covered = 0;
  double DepthMedian = 0.0;
  double DepthP99 = 0.0;
  double DepthMax = 0.0;
};

bool Boundary(const std::vector<unsigned char>& m, int x, int y, int radius)
{
  const unsigned char v = m[y * W + x];
  for (int dy = -radius; dy <= radius; ++dy)
  {
    for (int dx = -radius; dx <= radius; ++dx)
    {
      const int xx = x + dx, yy = y + dy;
      if (xx >= 0 && yy >= 0 && xx < W && yy < H && m[yy * W + xx] != v)
      {
        return true;
      }
    }
  }
  return false;
}

Comparison Compare(const Capture& gpu, const Capture& ref, const std::string& diffPng)
{
  Comparison r;
  std::vector<double> dz;
  vtkNew<vtkImageData> diff;
  diff->SetDimensions(W, H, 1);
  diff->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  unsigned char* d = static_cast<unsigned char*>(diff->GetScalarPointer());
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      const int i = y * W + x;
      const bool a = gpu.Mask[i] != 0, b = ref.Mask[i] != 0;
      r.Covered += b;
      unsigned char* px = d + 3 * i;
      px[0] = px[1] = px[2] = b ? 60 : 0;
      if (a != b)
      {
        ++r.Mismatches;
        const bool tolerated = Boundary(ref.Mask, x, y, 1);
        r.Untolerated += !tolerated;
        px[0] = tolerated ? 0 : 255;
        px[1] = tolerated ? 160 : 0;
        px[2] = tolerated ? 255 : 0;
      }
      else if (a && !Boundary(ref.Mask, x, y, 2) && !Boundary(gpu.Mask, x, y, 2))
      {
        dz.push_back(std::abs(gpu.Depth[i] - ref.Depth[i]));
      }
    }
  }
  if (!dz.empty())
  {
    std::sort(dz.begin(), dz.end());
    r.DepthMedian = dz[dz.size() / 2];
    r.DepthP99 = dz[dz.size() * 99 / 100];
    r.DepthMax = dz.back();
  }
  if (!diffPng.empty())
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(diffPng.c_str());
    writer->SetInputData(diff);
    writer->Write();
  }
  return r;
}
}

int TestSuperquadricGlyphMapperReference(int argc, char* argv[])
{
  SplineVizTestStatus status;
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string out = testing->GetTempDirectory() ? testing->GetTempDirectory() : ".";

  std::vector<std::array<double, 6>> tensors;
  for (const auto& h : sqtest::HandTensors())
  {
    tensors.push_back(sqtest::Compose(h));
  }
  auto image = sqtest::TensorImage(tensors, 4);
  const double scale = 0.42;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(W, H);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(1.5, 1.0, 0.0);
  camera->SetPosition(3.2, -2.6, 4.4);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(32);
  camera->SetClippingRange(2.0, 12.0);

  vtkNew<vtkSuperquadricGlyphMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetScaleFactor(scale);
  mapper->SetNegativeEigenvaluePolicy(vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES);
  mapper->SetGlyphColorMode(vtkSuperquadricGlyphMapper::COLOR_SOLID);
  auto gpuActor = sqtest::UnlitWhiteActor(mapper);

  vtkNew<vtkPolyDataMapper> refMapper;
  refMapper->ScalarVisibilityOff();
  auto refActor = sqtest::UnlitWhiteActor(refMapper);

  for (double gamma : { 0.0, 3.0, 20.0 })
  {
    const std::string tag = "gamma" + std::to_string(static_cast<int>(gamma));
    mapper->SetGamma(gamma);
    renderer->RemoveAllViewProps();
    renderer->AddActor(gpuActor);
    const Capture gpu =
      Grab(window, renderer, out + "/TestSuperquadricGlyphMapperReference-gpu-" + tag + ".png");
    SV_CHECK(status, mapper->GetNumberOfGlyphs() == 12);

    sqtest::ReferenceSettings settings;
    settings.Gamma = gamma;
    settings.ScaleFactor = scale;
    renderer->RemoveAllViewProps();
    renderer->AddActor(refActor);
    refMapper->SetInputData(sqtest::ReferenceGlyphs(image, settings));
    const Capture ref =
      Grab(window, renderer, out + "/TestSuperquadricGlyphMapperReference-ref-" + tag + ".png");
    const Comparison c =
      Compare(gpu, ref, out + "/TestSuperquadricGlyphMapperReference-diff-" + tag + ".png");
    std::cout << tag << ": " << c.Covered << " covered pixels, " << c.Mismatches
              << " differ (all within 1 px of the silhouette but " << c.Untolerated
              << "); depth difference median " << c.DepthMedian << ", 99% " << c.DepthP99
              << ", max " << c.DepthMax << std::endl;
    SV_CHECK(status, c.Covered > 10000);
    SV_CHECK_MSG(status, c.Untolerated == 0, tag << ": " << c.Untolerated << " pixels differ");
    SV_CHECK_MSG(status, c.DepthP99 < 2e-3, tag << ": depth");

    // The comparison must catch wrong implementations.
    for (sqtest::Mutation mutation :
      { sqtest::WRONG_AXIS_SWITCH, sqtest::SWAPPED_ALPHA_BETA, sqtest::WRONG_EIGENVECTOR_ORDER })
    {
      if (gamma == 0.0 && mutation != sqtest::WRONG_EIGENVECTOR_ORDER)
      {
        continue; // ellipsoids: alpha = beta = 1, no axis to switch
      }
      settings.Mutate = mutation;
      refMapper->SetInputData(sqtest::ReferenceGlyphs(image, settings));
      const Capture bad = Grab(window, renderer, "");
      const Comparison cb = Compare(gpu, bad,
        out + "/TestSuperquadricGlyphMapperReference-mutation" + std::to_string(mutation) + "-" +
          tag + ".png");
      std::cout << "  mutation " << mutation << ": " << cb.Untolerated
                << " pixels differ by more than 1 px" << std::endl;
      SV_CHECK_MSG(status, cb.Untolerated > 100,
        tag << ": the comparison did not detect mutation " << mutation);
    }
  }
  return status.Result();
}
