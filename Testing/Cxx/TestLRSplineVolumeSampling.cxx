// SPDX-License-Identifier: BSD-3-Clause
// Adaptive stepping (Fuchs et al. Eq. 4: the current element's shortest side
// over 2^degree) against uniform stepping at the smallest element's step, on
// a strongly locally refined volume: both pictures within the reference
// tolerance (RMS <= 2/255 against the CPU reference of
// LRSplineVolumeTestUtilities.h), the adaptive one with at least 2x fewer
// spline evaluations, counted per pixel by the mapper's CountSamples mode
// (24-bit counts in RGB). Negative control: a fixed step as long as the
// largest element's side without the transfer function's supersampling
// (§4.1) must fail the tolerance (the comparison sees under-sampling; with
// the supersampling this smooth field survives even that step, printed), and
// StepScale 4 must reduce the count about fourfold.
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

#include <iostream>

namespace
{
struct Setup
{
  vtkNew<vtkLRSplineVolumeMapper> Mapper;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  explicit Setup(vtkMultiBlockDataSet* data)
  {
    this->Mapper->SetInputDataObject(data);
    vtkNew<vtkColorTransferFunction> ctf;
    ctf->AddRGBPoint(0.0, 0.1, 0.2, 0.9);
    ctf->AddRGBPoint(0.5, 0.2, 0.9, 0.6);
    ctf->AddRGBPoint(1.1, 1.0, 0.4, 0.1);
    vtkNew<vtkPiecewiseFunction> otf;
    otf->AddPoint(0.0, 0.0);
    otf->AddPoint(0.25, 0.02);
    otf->AddPoint(0.6, 0.6);
    otf->AddPoint(1.1, 0.9);
    this->Property->SetColor(ctf);
    this->Property->SetScalarOpacity(otf);
    this->Property->SetScalarOpacityUnitDistance(0.08);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(80, 60);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
    this->Renderer->GetActiveCamera()->Azimuth(30);
    this->Renderer->GetActiveCamera()->Elevation(20);
    this->Renderer->ResetCamera();
    this->Renderer->GetActiveCamera()->Zoom(1.3);
  }

  // Total number of spline evaluations over all pixels.
  double Count()
  {
    this->Mapper->CountSamplesOn();
    this->Renderer->SetBackground(0, 0, 0);
    this->Window->Render();
    const std::vector<double> rgb = lrvolume::ReadRGB(this->Window);
    this->Mapper->CountSamplesOff();
    double total = 0.0;
    for (std::size_t p = 0; p + 2 < rgb.size(); p += 3)
    {
      total += rgb[p] + 256.0 * rgb[p + 1] + 65536.0 * rgb[p + 2];
    }
    return total;
  }

  std::vector<double> Picture(const double background[3])
  {
    this->Renderer->SetBackground(background[0], background[1], background[2]);
    this->Window->Render();
    return lrvolume::ReadRGB(this->Window);
  }
};
}

int TestLRSplineVolumeSampling(int, char*[])
{
  SplineVizTestStatus status;
  vtkIdType elements = 0;
  vtkSmartPointer<vtkMultiBlockDataSet> data = lrvolume::RefinedScalarVolume(
    std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeSampling.lr", 5, &elements, 4.0);
  SV_CHECK(status, data != nullptr);
  if (!data)
  {
    return status.Result();
  }
  vtkLRSplineField field;
  std::string error;
  SV_CHECK(status,
    field.Build(data, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
  const int degree = field.GetMaximumDegree();
  double smallest = 1e300, largest = 0.0;
  for (vtkIdType e = 0; e < field.GetPatch(0).GetNumberOfElements(); ++e)
  {
    const double s = field.GetPatch(0).GetElementMinimumSide(e);
    smallest = std::min(smallest, s);
    largest = std::max(largest, s);
  }
  std::cout << elements << " elements, shortest element sides from " << smallest << " to "
            << largest << " (ratio " << largest / smallest << ")" << std::endl;
  SV_CHECK_MSG(status, largest / smallest >= 8.0, "the volume is not refined enough to test");

  const double background[3] = { 0.1, 0.1, 0.12 };
  Setup s(data);
  // The reference at a tenth of the finest step.
  s.Window->Render();
  lrvolume::View view;
  view.Set(s.Renderer, s.Volume);
  lrvolume::Settings settings;
  settings.Step = smallest / (1 << degree) / 10.0;
  const std::vector<double> ref =
    lrvolume::OverBackground(lrvolume::Render(field, s.Volume, view, settings), background);
  const int w = s.Window->GetSize()[0], h = s.Window->GetSize()[1];

  // Adaptive (the default).
  const double adaptiveCount = s.Count();
  const std::vector<double> adaptive = s.Picture(background);
  const double adaptiveRMS = lrvolume::RMS(adaptive, ref);
  // Uniform at the smallest element's step (world = data units here).
  s.Mapper->AdaptiveStepsOff();
  s.Mapper->SetSampleDistance(smallest / (1 << degree));
  const double uniformCount = s.Count();
  const std::vector<double> uniform = s.Picture(background);
  const double uniformRMS = lrvolume::RMS(uniform, ref);
  // Uniform as long as the largest element's side: with the transfer
  // function supersampled between samples (§4.1) and without.
  s.Mapper->SetSampleDistance(largest);
  const double coarseCount = s.Count();
  const double coarseRMS = lrvolume::RMS(s.Picture(background), ref);
  s.Mapper->SetSupersampling(1);
  const double coarseNoSupersamplingRMS = lrvolume::RMS(s.Picture(background), ref);
  s.Mapper->SetSupersampling(4);
  // Adaptive with a scale of 4.
  s.Mapper->AdaptiveStepsOn();
  s.Mapper->SetStepScale(4.0);
  const double scaledCount = s.Count();
  s.Mapper->SetStepScale(1.0);

  const std::string out = std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeSampling-";
  lrvolume::WritePNG(adaptive, w, h, out + "adaptive.png");
  lrvolume::WritePNG(uniform, w, h, out + "uniform.png");
  lrvolume::WritePNG(ref, w, h, out + "reference.png");
  std::cout << "adaptive: " << adaptiveCount << " evaluations, RMS " << adaptiveRMS << " / 255\n"
            << "uniform at the finest step: " << uniformCount << " evaluations ("
            << uniformCount / adaptiveCount << "x), RMS " << uniformRMS << " / 255\n"
            << "uniform at the largest element's side: " << coarseCount << " evaluations, RMS "
            << coarseRMS << " / 255, without supersampling " << coarseNoSupersamplingRMS
            << " / 255\n"
            << "adaptive, StepScale 4: " << scaledCount << " evaluations ("
            << adaptiveCount / scaledCount << "x fewer)" << std::endl;
  SV_CHECK(status, lrvolume::CountNonBackground(ref, background) > w * h / 4);
  SV_CHECK(status, adaptiveRMS <= 2.0);
  SV_CHECK(status, uniformRMS <= 2.0);
  SV_CHECK_MSG(status, uniformCount >= 2.0 * adaptiveCount,
    "adaptive stepping must take at least 2x fewer samples than uniform stepping");
  SV_CHECK_MSG(status, coarseNoSupersamplingRMS > 2.0,
    "negative control: the coarse step without supersampling passes, the comparison cannot see "
    "under-sampling");
  SV_CHECK(status, adaptiveCount / scaledCount > 2.5 && adaptiveCount / scaledCount < 5.0);

  // Empty-space skipping: a transfer function transparent below 0.3 (most of
  // the volume): the elements whose coefficients stay below are jumped over,
  // with the same picture (against the reference and against no skipping)
  // and fewer samples.
  {
    vtkPiecewiseFunction* otf = s.Property->GetScalarOpacity();
    otf->RemoveAllPoints();
    otf->AddPoint(0.0, 0.0);
    otf->AddPoint(0.3, 0.0);
    otf->AddPoint(0.6, 0.6);
    otf->AddPoint(1.1, 0.9);
    s.Mapper->EmptySpaceSkippingOff();
    const double fullCount = s.Count();
    const std::vector<double> full = s.Picture(background);
    s.Mapper->EmptySpaceSkippingOn();
    const double skipCount = s.Count();
    const std::vector<double> skip = s.Picture(background);
    const vtkIdType skipped = s.Mapper->GetNumberOfSkippedElements();
    s.Window->Render();
    view.Set(s.Renderer, s.Volume);
    const std::vector<double> sparseRef =
      lrvolume::OverBackground(lrvolume::Render(field, s.Volume, view, settings), background);
    const double skipRMS = lrvolume::RMS(skip, sparseRef), fullRMS = lrvolume::RMS(full, sparseRef),
                 between = lrvolume::RMS(skip, full);
    std::cout << "empty-space skipping: " << skipped << " of " << elements
              << " elements skipped; " << fullCount << " evaluations without, " << skipCount
              << " with (" << fullCount / skipCount << "x fewer); RMS against the reference "
              << fullRMS << " without, " << skipRMS << " with; between the two " << between
              << " / 255" << std::endl;
    SV_CHECK(status, skipped > elements / 4);
    SV_CHECK(status, skipRMS <= 2.0 && fullRMS <= 2.0);
    SV_CHECK(status, between <= 0.5);
    SV_CHECK(status, fullCount > 1.3 * skipCount);
  }
  return status.Result();
}
