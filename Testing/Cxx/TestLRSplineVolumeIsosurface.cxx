// SPDX-License-Identifier: BSD-3-Clause
// The depth vtkLRSplineVolumeMapper writes for an isosurface agrees with an
// exact root of the spline along the same rays: the CPU reference
// (LRSplineVolumeTestUtilities.h) brackets the first crossing at uniform
// steps ten times finer than the mapper's finest step and bisects it 60
// times in double precision on vtkLRSplineField; the mapper's z-buffer is
// turned back into the eye-ray distance. The volume is placed by a
// non-trivial vtkVolume matrix (rotation, translation, non-uniform scale), so
// that the data-to-world transforms of rays and depths are exercised.
// Tolerances: 99 % of the pixels that both hit within 2e-5 of the volume's
// diagonal and none beyond 2e-4; coverage differs in at most 1 % of the
// pixels (silhouette). Negative control: one bisection step instead of 16
// must fail the same tolerance. The picture itself is compared too (RMS).
#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkLRSplineVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <iostream>

namespace
{
struct DepthResult
{
  double Fraction = 0.0; ///< of common pixels within the tight tolerance
  double Worst = 0.0;    ///< largest error / diagonal
  double CoverageMismatch = 0.0;
  double RMS = 0.0;
  bool Ok = false;
};

DepthResult Run(vtkMultiBlockDataSet* data, int bisections, const std::string& name)
{
  DepthResult result;
  const int width = 140, height = 105;
  const double background[3] = { 0.0, 0.0, 0.0 };
  vtkNew<vtkLRSplineVolumeMapper> mapper;
  mapper->SetInputDataObject(data);
  mapper->SetBlendModeToIsoSurface();
  mapper->SetIsosurfaceBisections(bisections);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 0.2, 0.5, 1.0);
  ctf->AddRGBPoint(1.0, 1.0, 0.8, 0.3);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 1.0);
  otf->AddPoint(1.0, 1.0);
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  property->ShadeOn();
  property->GetIsoSurfaceValues()->SetValue(0, 0.3);
  lrvolume::Scene scene(mapper, property, width, height, background);
  scene.Volume->SetOrientation(15, 30, -20);
  scene.Volume->SetPosition(1.0, -2.0, 0.5);
  scene.Volume->SetScale(1.6, 1.0, 0.7);
  scene.SetCamera(nullptr, 20, 15, 2.0);
  vtkVolume* volume = scene.Volume;
  vtkRenderer* ren = scene.Renderer;
  vtkRenderWindow* win = scene.Window;
  ren->ResetCameraClippingRange();
  win->Render();
  if (std::string(mapper->GetLastErrorMessage()) != "")
  {
    std::cerr << "ERROR: " << mapper->GetLastErrorMessage() << std::endl;
    return result;
  }
  const std::vector<float> depth = lrvolume::ReadDepth(win);
  const std::vector<double> gpu = lrvolume::ReadRGB(win);

  vtkLRSplineField field;
  std::string error;
  if (!field.Build(data, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
  {
    std::cerr << "ERROR: " << error << std::endl;
    return result;
  }
  lrvolume::View view;
  view.Set(ren, volume);
  lrvolume::Settings settings;
  settings.BlendMode = 5;
  settings.Shade = true;
  settings.IsoValues = { 0.3 };
  settings.Step = lrvolume::MinimumElementSide(field) / (1 << field.GetMaximumDegree()) / 10.0;
  const lrvolume::Image ref = lrvolume::Render(field, volume, view, settings);
  const std::vector<double> cpu = lrvolume::OverBackground(ref, background);
  result.RMS = lrvolume::RMS(gpu, cpu);
  lrvolume::WritePNG(gpu, width, height,
    std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeIsosurface-" + name + ".png");

  // World diagonal of the volume.
  double b[6];
  volume->GetBounds(b);
  const double diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  const double* eye = ren->GetActiveCamera()->GetPosition();
  auto worldDistance = [&](const double x[3])
  {
    double in[4] = { x[0], x[1], x[2], 1.0 }, w[4];
    view.DataToWorld->MultiplyPoint(in, w);
    return std::sqrt((w[0] - eye[0]) * (w[0] - eye[0]) + (w[1] - eye[1]) * (w[1] - eye[1]) +
      (w[2] - eye[2]) * (w[2] - eye[2]));
  };
  long long both = 0, close = 0, mismatch = 0, hits = 0;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const std::size_t p = static_cast<std::size_t>(j) * width + i;
      const bool gpuHit = depth[p] < 1.0f;
      const bool cpuHit = ref.FirstHit[p] >= 0;
      hits += cpuHit ? 1 : 0;
      if (gpuHit != cpuHit)
      {
        ++mismatch;
        continue;
      }
      if (!gpuHit)
      {
        continue;
      }
      double x[3];
      view.Unproject(
        2.0 * (i + 0.5) / width - 1.0, 2.0 * (j + 0.5) / height - 1.0, 2.0 * depth[p] - 1.0, x);
      const double err =
        std::abs(worldDistance(x) - worldDistance(ref.FirstHitPoint[p].data())) / diagonal;
      ++both;
      close += err <= 2e-5 ? 1 : 0;
      result.Worst = std::max(result.Worst, err);
    }
  }
  result.Fraction = both > 0 ? static_cast<double>(close) / both : 0.0;
  result.CoverageMismatch = hits > 0 ? static_cast<double>(mismatch) / hits : 1.0;
  std::cout << name << ": " << both << " pixels hit by both, " << 100.0 * result.Fraction
            << " % within 2e-5 of the diagonal, worst " << result.Worst << ", coverage mismatch "
            << 100.0 * result.CoverageMismatch << " % of " << hits << ", picture RMS " << result.RMS
            << " / 255" << std::endl;
  result.Ok = both > width * height / 6;
  return result;
}
}

int TestLRSplineVolumeIsosurface(int, char*[])
{
  SplineVizTestStatus status;
  vtkSmartPointer<vtkMultiBlockDataSet> data = lrvolume::RefinedScalarVolume(
    std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeIsosurface.lr", 4);
  SV_CHECK(status, data != nullptr);
  if (!data)
  {
    return status.Result();
  }
  const DepthResult good = Run(data, 16, "bisections16");
  SV_CHECK_MSG(status, good.Ok, "the isosurface covers too little of the picture");
  SV_CHECK(status, good.Fraction >= 0.99);
  SV_CHECK(status, good.Worst <= 2e-4);
  SV_CHECK(status, good.CoverageMismatch <= 0.01);
  SV_CHECK(status, good.RMS <= 2.0);

  const DepthResult coarse = Run(data, 1, "bisections1");
  SV_CHECK_MSG(status, coarse.Fraction < 0.99 || coarse.Worst > 2e-4,
    "negative control: one bisection step passes the depth tolerance, which cannot see a "
    "missing refinement");
  return status.Result();
}
