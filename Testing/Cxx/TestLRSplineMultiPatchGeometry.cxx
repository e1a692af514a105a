// SPDX-License-Identifier: BSD-3-Clause
// The real three-patch cube-3patch-refined.lr placed by its geometry
// (geometry mode): its patches are the unit cubes at x in [0, 1], [-1, 0]
// and [-2, -1], and its coefficients are the control points themselves, so
// the field is f(x) = x exactly -- an analytic reference for probing,
// tracing and volume rendering across the patches.
// - Probe at random points of a box around the geometry: inside, the value
//   is x to 1e-12 (every patch hit); outside, masked.
// - Stream tracer: v = x from a seed in the middle patch gives the ray
//   x(t) = s e^t: the line stays on the ray through the seed (1e-6), crosses
//   the interface x = -1 into the last patch and ends on its boundary x = -2.
// - Volume mapper (|f|, composite) against the CPU ray caster of
//   LRSplineVolumeTestUtilities.h over the analytic field on the box
//   [-2, 1] x [0, 1]^2: RMS at most 3/255.
// Negative controls: the same file in field mode (all patches stacked on
// the unit cube, what ParaView drew before) fails each check.
#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkLRSplineProbeFilter.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineStreamTracer.h"
#include "vtkLRSplineVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <random>
#include <string>

namespace
{
const double Box[6] = { -2.0, 1.0, 0.0, 1.0, 0.0, 1.0 };

bool InBox(const double x[3], double margin)
{
  for (int k = 0; k < 3; ++k)
  {
    if (x[k] < Box[2 * k] + margin || x[k] > Box[2 * k + 1] - margin)
    {
      return false;
    }
  }
  return true;
}

// f(x) = x on the box, for the CPU ray caster.
struct AnalyticField
{
  int GetNumberOfComponents() const { return 3; }
  void GetBounds(double b[6]) const { std::copy(Box, Box + 6, b); }
  template <class Index>
  int EvaluateWithHint(const double x[3], double* value, double* gradient, int&, Index&) const
  {
    if (!InBox(x, 0.0))
    {
      return -1;
    }
    for (int c = 0; c < 3; ++c)
    {
      value[c] = x[c];
      for (int k = 0; k < 3; ++k)
      {
        gradient[3 * c + k] = c == k ? 1.0 : 0.0;
      }
    }
    return 0;
  }
};

vtkSmartPointer<vtkMultiBlockDataSet> Read(bool geometry)
{
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr");
  reader->SetGeometryMode(geometry);
  reader->Update();
  return reader->GetOutput();
}

// Largest |f(x) - x| inside (-1: an inside point masked or an outside point
// not), and the patches hit (bits 1, 2, 4 for x > 0, in (-1, 0), < -1).
double Probe(vtkMultiBlockDataSet* data, int& hit)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(-2.2, 1.2), uy(-0.1, 1.1);
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 3000; ++i)
  {
    points->InsertNextPoint(ux(rng), uy(rng), uy(rng));
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkLRSplineProbeFilter> probe;
  probe->SetInputData(cloud);
  probe->SetSourceData(data);
  probe->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Field");
  probe->Update();
  vtkDataSet* out = vtkDataSet::SafeDownCast(probe->GetOutputDataObject(0));
  vtkDataArray* f = out ? out->GetPointData()->GetArray("Field") : nullptr;
  vtkDataArray* mask = out ? out->GetPointData()->GetArray("vtkValidPointMask") : nullptr;
  if (!f || !mask || f->GetNumberOfComponents() != 3)
  {
    return -1;
  }
  double worst = 0.0;
  hit = 0;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    const bool inside = mask->GetComponent(i, 0) != 0;
    // Away from the boundary (1e-9), inside and outside must agree.
    if ((InBox(x, 1e-9) && !inside) || (!InBox(x, -1e-9) && inside))
    {
      return -1;
    }
    if (inside)
    {
      for (int k = 0; k < 3; ++k)
      {
        worst = std::max(worst, std::abs(f->GetComponent(i, k) - x[k]));
      }
      hit |= x[0] > 0 ? 1 : (x[0] > -1 ? 2 : 4);
    }
  }
  return worst;
}

// The streamline of v = x from `seed`: largest distance from the ray through
// the seed, and the smallest x reached (1e300: no line).
void Trace(vtkMultiBlockDataSet* data, double& offRay, double& minX, bool& crossed)
{
  const double seed[3] = { -0.3, 0.1, 0.08 };
  vtkNew<vtkPolyData> seeds;
  vtkNew<vtkPoints> sp;
  sp->InsertNextPoint(seed);
  seeds->SetPoints(sp);
  vtkNew<vtkLRSplineStreamTracer> tracer;
  tracer->SetInputData(data);
  tracer->SetSourceData(seeds);
  tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Field");
  tracer->SetIntegratorTypeToRungeKutta4();
  tracer->SetStepModeToFixedLength();
  tracer->SetIntegrationStep(0.01);
  tracer->SetIntegrationDirectionToForward();
  tracer->SetMaximumNumberOfSteps(10000);
  tracer->Update();
  vtkPolyData* lines = vtkPolyData::SafeDownCast(tracer->GetOutputDataObject(0));
  offRay = 0.0;
  minX = 1e300;
  crossed = false;
  if (!lines || lines->GetNumberOfPoints() < 2)
  {
    return;
  }
  const double n = std::sqrt(seed[0] * seed[0] + seed[1] * seed[1] + seed[2] * seed[2]);
  bool before = false, after = false;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    double p[3];
    lines->GetPoint(i, p);
    // |p x s| / |s|: the distance from the ray.
    const double c[3] = { p[1] * seed[2] - p[2] * seed[1], p[2] * seed[0] - p[0] * seed[2],
      p[0] * seed[1] - p[1] * seed[0] };
    offRay = std::max(offRay, std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / n);
    minX = std::min(minX, p[0]);
    before = before || (p[0] > -1 && p[0] < 0);
    after = after || p[0] < -1;
  }
  crossed = before && after;
}

// RMS of the GPU's picture of |f| against the analytic reference.
double Render(vtkMultiBlockDataSet* data, const std::string& tag)
{
  const int width = 160, height = 90;
  const double background[3] = { 0.1, 0.1, 0.12 };
  vtkNew<vtkLRSplineVolumeMapper> mapper;
  mapper->SetInputDataObject(data);
  mapper->SetFieldArray("Field");
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 0.1, 0.2, 0.9);
  ctf->AddRGBPoint(1.2, 0.2, 0.9, 0.3);
  ctf->AddRGBPoint(2.45, 0.95, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 0.05);
  otf->AddPoint(2.45, 0.6);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  property->SetScalarOpacityUnitDistance(0.3);
  lrvolume::Scene scene(mapper, property, width, height, background);
  double bounds[6] = { -2.1, 1.1, -0.1, 1.1, -0.1, 1.1 };
  scene.SetCamera(bounds, 25, 20, 1.8);
  vtkVolume* volume = scene.Volume;
  vtkRenderer* ren = scene.Renderer;
  vtkRenderWindow* win = scene.Window;
  win->Render();
  win->Render();
  if (std::string(mapper->GetLastErrorMessage()) != "")
  {
    std::cerr << "ERROR: " << tag << ": " << mapper->GetLastErrorMessage() << std::endl;
    return -1;
  }
  const std::vector<double> gpu = lrvolume::ReadRGB(win);
  lrvolume::View view;
  view.Set(ren, volume);
  lrvolume::Settings settings;
  settings.Step = 0.002;
  AnalyticField field;
  const std::vector<double> cpu =
    lrvolume::OverBackground(lrvolume::Render(field, volume, view, settings), background);
  const std::string out =
    std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineMultiPatchGeometry-";
  lrvolume::WritePNG(gpu, width, height, out + tag + ".png");
  lrvolume::WritePNG(cpu, width, height, out + tag + "-cpu.png");
  lrvolume::WritePNG(gpu, width, height, out + tag + "-diff.png", &cpu);
  if (lrvolume::CountNonBackground(cpu, background) < width * height / 8)
  {
    std::cerr << "ERROR: the reference covers too few pixels" << std::endl;
    return -1;
  }
  const double rms = lrvolume::RMS(gpu, cpu);
  std::cout << tag << ": RMS " << rms << " / 255" << std::endl;
  return rms;
}
}

int TestLRSplineMultiPatchGeometry(int, char*[])
{
  SplineVizTestStatus status;
  vtkSmartPointer<vtkMultiBlockDataSet> geometry = Read(true);
  vtkSmartPointer<vtkMultiBlockDataSet> stacked = Read(false);
  SV_CHECK(status, geometry && geometry->GetNumberOfBlocks() == 3);
  SV_CHECK(status, stacked && stacked->GetNumberOfBlocks() == 3);
  if (status.Failures)
  {
    return status.Result();
  }

  int hit = 0, stackedHit = 0;
  const double probe = Probe(geometry, hit);
  const double stackedProbe = Probe(stacked, stackedHit);
  std::cout << "probe: largest error " << probe << ", patches hit " << hit << "; field mode "
            << stackedProbe << std::endl;
  SV_CHECK(status, probe >= 0 && probe < 1e-12 && hit == 7);
  SV_CHECK(status, !(stackedProbe >= 0 && stackedProbe < 1e-12 && stackedHit == 7));

  double offRay, minX, stackedOff, stackedMinX;
  bool crossed, stackedCrossed;
  Trace(geometry, offRay, minX, crossed);
  Trace(stacked, stackedOff, stackedMinX, stackedCrossed);
  std::cout << "trace: off the ray " << offRay << ", smallest x " << minX << ", crossed " << crossed
            << "; field mode: smallest x " << stackedMinX << std::endl;
  SV_CHECK(status, crossed && offRay < 1e-6 && std::abs(minX + 2.0) < 1e-6);
  SV_CHECK(status, !(stackedCrossed && std::abs(stackedMinX + 2.0) < 1e-6));

  const double rms = Render(geometry, "geometry");
  const double stackedRMS = Render(stacked, "field-mode");
  SV_CHECK(status, rms >= 0 && rms <= 3.0);
  SV_CHECK(status, stackedRMS > 3.0);
  return status.Result();
}
