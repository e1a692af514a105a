// The scene of the vtkPointLoad glyph image tests: the glyphs (specular),
// the load's outline and the camera, in the left (v = 0) or right (v = 1)
// half of the window.
#ifndef PointLoadGlyphScene_h
#define PointLoadGlyphScene_h

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkOutlineFilter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

namespace sqtest
{
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
}

#endif
