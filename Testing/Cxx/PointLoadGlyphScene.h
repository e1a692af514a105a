// SPDX-License-Identifier: BSD-3-Clause
// The scene of the vtkPointLoad glyph image tests: the Boussinesq stress
// field (7^3 samples, effective stress as scalars), a 640x320 window, a
// lookup table and the color range up to the effective stress's 90th
// percentile (the load point is singular) (PointLoadScene); per view the
// glyphs (specular), the load's outline and the camera, in the left (v = 0)
// or right (v = 1) half of the window (AddPointLoadView); the regression
// comparison (ComparePointLoadImage).
#ifndef PointLoadGlyphScene_h
#define PointLoadGlyphScene_h

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkOutlineFilter.h"
#include "vtkPointData.h"
#include "vtkPointLoad.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <vector>

namespace sqtest
{
struct PointLoadScene
{
  vtkNew<vtkPointLoad> Load;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkLookupTable> Lut;
  double Range[2] = { 0.0, 1.0 };
  vtkImageData* Stress = nullptr;

  PointLoadScene()
  {
    this->Load->SetLoadValue(100.0);
    this->Load->SetSampleDimensions(7, 7, 7);
    this->Load->ComputeEffectiveStressOn();
    this->Load->SetModelBounds(-10, 10, -10, 10, -10, 10);
    this->Load->Update();
    this->Stress = this->Load->GetOutput();
    this->Window->SetSize(640, 320);
    this->Window->SetMultiSamples(0);
    this->Lut->SetHueRange(0.66, 0.0);
    this->Lut->Build();
    std::vector<double> values;
    vtkDataArray* effective = this->Stress->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < effective->GetNumberOfTuples(); ++i)
    {
      values.push_back(effective->GetTuple1(i));
    }
    std::sort(values.begin(), values.end());
    this->Range[0] = values.front();
    this->Range[1] = values[values.size() * 9 / 10];
  }
};

inline void AddPointLoadView(vtkRenderWindow* window, vtkAlgorithm* load, vtkMapper* mapper, int v)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(20);

  vtkNew<vtkOutlineFilter> outline;
  outline->SetInputConnection(load->GetOutputPort());
  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputConnection(outline->GetOutputPort());
  vtkNew<vtkActor> outlineActor;
  outlineActor->SetMapper(outlineMapper);
  outlineActor->GetProperty()->SetColor(0.9, 0.9, 0.9);

  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(0.5 * v, 0.0, 0.5 * v + 0.5, 1.0);
  renderer->SetBackground(0.1, 0.1, 0.12);
  renderer->AddActor(actor);
  renderer->AddActor(outlineActor);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(24, -38, 30);
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  camera->Zoom(1.3);
}

/// vtkRegressionTestImageThreshold on the scene's window (0.05); true when
/// the image test passed (or ran interactively).
inline bool ComparePointLoadImage(int argc, char* argv[], vtkRenderWindow* window)
{
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result != vtkRegressionTester::FAILED;
}
}

#endif
