// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkSuperquadricGlyphMapper: the hand-made tensors
// (linear, planar, spherical, cl == cp, repeated eigenvalues, mixed signs with
// absolute values, thin plate, needle, ...) at gamma 0, 3 and 20 colored by
// the principal eigenvector (RGB x FA), and at gamma 3 in parallel
// projection colored by a scalar array through a lookup table.
#include "vtkSuperquadricGlyphMapper.h"

#include "SuperquadricGlyphTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

int TestSuperquadricGlyphMapper(int argc, char* argv[])
{
  std::vector<std::array<double, 6>> tensors;
  for (const auto& h : sqtest::HandTensors())
  {
    tensors.push_back(sqtest::Compose(h));
  }
  auto image = sqtest::TensorImage(tensors, 4);
  vtkNew<vtkDoubleArray> index;
  index->SetName("Index");
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    index->InsertNextValue(static_cast<double>(i));
  }
  image->GetPointData()->AddArray(index);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(640, 480);
  window->SetMultiSamples(0);
  const double viewports[4][4] = { { 0.0, 0.5, 0.5, 1.0 }, { 0.5, 0.5, 1.0, 1.0 },
    { 0.0, 0.0, 0.5, 0.5 }, { 0.5, 0.0, 1.0, 0.5 } };
  const double gammas[4] = { 0.0, 3.0, 20.0, 3.0 };
  for (int v = 0; v < 4; ++v)
  {
    vtkNew<vtkSuperquadricGlyphMapper> mapper;
    mapper->SetInputData(image);
    mapper->SetGamma(gammas[v]);
    mapper->SetScaleFactor(0.42);
    mapper->SetNegativeEigenvaluePolicy(vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.4);
    actor->GetProperty()->SetSpecularPower(30);
    actor->GetProperty()->SetAmbient(0.15);
    if (v == 3)
    {
      vtkNew<vtkLookupTable> lut;
      lut->SetHueRange(0.66, 0.0);
      lut->Build();
      mapper->SetGlyphColorMode(vtkSuperquadricGlyphMapper::COLOR_BY_SCALARS);
      mapper->SetScalarModeToUsePointFieldData();
      mapper->SelectColorArray("Index");
      mapper->SetScalarRange(0, 11);
      mapper->SetLookupTable(lut);
    }
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(viewports[v]);
    renderer->SetBackground(0.32, 0.34, 0.43);
    renderer->AddActor(actor);
    window->AddRenderer(renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(1.5, 1.0, 0.0);
    camera->SetPosition(3.2, -2.6, 4.4);
    camera->SetViewUp(0, 0, 1);
    if (v == 3)
    {
      camera->SetParallelProjection(1);
    }
    renderer->ResetCamera();
    camera->Zoom(1.6);
  }

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? 1 : 0;
}
