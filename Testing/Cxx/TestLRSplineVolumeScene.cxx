// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineVolumeMapper in a scene, against the CPU reference of
// LRSplineVolumeTestUtilities.h (RMS <= 2/255 each), then an image
// regression test of the three together:
//  - opaque geometry inside the volume (a sphere and a tube): the reference
//    ends its rays at the depth of the geometry rendered alone and composites
//    over its picture;
//  - a clipping plane (vtkAbstractMapper::AddClippingPlane): the reference
//    clips its rays analytically;
//  - trimming by a closed surface (a tessellated sphere on input port 1): the
//    reference trims its rays by the exact sphere; no pixel whose ray misses
//    the sphere may be drawn (negative control: without the trimming
//    surface that check finds many).
// The volume is the real three-patch file (field magnitude), shaded.
#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkLRSplineVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLineSource.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <iostream>

namespace
{
const double Background[3] = { 0.12, 0.12, 0.15 };
const double TrimCenter[3] = { 0.5, 0.5, 0.5 };
const double TrimRadius = 0.42;

vtkSmartPointer<vtkVolumeProperty> MakeProperty()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 0.1, 0.3, 0.95);
  ctf->AddRGBPoint(0.8, 0.2, 0.85, 0.7);
  ctf->AddRGBPoint(1.3, 1.0, 0.85, 0.2);
  ctf->AddRGBPoint(1.75, 0.95, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 0.0);
  otf->AddPoint(0.7, 0.05);
  otf->AddPoint(1.3, 0.5);
  otf->AddPoint(1.75, 0.8);
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  property->SetScalarOpacityUnitDistance(0.2);
  property->ShadeOn();
  property->SetAmbient(0.3);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.2);
  property->SetSpecularPower(15);
  return property;
}

// Opaque geometry inside the volume: a sphere and a tube.
void AddGeometry(vtkRenderer* ren)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.45, 0.5, 0.55);
  sphere->SetRadius(0.18);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  ren->AddActor(sphereActor);
  vtkNew<vtkLineSource> line;
  line->SetPoint1(0.05, 0.2, 0.8);
  line->SetPoint2(0.95, 0.85, 0.3);
  vtkNew<vtkTubeFilter> tube;
  tube->SetInputConnection(line->GetOutputPort());
  tube->SetRadius(0.03);
  tube->SetNumberOfSides(24);
  vtkNew<vtkPolyDataMapper> tubeMapper;
  tubeMapper->SetInputConnection(tube->GetOutputPort());
  vtkNew<vtkActor> tubeActor;
  tubeActor->SetMapper(tubeMapper);
  tubeActor->GetProperty()->SetColor(0.95, 0.5, 0.2);
  ren->AddActor(tubeActor);
}

void SetCamera(vtkRenderer* ren)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0.5, 0.5, 0.5);
  cam->SetPosition(0.5 - 2.2, 0.5 + 1.4, 0.5 - 2.6);
  cam->SetViewUp(0, 1, 0);
  ren->ResetCameraClippingRange(-0.1, 1.1, -0.1, 1.1, -0.1, 1.1);
}

struct Window
{
  vtkNew<vtkRenderWindow> Win;
  vtkNew<vtkRenderer> Ren;
  Window(int w, int h)
  {
    this->Win->SetMultiSamples(0);
    this->Win->SetSize(w, h);
    this->Win->AddRenderer(this->Ren);
    this->Ren->SetBackground(Background[0], Background[1], Background[2]);
    SetCamera(this->Ren);
  }
};

// Window depths where the ray of each pixel enters / leaves the exact
// trimming sphere (1 / 0 where it misses).
void SphereDepths(const lrvolume::View& view, std::vector<float>& front, std::vector<float>& back)
{
  const std::size_t n = static_cast<std::size_t>(view.Width) * view.Height;
  front.assign(n, 1.0f);
  back.assign(n, 0.0f);
  for (int j = 0; j < view.Height; ++j)
  {
    for (int i = 0; i < view.Width; ++i)
    {
      double o[3], d[3];
      view.Ray(i, j, o, d);
      double oc[3] = { o[0] - TrimCenter[0], o[1] - TrimCenter[1], o[2] - TrimCenter[2] };
      const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
      const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - TrimRadius * TrimRadius;
      const double disc = b * b - c;
      if (disc <= 0)
      {
        continue;
      }
      for (int k = 0; k < 2; ++k)
      {
        const double t = -b + (k == 0 ? -1.0 : 1.0) * std::sqrt(disc);
        const double x[4] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2], 1.0 };
        double clip[4];
        view.DataToClip->MultiplyPoint(x, clip);
        const float z = static_cast<float>(0.5 * (clip[2] / clip[3] + 1.0));
        (k == 0 ? front : back)[static_cast<std::size_t>(j) * view.Width + i] = z;
      }
    }
  }
}

// The reference over a per-pixel background picture (8-bit RGB).
std::vector<double> Over(const lrvolume::Image& image, const std::vector<double>& under)
{
  std::vector<double> rgb(under.size());
  for (std::size_t p = 0; p < under.size() / 3; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v =
        image.RGBA[4 * p + c] + (1.0 - image.RGBA[4 * p + 3]) * under[3 * p + c] / 255.0;
      rgb[3 * p + c] = std::round(255.0 * std::min(1.0, std::max(0.0, v)));
    }
  }
  return rgb;
}
}

int TestLRSplineVolumeScene(int argc, char* argv[])
{
  SplineVizTestStatus status;
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr");
  reader->Update();
  vtkLRSplineField field;
  std::string error;
  SV_CHECK(status,
    field.Build(
      reader->GetOutput(), nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
  lrvolume::Settings base;
  base.Shade = true;
  base.Step = lrvolume::MinimumElementSide(field) / (1 << field.GetMaximumDegree()) / 10.0;
  vtkSmartPointer<vtkVolumeProperty> property = MakeProperty();
  const int w = 120, h = 90;
  const std::string out = std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeScene-";

  // 1. Opaque geometry inside the volume.
  {
    Window geometry(w, h);
    AddGeometry(geometry.Ren);
    geometry.Win->Render();
    const std::vector<float> depth = lrvolume::ReadDepth(geometry.Win);
    const std::vector<double> under = lrvolume::ReadRGB(geometry.Win);

    Window scene(w, h);
    AddGeometry(scene.Ren);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    mapper->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    scene.Ren->AddVolume(volume);
    scene.Win->Render();
    const std::vector<double> gpu = lrvolume::ReadRGB(scene.Win);
    lrvolume::View view;
    view.Set(scene.Ren, volume);
    lrvolume::Settings s = base;
    s.EndDepth = &depth;
    const std::vector<double> cpu = Over(lrvolume::Render(field, volume, view, s), under);
    // Without the depth: the volume drawn over the geometry.
    lrvolume::Settings noDepth = base;
    const std::vector<double> wrong = Over(lrvolume::Render(field, volume, view, noDepth), under);
    const double rms = lrvolume::RMS(gpu, cpu), wrongRMS = lrvolume::RMS(gpu, wrong);
    lrvolume::WritePNG(gpu, w, h, out + "opaque.png");
    lrvolume::WritePNG(cpu, w, h, out + "opaque-cpu.png");
    std::cout << "opaque geometry inside: RMS " << rms
              << " / 255 (ignoring the geometry's depth: " << wrongRMS << ")" << std::endl;
    SV_CHECK(status, rms <= 2.0);
    SV_CHECK_MSG(status, wrongRMS > 2.0, "negative control: the depth makes no difference");
  }

  // 2. A clipping plane.
  const double planeOrigin[3] = { 0.55, 0.5, 0.5 };
  const double planeNormal[3] = { -0.8, 0.2, -0.55 };
  {
    Window scene(w, h);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    mapper->SetInputConnection(reader->GetOutputPort());
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(planeOrigin[0], planeOrigin[1], planeOrigin[2]);
    plane->SetNormal(planeNormal[0], planeNormal[1], planeNormal[2]);
    mapper->AddClippingPlane(plane);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    scene.Ren->AddVolume(volume);
    scene.Win->Render();
    const std::vector<double> gpu = lrvolume::ReadRGB(scene.Win);
    lrvolume::View view;
    view.Set(scene.Ren, volume);
    lrvolume::Settings s = base;
    const double* n = plane->GetNormal();
    s.ClipPlanes.push_back({ n[0], n[1], n[2],
      -(n[0] * planeOrigin[0] + n[1] * planeOrigin[1] + n[2] * planeOrigin[2]) });
    const std::vector<double> cpu =
      lrvolume::OverBackground(lrvolume::Render(field, volume, view, s), Background);
    const std::vector<double> unclipped =
      lrvolume::OverBackground(lrvolume::Render(field, volume, view, base), Background);
    const double rms = lrvolume::RMS(gpu, cpu), wrongRMS = lrvolume::RMS(gpu, unclipped);
    lrvolume::WritePNG(gpu, w, h, out + "clip.png");
    std::cout << "clipping plane: RMS " << rms << " / 255 (against the unclipped reference "
              << wrongRMS << ")" << std::endl;
    SV_CHECK(status, rms <= 2.0);
    SV_CHECK_MSG(status, wrongRMS > 2.0, "negative control: the plane makes no difference");
  }

  // 3. Trimming by a closed surface.
  {
    vtkNew<vtkSphereSource> trim;
    trim->SetCenter(TrimCenter[0], TrimCenter[1], TrimCenter[2]);
    trim->SetRadius(TrimRadius);
    trim->SetThetaResolution(128);
    trim->SetPhiResolution(128);
    for (int withSurface = 1; withSurface >= 0; --withSurface)
    {
      Window scene(w, h);
      vtkNew<vtkLRSplineVolumeMapper> mapper;
      mapper->SetInputConnection(reader->GetOutputPort());
      if (withSurface)
      {
        mapper->SetTrimmingSurfaceConnection(trim->GetOutputPort());
      }
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(property);
      scene.Ren->AddVolume(volume);
      scene.Win->Render();
      const std::vector<double> gpu = lrvolume::ReadRGB(scene.Win);
      lrvolume::View view;
      view.Set(scene.Ren, volume);
      std::vector<float> front, back;
      SphereDepths(view, front, back);
      // Pixels whose rays miss a slightly larger sphere must be background.
      long long outside = 0, outsidePixels = 0;
      for (int j = 0; j < h; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          double o[3], d[3];
          view.Ray(i, j, o, d);
          double oc[3] = { o[0] - TrimCenter[0], o[1] - TrimCenter[1], o[2] - TrimCenter[2] };
          const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
          const double r = 1.01 * TrimRadius;
          const double c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r;
          if (b * b - c > 0)
          {
            continue;
          }
          ++outsidePixels;
          const std::size_t p = 3 * (static_cast<std::size_t>(j) * w + i);
          for (int k = 0; k < 3; ++k)
          {
            if (std::abs(gpu[p + k] - std::round(255.0 * Background[k])) > 0.5)
            {
              ++outside;
              break;
            }
          }
        }
      }
      if (withSurface)
      {
        lrvolume::Settings s = base;
        s.TrimFront = &front;
        s.TrimBack = &back;
        const std::vector<double> cpu =
          lrvolume::OverBackground(lrvolume::Render(field, volume, view, s), Background);
        const double rms = lrvolume::RMS(gpu, cpu);
        lrvolume::WritePNG(gpu, w, h, out + "trim.png");
        lrvolume::WritePNG(cpu, w, h, out + "trim-cpu.png");
        std::cout << "trimming sphere: RMS " << rms << " / 255 against the exact sphere; "
                  << outside << " of " << outsidePixels << " pixels outside the sphere drawn"
                  << std::endl;
        SV_CHECK(status, rms <= 2.0);
        SV_CHECK(status, outsidePixels > w * h / 4);
        SV_CHECK(status, outside == 0);
      }
      else
      {
        std::cout << "without the trimming surface: " << outside << " of " << outsidePixels
                  << " pixels outside the sphere drawn" << std::endl;
        SV_CHECK_MSG(status, outside > outsidePixels / 10,
          "negative control: the outside check finds nothing without trimming");
      }
    }
  }

  // The regression image: the three in one window.
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(360, 150);
  vtkNew<vtkSphereSource> trim;
  trim->SetCenter(TrimCenter[0], TrimCenter[1], TrimCenter[2]);
  trim->SetRadius(TrimRadius);
  trim->SetThetaResolution(128);
  trim->SetPhiResolution(128);
  std::vector<vtkSmartPointer<vtkLRSplineVolumeMapper>> mappers;
  for (int v = 0; v < 3; ++v)
  {
    vtkNew<vtkRenderer> ren;
    ren->SetViewport(v / 3.0, 0.0, (v + 1) / 3.0, 1.0);
    ren->SetBackground(Background[0], Background[1], Background[2]);
    auto mapper = vtkSmartPointer<vtkLRSplineVolumeMapper>::New();
    mapper->SetInputConnection(reader->GetOutputPort());
    if (v == 0)
    {
      AddGeometry(ren);
    }
    else if (v == 1)
    {
      vtkNew<vtkPlane> plane;
      plane->SetOrigin(planeOrigin[0], planeOrigin[1], planeOrigin[2]);
      plane->SetNormal(planeNormal[0], planeNormal[1], planeNormal[2]);
      mapper->AddClippingPlane(plane);
    }
    else
    {
      mapper->SetTrimmingSurfaceConnection(trim->GetOutputPort());
    }
    mappers.push_back(mapper);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    ren->AddVolume(volume);
    win->AddRenderer(ren);
    SetCamera(ren);
  }
  vtkNew<vtkRenderWindowInteractor> iren;
  iren->SetRenderWindow(win);
  win->Render();
  const int result = vtkRegressionTestImageThreshold(win, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    iren->Start();
  }
  return (result == vtkRegressionTester::FAILED || status.Result() != 0) ? 1 : 0;
}
